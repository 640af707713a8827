import { COMMANDS } from '../worker/protocol.js';
import { crossLines, singularityMarkers } from '../viewer/field-layers.js';
import { valenceColor } from '../viewer/palette.js';
import { fillFigures } from './info-panel.js';
import { fieldFigures, valenceCounts } from './field-figures.js';
import { FIELD_DEFAULTS, FIELD_PARSERS, readFieldOptions, sameField } from './field-options.js';

/**
 * The Field view of the Quad layout mode: the options, the cross field of the mesh on screen
 * (crosses, singularities by valence) and its seamless parameterization (a texture), with figures.
 * root: the view's section; viewer; status (Status); request(label, command, payload) runs a worker
 * job (resolves undefined when it failed or was cancelled); onStateChange(partial state);
 * onFieldChange() when the field or the parameterization on screen is replaced or cleared.
 */
export class FieldView {
  constructor({ root, viewer, status, request, onStateChange, onFieldChange = () => {} }) {
    Object.assign(this, { viewer, status, request, onStateChange, onFieldChange });
    this.part = (role) => root.querySelector(`[data-role=${role}]`);
    this.form = this.part('field-form');
    this.input = (name) => root.querySelector(`[name=${name}]`);
    this.mesh = null; // where the mesh on screen came from: { id, sample } or { id, file }
    this.shown = null; // { options, field, param }: what the view shows of that mesh
    this.fillForm(FIELD_DEFAULTS);

    this.form.addEventListener('submit', (event) => {
      event.preventDefault();
      this.computeFromForm();
    });
    this.input('sharp').addEventListener('input', () => this.showSharp());
    this.input('crosses').addEventListener('change', () => this.showCrosses());
    this.input('texture').addEventListener('change', () => {
      this.viewer.setTexture(this.input('texture').value);
      this.onStateChange({ texture: this.input('texture').value });
    });
  }

  /** A new mesh on screen (its source as the worker can build it again): nothing computed yet. */
  setMesh(source) {
    this.mesh = source;
    this.clear();
  }

  /** Brings the options, the texture and the field to a link's state. */
  async applyState(state) {
    this.fillForm(state);
    this.input('texture').value = state.texture;
    this.viewer.setTexture(state.texture);
    if (!state.field) return this.clear();
    const options = { align: state.align, sharp: state.sharp, h: state.h };
    if (this.shown?.param && sameField(this.shown.options, options) && this.shown.options.h === options.h) return;
    await this.compute(options);
  }

  async computeFromForm() {
    const options = this.readForm();
    if (options) await this.compute(options);
  }

  /**
   * The form's options with the field and parameterization of the mesh computed for them (now, or
   * already on screen); null when the form is invalid or a job failed.
   */
  async computedOptions() {
    const options = this.readForm();
    if (!options) return null;
    const shown = this.shown;
    const current = shown?.param && sameField(shown.options, options) && shown.options.h === options.h;
    if (!current) await this.compute(options);
    return this.shown?.param ? options : null;
  }

  // The form's options, or null with the problems shown.
  readForm() {
    const texts = Object.fromEntries(Object.keys(FIELD_PARSERS).map((key) => [key, this.input(key).value]));
    const { options, problems } = readFieldOptions(texts);
    for (const key of Object.keys(FIELD_PARSERS)) this.input(key).setAttribute('aria-invalid', String(key in problems));
    if (Object.keys(problems).length === 0) return options;
    this.status.showMessage('error', 'The field options cannot be used', Object.values(problems).join(' '));
    return null;
  }

  /**
   * Computes and shows the field (unless the one on screen has these options: h only scales the
   * parameterization), then the parameterization. A failure keeps what the view showed before.
   */
  async compute(options) {
    const mesh = this.mesh;
    if (!mesh) return;
    this.onFieldChange();
    const field = { align: options.align, sharp: options.sharp };
    if (!this.shown || !sameField(this.shown.options, options)) {
      const result = await this.request('Designing the cross field', COMMANDS.crossField, { mesh, field });
      if (!result || this.mesh !== mesh) return;
      this.showField(result);
    }
    this.shown.options = options;
    this.showParam(null);
    this.onStateChange({ field: true, ...options });
    const label = 'Computing the seamless parameterization';
    const param = await this.request(label, COMMANDS.seamlessParam, { mesh, field, h: options.h });
    if (param && this.mesh === mesh) this.showParam(param);
  }

  showField(field) {
    this.shown = { options: null, field, param: null };
    this.viewer.setLayer('crosses', crossLines(field.glyphs));
    this.showCrosses();
    const { positions, valences } = field.singularities;
    this.viewer.setLayer('singularities', valences.length > 0 ? singularityMarkers(positions, valences, field.markerRadius) : null);
    this.fillLegend(valences);
    this.part('field-result').hidden = false;
    this.part('field-result').scrollIntoView({ block: 'nearest' });
  }

  /** The parameterization (its texture and figures), or null before there is one. */
  showParam(param) {
    this.shown.param = param;
    this.viewer.setUvSurface(param?.corners ?? null);
    this.input('texture').disabled = !param;
    const { figures, values } = fieldFigures(this.shown.field, param);
    fillFigures(this.part('field-figures'), figures, values);
  }

  clear() {
    this.shown = null;
    this.onFieldChange();
    for (const layer of ['crosses', 'singularities']) this.viewer.setLayer(layer, null);
    this.viewer.setUvSurface(null);
    this.part('field-result').hidden = true;
  }

  fillForm({ align, sharp, h }) {
    this.input('align').value = align;
    this.input('sharp').value = String(sharp);
    this.input('h').value = String(h);
    for (const key of Object.keys(FIELD_PARSERS)) this.input(key).removeAttribute('aria-invalid');
    this.showSharp();
  }

  showSharp() {
    const degrees = Number(this.input('sharp').value);
    this.input('sharp-value').textContent = degrees >= 180 ? 'none' : `${degrees}°`;
  }

  /** Unticks 'Show the crosses' (a layout on screen draws its own lines). */
  hideCrosses() {
    this.input('crosses').checked = false;
    this.showCrosses();
  }

  showCrosses() {
    this.viewer.setLayerVisible('crosses', this.input('crosses').checked);
  }

  fillLegend(valences) {
    const counts = valenceCounts(valences);
    const items = counts.map(([valence, n]) => {
      const item = document.createElement('li');
      item.dataset.valence = String(valence);
      const swatch = document.createElement('span');
      swatch.className = 'swatch';
      swatch.style.background = valenceColor(valence);
      item.append(swatch, `valence ${valence}: ${n}`);
      return item;
    });
    if (items.length === 0) {
      const none = document.createElement('li');
      none.textContent = 'No singularities';
      items.push(none);
    }
    this.part('legend').replaceChildren(...items);
  }
}
