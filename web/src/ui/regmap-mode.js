import { COMMANDS } from '../worker/protocol.js';
import { filterCatalog, findMap, parseQuery } from './catalog-filter.js';
import { count, fillFigures } from './info-panel.js';
import { MAP_FIGURES, mapFigureValues } from './map-figures.js';
import { VirtualList } from './virtual-list.js';

const DEFAULT_MAP = 'R3.1'; // Klein's quartic
const ROW_HEIGHT = 24; // CSS pixels, as .catalog-list [role=option] in style.css
const SEARCH_FIELDS = ['name', 'genus', 'type'];
// The catalog's largest tiling has 8,064 triangles. The browser draws an SVG image on the page's
// thread: one of 16,000 triangles holds the page for about a second, larger ones only download.
const MAX_DRAWN_TRIANGLES = 16_000;

/**
 * The Regular maps mode: the catalog with its search, a map's figures, its tiling (the 2D view) or
 * its regular surface (the 3D view), and maps typed as presentations. Every name and presentation
 * is user text and is shown as text only.
 * panel: the mode's section of the page; view (TilingView); viewChoices: the radio buttons of the
 * views ('tiling', 'map', 'surface'); drawn (DrawnView: the map on a target's surface) and surface
 * (SurfaceView: its own regular surface), both null without a 3D view; client (WorkerClient), jobs
 * (Jobs), status (Status); onStateChange(partial state) when what a link should share changes.
 */
export class RegularMapMode {
  constructor({ panel, view, viewChoices, drawn, surface, client, jobs, status, onStateChange }) {
    Object.assign(this, { panel, view, viewChoices, drawn, surface, client, jobs, status, onStateChange });
    this.part = (role) => panel.querySelector(`[data-role=${role}]`);
    this.rows = null; // the catalog, once read
    this.shown = null; // { name, info }: the map on screen; name is null for a typed presentation

    this.list = new VirtualList(this.part('catalog-list'), {
      rowHeight: ROW_HEIGHT,
      fillRow: catalogRow,
      keyOf: (entry) => entry.name,
      onChoose: (entry) => this.showMap(entry.name),
    });
    for (const field of SEARCH_FIELDS) this.searchField(field).addEventListener('input', () => this.search());
    this.part('dual').addEventListener('click', () => this.showMap(dualName(this.shown.name)));
    this.part('run-presentation').addEventListener('click', () => this.runPresentation());
    this.part('presentation').addEventListener('keydown', (event) => {
      if (event.key === 'Enter' && (event.ctrlKey || event.metaKey)) this.runPresentation();
    });
    for (const choice of this.viewChoices) {
      choice.disabled = choice.value !== 'tiling' && !surface;
      choice.addEventListener('change', () => this.chooseView(choice.value));
    }
    this.part('tiling-beside').addEventListener('click', () => this.chooseView('tiling'));
  }

  /** Reads the catalog and shows state.map (or the default map). */
  async start(state) {
    const reply = await this.request('Reading the catalog of regular maps', COMMANDS.regmapCatalog, null);
    if (!reply) return;
    this.rows = reply.rows;
    this.search();
    await this.applyState(state);
  }

  /**
   * Shows the map a link names; without a valid one, keeps the map on screen (or the default).
   * Opens the link's view, in the 3D view with the link's surface options. Reads the catalog first
   * if an earlier attempt failed.
   */
  async applyState(state) {
    if (!this.rows) return this.start(state);
    this.surface?.setOptions(state);
    this.drawn?.setTarget(state.on);
    this.drawn?.setColors(state.colors);
    this.setView(state.view);
    const { map } = state;
    const known = map !== null && findMap(this.rows, map) !== undefined;
    if (known && map !== this.shown?.name) await this.showMap(map);
    if (!known && !this.shown) await this.showMap(DEFAULT_MAP);
    if (map !== null && !known) {
      this.status.showNotice(
        `There is no map named "${map}" in the catalog.`,
        `It holds ${count(this.rows.length)} maps, ${this.rows[0].name} to ${this.rows.at(-1).name} (a prime names the dual).`,
      );
    }
    await this.update3d();
  }

  /** 'tiling', 'map' or 'surface' (the 2D tiling, unless there is a 3D view). */
  setView(view) {
    const shown = this.surface ? view : 'tiling';
    for (const choice of this.viewChoices) choice.checked = choice.value === shown;
    this.view.setVisible(shown === 'tiling');
    this.showTilingBeside(shown);
    this.surface?.setActive(shown === 'surface');
    this.drawn?.setActive(shown === 'map');
  }

  // Beside a 3D view, the map's fundamental polygon as a small picture that opens the 2D view.
  showTilingBeside(view = this.viewChoices.find((choice) => choice.checked)?.value) {
    const button = this.part('tiling-beside');
    const url = this.view.imageUrl();
    button.hidden = view === 'tiling' || url === null;
    if (url !== null) button.querySelector('img').src = url;
  }

  async chooseView(view) {
    this.setView(view);
    this.onStateChange({ view });
    await this.update3d();
  }

  async update3d() {
    await this.surface?.update();
    await this.drawn?.update();
  }

  async showMap(name) {
    const result = await this.request(`Enumerating ${name} and drawing its tiling`, COMMANDS.regmapTiling, { map: name });
    if (result) await this.show(result, name, name);
  }

  async runPresentation() {
    const text = this.part('presentation').value.trim();
    const label = 'Enumerating the typed presentation and drawing its tiling';
    const result = await this.request(label, COMMANDS.regmapTiling, { map: text });
    if (result) await this.show(result, null, text);
  }

  /**
   * A tiling result from the worker, for a catalog map (name) or a typed presentation (null); spec:
   * the map as the core takes it (the name or the presentation's text).
   */
  async show(result, name, spec) {
    const title = name ?? `${result.info.name || 'A map'} (typed presentation)`;
    try {
      await this.drawTiling(result, name ?? result.info.name);
    } catch (error) {
      this.status.showError(error);
      return;
    }
    this.shown = { name, info: result.info };
    this.showTilingBeside();
    this.part('map-name').textContent = title;
    fillFigures(this.part('map-figures'), MAP_FIGURES, mapFigureValues(result));
    const dual = this.part('dual');
    dual.hidden = name === null;
    if (name !== null) dual.textContent = `Show its dual, ${dualName(name)}`;
    this.list.setChosen(name);
    this.onStateChange({ map: name });
    const map = { spec, name: name ?? (result.info.name || 'typed map') };
    this.drawn?.setTarget(null);
    await this.surface?.setMap(map);
    await this.drawn?.setMap(map);
  }

  drawTiling({ svg, polygon }, name) {
    if (polygon.triangles <= MAX_DRAWN_TRIANGLES) return this.view.show(svg, name);
    return this.view.showUndrawn(
      svg,
      name,
      `This tiling has ${count(polygon.triangles)} triangles, more than the page draws ` +
        `(${count(MAX_DRAWN_TRIANGLES)}) without holding up. Download the SVG to see it.`,
    );
  }

  search() {
    if (!this.rows) return;
    const { query, problems } = parseQuery(
      Object.fromEntries(SEARCH_FIELDS.map((field) => [field, this.searchField(field).value])),
    );
    for (const field of SEARCH_FIELDS) {
      this.searchField(field).setAttribute('aria-invalid', String(Object.hasOwn(problems, field)));
    }
    const entries = filterCatalog(this.rows, query);
    this.list.setItems(entries);
    const found = entries.length === 0 ? 'No map matches.' : `${count(entries.length)} of ${count(this.rows.length)} maps`;
    this.part('catalog-count').textContent = [...Object.values(problems), found].join(' ');
  }

  searchField(field) {
    return this.part(`search-${field}`);
  }

  request(label, command, payload) {
    return this.jobs.run(label, (onProgress) => this.client.request(command, payload, { onProgress }));
  }
}

/** R3.1 <-> R3.1'. */
const dualName = (name) => (name.endsWith("'") ? name.slice(0, -1) : `${name}'`);

// One row of the catalog list: name, type, genus, group order, each in a cell of its own.
function catalogRow(row, entry) {
  row.setAttribute('aria-label', `${entry.name}, type {${entry.p},${entry.q}}, genus ${entry.genus}, |G| ${count(entry.order)}`);
  const cells = [entry.name, `{${entry.p},${entry.q}}`, String(entry.genus), count(entry.order)].map((text) => {
    const cell = document.createElement('span');
    cell.textContent = text;
    return cell;
  });
  row.replaceChildren(...cells);
}
