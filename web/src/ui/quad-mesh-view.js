import { COMMANDS } from '../worker/protocol.js';
import { patchMesh } from '../viewer/layout-layers.js';
import { segmentLines } from '../viewer/geometry.js';
import { downloadBytes, downloadName } from './download.js';
import { fillFigures } from './info-panel.js';
import { DEFAULT_QUADS, quadCountAt, quadMeshFigures, quadMeshVerdict, sliderPositionOf } from './quad-mesh-figures.js';

const EDGE_COLOR = '#111318';
const LAYERS = ['quad-mesh', 'quad-edges'];
const LAYOUT_LAYERS = ['patches', 'arcs']; // drawn in place of the quad mesh when it is hidden

/**
 * The Quad mesh view of the Quad layout mode (thesis Ch. 8): the quad mesh of the valid layout on
 * screen for a target quad count, coloured by the layout's patches, with its edges (on by default),
 * figures and exports. The count slider remeshes in the worker, which keeps what the count does not
 * change. root: the view's section; viewer; request(label, command, payload) runs a worker job
 * (resolves undefined when it failed or was cancelled).
 */
export class QuadMeshView {
  constructor({ root, viewer, request }) {
    Object.assign(this, { root, viewer, request });
    this.part = (role) => root.querySelector(`[data-role=${role}]`);
    this.slider = this.part('quad-count');
    this.layout = null; // the layout payload { mesh, field, h, alpha } the view remeshes
    this.shown = null; // { payload, result }: the quad mesh on screen
    this.wantedQuads = null; // the slider's count while remeshes run one after another
    this.remeshing = false;
    this.slider.value = String(sliderPositionOf(DEFAULT_QUADS));
    this.showCount();

    this.part('quad-mesh-run').addEventListener('click', () => this.remesh());
    this.slider.addEventListener('input', () => this.showCount());
    this.slider.addEventListener('change', () => {
      if (this.shown) this.remesh();
    });
    this.part('quad-wireframe').addEventListener('change', () => this.showLayers());
    this.part('quad-mesh-shown').addEventListener('change', () => this.showLayers());
    this.part('quad-obj').addEventListener('click', () => this.download('obj'));
    this.part('quad-glb').addEventListener('click', () => this.download('glb'));
  }

  /** The layout on screen changed: payload of a valid one, or null (none, or one not valid). */
  setLayout(payload) {
    this.clear();
    this.layout = payload;
    this.root.hidden = payload === null;
  }

  target() {
    return quadCountAt(this.slider.value);
  }

  /**
   * The quad mesh at the slider's count. Counts chosen while a remesh runs wait for it, the last
   * one wins: starting a job cancels the running one, and a cancel restarts the worker, which
   * would lose what it keeps of the layout.
   */
  async remesh() {
    if (!this.layout) return;
    this.wantedQuads = this.target();
    if (this.remeshing) return;
    this.remeshing = true;
    let tried = null;
    try {
      while (this.layout && this.wantedQuads !== tried && this.wantedQuads !== this.shown?.payload.quads) {
        tried = this.wantedQuads;
        const payload = { ...this.layout, quads: tried };
        const result = await this.request(`Quad mesh of about ${tried} quads`, COMMANDS.quadMesh, payload);
        if (result && this.layout && this.layout.mesh === payload.mesh && this.layout.alpha === payload.alpha) this.show(payload, result);
      }
    } finally {
      this.remeshing = false;
    }
  }

  show(payload, result) {
    this.dropLayers();
    this.shown = { payload, result };
    this.viewer.setLayer('quad-mesh', patchMesh(result.surface));
    this.viewer.setLayer('quad-edges', segmentLines(result.edges, EDGE_COLOR));
    this.showLayers();
    this.part('quad-mesh-verdict').textContent = quadMeshVerdict(result.info);
    const { figures, values } = quadMeshFigures({ ...result, target: payload.quads });
    fillFigures(this.part('quad-mesh-figures'), figures, values);
    this.part('quad-mesh-result').hidden = false;
  }

  // The quad mesh drawn in place of the layout's patches and arcs, or the layout again.
  showLayers() {
    const quads = this.shown !== null && this.part('quad-mesh-shown').checked;
    this.viewer.setLayerVisible('quad-mesh', quads);
    this.viewer.setLayerVisible('quad-edges', quads && this.part('quad-wireframe').checked);
    for (const layer of LAYOUT_LAYERS) this.viewer.setLayerVisible(layer, !quads);
  }

  async download(format) {
    if (!this.shown) return;
    const { payload } = this.shown;
    const label = `Writing the quad mesh as ${format.toUpperCase()}`;
    const reply = await this.request(label, COMMANDS.quadMeshExport, { ...payload, format });
    if (!reply) return;
    const source = payload.mesh.sample ?? payload.mesh.file?.name.replace(/\.[^.]*$/, '') ?? 'mesh';
    const type = format === 'obj' ? 'model/obj' : 'model/gltf-binary';
    downloadBytes(reply.bytes, downloadName(`${source}-quads`, format), type);
  }

  dropLayers() {
    for (const layer of LAYERS) this.viewer.setLayer(layer, null);
  }

  clear() {
    this.shown = null;
    this.dropLayers();
    this.showLayers();
    this.part('quad-mesh-result').hidden = true;
  }

  showCount() {
    this.part('quad-count-value').textContent = String(this.target());
  }
}
