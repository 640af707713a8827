import { COMMANDS } from '../worker/protocol.js';
import { downloadBytes, downloadName } from './download.js';
import { fillFigures } from './info-panel.js';
import { SURFACE_FIGURES, surfaceFigureValues } from './surface-figures.js';
import { SURFACE_DEFAULTS, SURFACE_PARSERS, coreOptions, readSurfaceOptions } from './surface-options.js';

/**
 * The 3D view of the Regular maps mode: the regular surface of the map on screen (its edges as
 * tubes, coloured by quarter tube) in the viewer's 'surface' scene, its options, figures and GLB.
 * While the view is open it shows the surface of the map on screen with the options chosen,
 * building it when there is none, unless that build failed or was cancelled: then only the
 * Build button or another map starts it again.
 * root: the view's section of the panel; note: the element over the viewport shown while there is
 * no surface; viewer; status (Status); request(label, command, payload) runs a worker job
 * (resolves undefined when it failed or was cancelled); onStateChange(partial state).
 */
export class SurfaceView {
  constructor({ root, note, viewer, status, request, onStateChange }) {
    Object.assign(this, { root, note, viewer, status, request, onStateChange });
    this.part = (role) => root.querySelector(`[data-role=${role}]`);
    this.input = (name) => root.querySelector(`[name=${name}]`);
    this.map = null; // { spec, name }: spec as the core takes it (a catalog name or a presentation)
    this.options = { ...SURFACE_DEFAULTS };
    this.active = false;
    this.shown = null; // { key, payload, name } of the surface on screen
    this.building = null; // the key of the surface being built
    this.stopped = null; // the key of the last build that failed or was cancelled
    this.setOptions(SURFACE_DEFAULTS);

    this.part('surface-form').addEventListener('submit', (event) => {
      event.preventDefault();
      this.buildFromForm();
    });
    this.input('smoothness').addEventListener('input', () => this.showSmoothness());
    this.part('export-surface-glb').addEventListener('click', () => this.exportGlb());
  }

  /** A new map on screen ({ spec, name }): the surface of the previous one goes. */
  setMap(map) {
    this.map = map;
    this.stopped = null;
    this.clear();
    return this.update();
  }

  /** Opens (true) or closes the view; the surface stays for when it opens again. */
  setActive(active) {
    this.active = active;
    this.root.hidden = !active;
    if (active && this.shown) {
      this.viewer.showColoredSurface(this.shown.surface);
      this.viewer.showSurfaceLines(null);
    }
    this.showNote();
  }

  /** The options a link names ({ base, radius, smoothness }), into the form. */
  setOptions({ base, radius, smoothness }) {
    this.options = { base, radius, smoothness };
    this.input('base').value = base;
    this.input('radius').value = String(radius);
    this.input('smoothness').value = String(smoothness);
    for (const key of Object.keys(SURFACE_PARSERS)) this.input(key).removeAttribute('aria-invalid');
    this.showSmoothness();
  }

  /**
   * While the view is open: builds the surface of the map and options unless it shows, is under
   * way or was stopped.
   */
  async update() {
    if (!this.active || !this.map) return;
    const key = surfaceKey(this.map, this.options);
    if (![this.shown?.key, this.building, this.stopped].includes(key)) await this.build();
  }

  async buildFromForm() {
    const texts = Object.fromEntries(Object.keys(SURFACE_PARSERS).map((key) => [key, this.input(key).value]));
    const { options, problems } = readSurfaceOptions(texts);
    for (const key of Object.keys(SURFACE_PARSERS)) this.input(key).setAttribute('aria-invalid', String(key in problems));
    if (Object.keys(problems).length > 0) {
      this.status.showMessage('error', 'The surface options cannot be used', Object.values(problems).join(' '));
      return;
    }
    this.options = options;
    await this.build();
  }

  /** Builds and shows the surface of the map with the current options; a failure keeps what shows. */
  async build() {
    const { map, options } = this;
    if (!map) return;
    const key = surfaceKey(map, options);
    const payload = { map: map.spec, options: coreOptions(options) };
    this.building = key;
    const result = await this.request(`Building the regular surface of ${map.name}`, COMMANDS.regmapSurface, payload);
    if (this.building === key) this.building = null;
    if (this.map !== map) return;
    if (!result) {
      this.stopped = key;
      return this.showNote();
    }
    this.shown = { key, payload, name: map.name, surface: result.surface };
    this.viewer.showColoredSurface(result.surface);
    this.viewer.showSurfaceLines(null);
    fillFigures(this.part('surface-figures'), SURFACE_FIGURES, surfaceFigureValues(result.stats));
    this.part('surface-result').hidden = false;
    this.part('surface-result').scrollIntoView({ block: 'nearest' });
    this.showNote();
    this.onStateChange(options);
  }

  async exportGlb() {
    if (!this.shown) return;
    const { payload, name } = this.shown;
    const reply = await this.request('Writing the GLB file', COMMANDS.regmapSurfaceGlb, payload);
    // A map's name is no file name: its dot (R2.4) is not an extension.
    if (reply) downloadBytes(reply.bytes, downloadName(`${name}-surface.glb`, 'glb'), 'model/gltf-binary');
  }

  clear() {
    this.shown = null;
    if (this.active) this.viewer.showColoredSurface(null);
    this.part('surface-result').hidden = true;
    this.showNote();
  }

  showNote() {
    this.note.hidden = !this.active || this.shown !== null || !this.map;
    if (!this.map) return;
    const stopped = this.stopped === surfaceKey(this.map, this.options);
    this.note.textContent = stopped
      ? `The regular surface of ${this.map.name} was not built. "Build the surface" tries again.`
      : `The regular surface of ${this.map.name} shows here once it is built.`;
  }

  showSmoothness() {
    this.input('smoothness-value').textContent = this.input('smoothness').value;
  }
}

const surfaceKey = (map, { base, radius, smoothness }) => JSON.stringify([map.spec, base, radius, smoothness]);
