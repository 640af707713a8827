// The 2D view of a regular map: the core's SVG of its fundamental polygon, shown as an <img> from a
// Blob URL (an SVG image runs no script and loads nothing), zoomed with the wheel, the keys + and -
// or the buttons, and panned by dragging or with the arrow keys.
import { downloadBytes, downloadName } from './download.js';
import { jobError } from '../worker/protocol.js';

const FIT_MARGIN = 0.96; // share of the smaller side of the view that a fitted image fills
const ZOOM_RANGE = [0.5, 24]; // zoom limits, relative to the fitted size
const BUTTON_ZOOM = 1.5;
const KEY_PAN = 60; // CSS pixels per arrow key

/** The view { scale, x, y } that centres an image of size (imageWidth, imageHeight) in the view. */
export function fitView(viewWidth, viewHeight, imageWidth, imageHeight) {
  const scale = (FIT_MARGIN * Math.min(viewWidth / imageWidth, viewHeight / imageHeight)) || 1;
  return { scale, x: (viewWidth - scale * imageWidth) / 2, y: (viewHeight - scale * imageHeight) / 2 };
}

/**
 * The view zoomed by `factor` about the point (px, py) of the view, which stays where it is; the
 * scale is kept within ZOOM_RANGE times fitScale.
 */
export function zoomAbout(view, factor, px, py, fitScale) {
  const [least, most] = ZOOM_RANGE.map((zoom) => zoom * fitScale);
  const scale = Math.min(most, Math.max(least, view.scale * factor));
  const ratio = scale / view.scale;
  return { scale, x: px - (px - view.x) * ratio, y: py - (py - view.y) * ratio };
}

/** root: the element holding [data-role=stage|image|note|zoom-in|zoom-out|fit|download-svg]. */
export class TilingView {
  constructor(root) {
    this.root = root;
    this.part = (role) => root.querySelector(`[data-role=${role}]`);
    this.stage = this.part('stage');
    this.image = this.part('image');
    this.shown = null; // { svg, name, url, width, height } of the image on screen (url null: not drawn)
    this.view = { scale: 1, x: 0, y: 0 };
    this.fitted = true; // the user has not zoomed or panned since the last fit
    this.request = 0;

    this.part('zoom-in').addEventListener('click', () => this.zoomAtCentre(BUTTON_ZOOM));
    this.part('zoom-out').addEventListener('click', () => this.zoomAtCentre(1 / BUTTON_ZOOM));
    this.part('fit').addEventListener('click', () => this.fit());
    this.part('download-svg').addEventListener('click', () => this.download());
    this.stage.addEventListener('wheel', (event) => this.onWheel(event), { passive: false });
    this.stage.addEventListener('keydown', (event) => this.onKey(event));
    this.stage.addEventListener('pointerdown', (event) => this.startDrag(event));
    new ResizeObserver(() => this.fitted && this.fit()).observe(this.stage);
    this.setDrawn(false);
    this.part('download-svg').disabled = true;
  }

  /**
   * Shows an SVG (text made by the core) named `name` (the map's name, used for the download and the
   * image's description). Resolves once the image is decoded; rejects if it cannot be.
   */
  async show(svg, name) {
    const request = ++this.request;
    const url = URL.createObjectURL(new Blob([svg], { type: 'image/svg+xml' }));
    const image = new Image();
    image.src = url;
    try {
      await image.decode();
    } catch {
      URL.revokeObjectURL(url);
      throw jobError('internal', `The tiling of ${name} could not be drawn: its SVG image did not decode.`);
    }
    if (request !== this.request) {
      URL.revokeObjectURL(url);
      return;
    }
    this.keep({ svg, name, url, width: image.naturalWidth || 1000, height: image.naturalHeight || 1000 });
    // The decoded image itself takes the place of the one on screen: decoding an SVG parses it on
    // the page's thread, once is enough.
    image.dataset.role = 'image';
    image.draggable = false;
    image.alt = `The tiling of the regular map ${name}: its fundamental polygon with the paired boundary edges numbered.`;
    this.image.replaceWith(image);
    this.image = image;
    this.setDrawn(true);
    this.fit();
  }

  /** Keeps an SVG for its download without drawing it, and shows `note` (text) in its place. */
  showUndrawn(svg, name, note) {
    this.request++;
    this.keep({ svg, name, url: null });
    this.part('note').textContent = note;
    this.setDrawn(false);
  }

  /** The URL of the image on screen (valid until the next map), or null when none is drawn. */
  imageUrl() {
    return this.image.hidden ? null : (this.shown?.url ?? null);
  }

  /** Shows or hides the whole view (the image keeps its zoom). */
  setVisible(visible) {
    this.root.hidden = !visible;
  }

  keep(shown) {
    if (this.shown?.url) URL.revokeObjectURL(this.shown.url);
    this.shown = shown;
    this.part('download-svg').disabled = false;
  }

  setDrawn(drawn) {
    for (const role of ['zoom-in', 'zoom-out', 'fit']) this.part(role).disabled = !drawn;
    this.image.hidden = !drawn;
    this.part('note').hidden = drawn || !this.shown;
  }

  download() {
    // A map's name is no file name: its dot (R2.4) is not an extension.
    if (this.shown) downloadBytes(this.shown.svg, downloadName(`${this.shown.name}.svg`, 'svg'), 'image/svg+xml');
  }

  get drawn() {
    return Boolean(this.shown?.url);
  }

  fitScale() {
    return fitView(this.stage.clientWidth, this.stage.clientHeight, this.shown.width, this.shown.height).scale;
  }

  fit() {
    if (!this.drawn) return;
    this.fitted = true;
    this.apply(fitView(this.stage.clientWidth, this.stage.clientHeight, this.shown.width, this.shown.height));
  }

  zoomAt(factor, px, py) {
    if (!this.drawn) return;
    this.fitted = false;
    this.apply(zoomAbout(this.view, factor, px, py, this.fitScale()));
  }

  zoomAtCentre(factor) {
    this.zoomAt(factor, this.stage.clientWidth / 2, this.stage.clientHeight / 2);
  }

  panBy(dx, dy) {
    if (!this.drawn) return;
    this.fitted = false;
    this.apply({ ...this.view, x: this.view.x + dx, y: this.view.y + dy });
  }

  // The image is laid out at its zoomed size (not scaled by a transform), so that the browser draws
  // the vector image sharp at every zoom.
  apply(view) {
    this.view = view;
    this.image.style.width = `${view.scale * this.shown.width}px`;
    this.image.style.height = `${view.scale * this.shown.height}px`;
    this.image.style.transform = `translate(${view.x}px, ${view.y}px)`;
  }

  onWheel(event) {
    event.preventDefault();
    const pixels = event.deltaMode === WheelEvent.DOM_DELTA_LINE ? 16 * event.deltaY : event.deltaY;
    const box = this.stage.getBoundingClientRect();
    this.zoomAt(Math.exp(-0.0015 * pixels), event.clientX - box.left, event.clientY - box.top);
  }

  onKey(event) {
    const actions = {
      '+': () => this.zoomAtCentre(BUTTON_ZOOM),
      '=': () => this.zoomAtCentre(BUTTON_ZOOM),
      '-': () => this.zoomAtCentre(1 / BUTTON_ZOOM),
      0: () => this.fit(),
      ArrowLeft: () => this.panBy(KEY_PAN, 0),
      ArrowRight: () => this.panBy(-KEY_PAN, 0),
      ArrowUp: () => this.panBy(0, KEY_PAN),
      ArrowDown: () => this.panBy(0, -KEY_PAN),
    };
    if (!Object.hasOwn(actions, event.key)) return;
    event.preventDefault();
    actions[event.key]();
  }

  startDrag(event) {
    if (event.button !== 0 || !this.drawn) return;
    this.stage.setPointerCapture(event.pointerId);
    let last = { x: event.clientX, y: event.clientY };
    const move = (moveEvent) => {
      this.panBy(moveEvent.clientX - last.x, moveEvent.clientY - last.y);
      last = { x: moveEvent.clientX, y: moveEvent.clientY };
    };
    const end = () => {
      this.stage.removeEventListener('pointermove', move);
      this.stage.removeEventListener('pointerup', end);
      this.stage.removeEventListener('pointercancel', end);
    };
    this.stage.addEventListener('pointermove', move);
    this.stage.addEventListener('pointerup', end);
    this.stage.addEventListener('pointercancel', end);
  }
}
