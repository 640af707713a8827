import { COMMANDS } from '../worker/protocol.js';
import { arcLines, patchMesh } from '../viewer/layout-layers.js';
import { singularityMarkers } from '../viewer/field-layers.js';
import { downloadBytes, downloadName } from './download.js';
import { fillFigures } from './info-panel.js';
import { formatAlpha, layoutFigures, layoutVerdict } from './layout-figures.js';

export const DEFAULT_ALPHA = 5;
const LAYERS = ['patches', 'arcs', 'layout-singularities'];

/**
 * The Layout view of the Quad layout mode: the quad layout of the mesh on screen from the Field
 * view's field and parameterization, its patches, arcs and singularities, the checker's verdict,
 * the figures, an alpha slider that solves P1 again on the graph the worker keeps, and exports.
 * root: the view's section; viewer; field (FieldView); request(label, command, payload) runs a
 * worker job (resolves undefined when it failed or was cancelled); onLayoutChange(layout) when the
 * layout on screen changes: { mesh, field, h, alpha } of a valid one, null for none or an invalid
 * one (the Quad mesh view remeshes the valid ones).
 */
export class LayoutView {
  constructor({ root, viewer, field, request, onLayoutChange = () => {} }) {
    Object.assign(this, { viewer, field, request, onLayoutChange });
    this.part = (role) => root.querySelector(`[data-role=${role}]`);
    this.alpha = this.part('alpha');
    this.mesh = null; // where the mesh on screen came from
    this.shown = null; // { payload, result }: the layout on screen and what it was asked with
    this.wantedAlpha = null; // the slider's alpha while re-solves run one after another
    this.resolving = false;
    this.alpha.value = String(DEFAULT_ALPHA);
    this.showAlpha();

    this.part('layout-run').addEventListener('click', () => this.run());
    this.alpha.addEventListener('input', () => this.showAlpha());
    this.alpha.addEventListener('change', () => this.resolve());
    this.part('layout-glb').addEventListener('click', () => this.download('glb'));
    this.part('layout-ply').addEventListener('click', () => this.download('ply'));
  }

  setMesh(source) {
    this.mesh = source;
    this.clear();
  }

  /** The field or parameterization changed: the layout on screen no longer belongs to it. */
  fieldChanged() {
    this.clear();
  }

  /** Field and parameterization (the Field view's options), the graph of the ports, P1, the layout. */
  async run() {
    const options = await this.field.computedOptions();
    if (!options || !this.mesh) return;
    const { align, sharp, h } = options;
    const alpha = Number(this.alpha.value);
    await this.solve({ mesh: this.mesh, field: { align, sharp }, h, alpha, presolve: sliderPositions(this.alpha) });
  }

  /**
   * A new alpha: P1 again on the kept graph (nothing to do before a layout was run). Alphas chosen
   * while a re-solve runs wait for it, the last one wins: starting a job cancels the running one,
   * and a cancel restarts the worker, which would lose the graph.
   */
  async resolve() {
    if (!this.shown) return;
    this.wantedAlpha = Number(this.alpha.value);
    if (this.resolving) return;
    this.resolving = true;
    let tried = null;
    try {
      while (this.shown && this.wantedAlpha !== this.shown.payload.alpha && this.wantedAlpha !== tried) {
        tried = this.wantedAlpha;
        await this.solve({ ...this.shown.payload, alpha: tried });
      }
    } finally {
      this.resolving = false;
    }
  }

  async solve(payload) {
    const label = `Quad layout at alpha = ${formatAlpha(payload.alpha)}`;
    const result = await this.request(label, COMMANDS.quadLayout, payload);
    if (result && this.mesh === payload.mesh) this.show(payload, result);
  }

  show(payload, result) {
    // A new alpha often gives the layout on screen again: its figures change, its 3D layers are
    // kept rather than built and uploaded again.
    const sameLayers = this.shown !== null && sameLayout(this.shown.result, result);
    this.shown = { payload, result };
    if (!sameLayers) this.showLayers(result);

    const verdict = layoutVerdict(result.info);
    const line = this.part('layout-verdict');
    line.textContent = verdict.text;
    line.dataset.valid = String(verdict.valid);
    const { figures, values } = layoutFigures(result);
    fillFigures(this.part('layout-figures'), figures, values);
    this.part('layout-problems').replaceChildren(
      ...(result.info.problems ?? []).map((text) => {
        const item = document.createElement('li');
        item.textContent = text;
        return item;
      }),
    );
    this.part('layout-result').hidden = false;
    this.part('layout-result').scrollIntoView({ block: 'nearest' });
    const { mesh, field, h, alpha } = payload;
    this.onLayoutChange(result.info.valid ? { mesh, field, h, alpha } : null);
  }

  showLayers(result) {
    this.viewer.setLayer('patches', patchMesh(result.surface));
    this.viewer.setLayer('arcs', arcLines(result.arcs));
    const { positions, valences } = result.singularities;
    const markers = valences.length > 0 ? singularityMarkers(positions, valences, result.markerRadius) : null;
    this.viewer.setLayer('layout-singularities', markers);
    this.viewer.setSurfaceCovered(true);
    this.field.hideCrosses();
  }

  async download(format) {
    if (!this.shown) return;
    const { payload } = this.shown;
    const label = `Writing the layout as ${format.toUpperCase()}`;
    const reply = await this.request(label, COMMANDS.layoutExport, { ...payload, format });
    if (!reply) return;
    const source = payload.mesh.sample ?? payload.mesh.file?.name.replace(/\.[^.]*$/, '') ?? 'mesh';
    const name = `${source}-layout`;
    const type = format === 'ply' ? 'application/octet-stream' : 'model/gltf-binary';
    downloadBytes(reply.bytes, downloadName(name, format), type);
  }

  clear() {
    this.shown = null;
    for (const layer of LAYERS) this.viewer.setLayer(layer, null);
    this.viewer.setSurfaceCovered(false);
    this.part('layout-result').hidden = true;
    this.onLayoutChange(null);
  }

  showAlpha() {
    this.part('alpha-value').textContent = formatAlpha(this.alpha.value);
  }
}

/** Whether two layout results draw the same: the same arcs, patches and singularities. */
export function sameLayout(a, b) {
  const same = (x, y) => x?.length === y?.length && x.every((value, i) => value === y[i]);
  return (
    same(a.arcs, b.arcs) &&
    same(a.surface.positions, b.surface.positions) &&
    same(a.surface.colors, b.surface.colors) &&
    same(a.surface.triangles, b.surface.triangles) &&
    same(a.singularities.positions, b.singularities.positions) &&
    same(a.singularities.valences, b.singularities.valences) &&
    a.markerRadius === b.markerRadius
  );
}

/** The positions of a range input (min to max by step): the alphas the worker presolves when idle. */
export function sliderPositions(input) {
  const min = Number(input.min);
  const max = Number(input.max);
  const step = Number(input.step);
  if (!(step > 0) || !(max >= min)) return [];
  const count = Math.min(Math.floor((max - min) / step + 1e-9), 1000);
  return Array.from({ length: count + 1 }, (_, k) => Number((min + k * step).toPrecision(12)));
}
