import { COMMANDS } from '../worker/protocol.js';
import { MAP_EDGE_COLOR } from '../viewer/palette.js';
import { downloadBytes, downloadName } from './download.js';
import { fillFigures } from './info-panel.js';
import { DRAWN_FIGURES, drawnDescription, drawnFigureValues } from './drawn-figures.js';

// The export formats: their file's MIME type.
const EXPORT_TYPES = Object.freeze({ glb: 'model/gltf-binary', ply: 'application/octet-stream', obj: 'model/obj', stl: 'model/stl' });

/**
 * The "On a surface" view of the Regular maps mode: the map on screen drawn on the regular surface
 * of a target of its genus (the best one, or the one a link or the list of others names), faces in
 * colours (each its own, or by orbit of the surface's rotations: faces that a rotation of the
 * surface carries onto each other share one), edges as dark lines, or the bare surface (coloured
 * by quarter tube), the
 * figures found on the drawing, the other targets and its export (GLB, PLY, OBJ, the fundamental
 * polygon's SVG, and an STL to print at a chosen size, checked). While the view is open it shows the
 * drawing of the map and target on screen, drawing it when there is none, unless that failed or
 * was cancelled.
 * root: the view's section of the panel; note: the element over the viewport shown while nothing
 * is drawn; viewer; status; request(label, command, payload); onStateChange(partial state);
 * exportSvg() downloads the map's fundamental polygon.
 */
export class DrawnView {
  constructor({ root, note, viewer, status, request, onStateChange, exportSvg }) {
    Object.assign(this, { root, note, viewer, status, request, onStateChange });
    this.part = (role) => root.querySelector(`[data-role=${role}]`);
    this.map = null; // { spec, name }
    this.on = null; // the target a link or a choice names; null: the best
    this.active = false;
    this.shown = null; // { key, payload, name, result }
    this.building = null;
    this.stopped = null;
    this.part('drawn-colors').addEventListener('change', () => {
      this.showDrawing();
      this.onStateChange({ colors: this.part('drawn-colors').value });
    });
    for (const button of this.part('drawn-export').querySelectorAll('[data-format]'))
      button.addEventListener('click', () => this.exportAs(button.dataset.format));
    this.part('export-svg').addEventListener('click', exportSvg);
  }

  setMap(map) {
    this.map = map;
    this.stopped = null;
    this.clear();
    return this.update();
  }

  /** The target a link names (null: the best). */
  setTarget(on) {
    this.on = on ?? null;
  }

  /** The colours a link names: 'faces', 'orbits' or 'tubes' (hash.js). */
  setColors(colors) {
    this.part('drawn-colors').value = colors;
    this.showDrawing();
  }

  /** Opens (true) or closes the view; opening it again retries a drawing that failed. */
  setActive(active) {
    if (active && !this.active) this.stopped = null;
    this.active = active;
    this.root.hidden = !active;
    if (active) this.showDrawing();
    this.showNote();
  }

  async update() {
    if (!this.active || !this.map) return;
    const key = drawnKey(this.map, this.on);
    if (![this.shown?.key, this.building, this.stopped].includes(key)) await this.draw();
  }

  async draw() {
    const { map, on } = this;
    if (!map) return;
    const key = drawnKey(map, on);
    const payload = { map: map.spec, on };
    this.building = key;
    const where = on ? ` on the surface of ${on}` : ' on a surface';
    const result = await this.request(`Drawing ${map.name}${where}`, COMMANDS.regmapDrawn, payload);
    if (this.building === key) this.building = null;
    if (this.map !== map || this.on !== on) return;
    if (!result) {
      this.stopped = key;
      return this.showNote();
    }
    this.shown = { key, payload, name: map.name, result };
    // Names the map on screen, for what waits for a drawing (build:gallery, the browser tests).
    this.root.dataset.drawn = map.name;
    this.showDrawing();
    fillFigures(this.part('drawn-figures'), DRAWN_FIGURES, drawnFigureValues(result.drawn));
    this.part('drawn-text').replaceChildren(
      ...drawnDescription(map.name, result.info, result.drawn).map((paragraph) => {
        const element = document.createElement('p');
        element.textContent = paragraph;
        return element;
      }),
    );
    this.showOthers(result.drawn.target, result.others);
    this.part('drawn-result').hidden = false;
    this.showNote();
    this.onStateChange({ on });
  }

  /** The drawing on screen in the viewer's surface scene in the chosen colours. */
  showDrawing() {
    if (!this.active || !this.shown) return;
    const { result } = this.shown;
    const colors = this.part('drawn-colors').value;
    const { surface } = result;
    const shown = { faces: surface, orbits: { ...surface, colors: surface.recolored }, tubes: result.bare }[colors];
    this.viewer.showColoredSurface(shown);
    this.viewer.showSurfaceLines(colors === 'tubes' ? null : result.edges, MAP_EDGE_COLOR);
  }

  // A button per other target; choosing one draws the map there.
  showOthers(target, others) {
    const list = this.part('drawn-others');
    const names = [...new Set([target, ...others])];
    list.replaceChildren(
      ...names.map((name) => {
        const button = document.createElement('button');
        button.type = 'button';
        button.textContent = name;
        button.setAttribute('aria-pressed', String(name === target));
        button.addEventListener('click', () => this.chooseTarget(name));
        return button;
      }),
    );
    this.part('drawn-others-label').hidden = names.length < 2;
    list.hidden = names.length < 2;
  }

  async chooseTarget(name) {
    this.on = name;
    await this.update();
  }

  /** Downloads the drawing as `format` (an EXPORT_TYPES key); an STL with its print check. */
  async exportAs(format) {
    if (!this.shown) return;
    const { payload, name } = this.shown;
    const print = format === 'stl' ? this.printOptions() : null;
    if (format === 'stl' && !print) return;
    const label = format === 'stl' ? 'Writing the STL to print and checking it' : `Writing the ${format.toUpperCase()} file`;
    const reply = await this.request(label, COMMANDS.regmapDrawnExport, { ...payload, format, print });
    if (!reply) return;
    downloadBytes(reply.bytes, downloadName(`${name}-drawn.${format}`, format), EXPORT_TYPES[format]);
    if (reply.print) this.showPrintReport(reply.print);
  }

  /** The print size and wall as typed, in mm, or null (marked and said) where one is no length. */
  printOptions() {
    const read = (role, min, max) => {
      const input = this.part(role);
      const value = Number(input.value);
      const ok = input.value.trim() !== '' && Number.isFinite(value) && value >= min && value <= max;
      input.setAttribute('aria-invalid', String(!ok));
      return ok ? value : null;
    };
    const sizeMm = read('print-size', 1, 10000);
    const wallMm = read('print-wall', 0.1, 100);
    if (sizeMm === null || wallMm === null || wallMm >= sizeMm) {
      this.status.showNotice('The print size or wall cannot be used.', 'The print size is 1 to 10,000 mm, the wall 0.1 to 100 mm and thinner than the print.');
      return null;
    }
    return { sizeMm, wallMm };
  }

  /** The print check of the STL just written, in words (text only). */
  showPrintReport(check) {
    const mm = (x) => `${Number(x).toFixed(1)} mm`;
    const [x, y, z] = check.extent_mm;
    const lines = [
      `Printed ${mm(x)} × ${mm(y)} × ${mm(z)}; thinnest wall ${mm(check.thinnest_mm)} (${mm(check.wall_mm)} asked).`,
      check.printable ? 'Printable: closed, oriented, no self-intersections, no thinner wall.' : 'Not printable as it is:',
      ...check.problems.map((problem) => `${problem[0].toUpperCase()}${problem.slice(1)}.`),
    ];
    const report = this.part('print-report');
    report.replaceChildren(...lines.map((line) => Object.assign(document.createElement('span'), { textContent: line })));
    report.dataset.printable = String(check.printable);
    report.hidden = false;
  }

  clear() {
    this.shown = null;
    delete this.root.dataset.drawn;
    if (this.active) {
      this.viewer.showColoredSurface(null);
      this.viewer.showSurfaceLines(null);
    }
    this.part('drawn-result').hidden = true;
    this.part('print-report').hidden = true;
    this.showNote();
  }

  showNote() {
    if (!this.active) return;
    this.note.hidden = this.shown !== null || !this.map;
    if (!this.map) return;
    const stopped = this.stopped === drawnKey(this.map, this.on);
    this.note.textContent = stopped
      ? `${this.map.name} was not drawn on a surface. Open this view again to retry.`
      : `${this.map.name} shows here once it is drawn on a surface.`;
  }
}

const drawnKey = (map, on) => JSON.stringify([map.spec, on ?? null]);
