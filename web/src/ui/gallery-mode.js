import { count } from './info-panel.js';
import { filterGallery, parseGalleryQuery, thumbnailFile, unpackGallery } from './gallery-data.js';
import { VirtualGrid } from './virtual-grid.js';

// A card's size in CSS pixels (style.css .gallery-card follows it): a 192 px thumbnail, three
// lines of text and two of badges under it.
const CARD = Object.freeze({ cardWidth: 208, cardHeight: 330, gap: 12 });
// The filter fields, as the panel's inputs and the link's keys name them.
const FIELDS = Object.freeze(['find', 'genus', 'p', 'q', 'realized', 'kind', 'sort']);
const BASE_LABELS = Object.freeze({ symmetric: 'symmetric base', spine: 'spine', relaxation: 'relaxed' });

/**
 * The Gallery mode: every map of the catalog and its dual as a card (a thumbnail of the map drawn
 * on its surface where `npm run build:gallery` rendered one, its name, type, genus, |G| and
 * badges), filtered and ordered by the panel's fields, each card a link to the map in the Regular
 * maps mode. Names come from the catalog and the manifest and are shown as text only.
 * panel: the mode's section of the side panel; grid: the element the cards scroll in; status;
 * base: the URL the static build's files are under (thumbnails/); mapLink(name):
 * the link that opens a map; onStateChange(partial state) when the filters change; maker: the
 * ThumbnailMaker (thumbnails.js) that renders a realized map's thumbnail the build has not.
 */
export class GalleryMode {
  constructor({ panel, grid, status, base, mapLink, onStateChange, maker }) {
    Object.assign(this, { panel, status, base, mapLink, onStateChange, maker });
    this.rendered = new Map(); // map name -> { url, source } of a thumbnail made in this page
    this.part = (role) => panel.querySelector(`[data-role=${role}]`);
    this.entries = null;
    this.query = null; // the filters as last read (parseGalleryQuery)
    this.thumbnails = new Set();
    this.grid = new VirtualGrid(grid, {
      ...CARD,
      fillCard: (card, entry) => this.fillCard(card, entry),
      keyOf: (entry) => entry.name,
      onOpen: (entry) => {
        location.hash = this.mapLink(entry.name);
      },
    });
    for (const field of FIELDS) {
      const input = this.input(field);
      input.addEventListener(input.type === 'checkbox' || input.tagName === 'SELECT' ? 'change' : 'input', () => {
        this.filter();
        this.onStateChange(this.fieldState());
      });
    }
  }

  /**
   * Reads the cards (a chunk of their own, packed from the manifest at build time; no core needed,
   * so that the cards are on screen at once) and the list of thumbnails, then shows the cards.
   */
  async start(state) {
    try {
      const [{ default: rows }, thumbnails] = await Promise.all([readGalleryIndex(), this.readThumbnails()]);
      this.entries = unpackGallery(rows);
      this.thumbnails = thumbnails;
    } catch (error) {
      this.status.showError({ kind: 'internal', message: `The gallery's list of maps could not be read (${error.message}). Reload the page.` });
      return;
    }
    await this.applyState(state);
  }

  async applyState(state) {
    if (!this.entries) return this.start(state);
    for (const field of FIELDS) {
      const input = this.input(field);
      const value = state[field];
      if (input.type === 'checkbox') input.checked = Boolean(value);
      else input.value = value ?? (field === 'sort' ? 'genus' : '');
    }
    this.filter();
  }

  filter() {
    if (!this.entries) return;
    const { query, problems } = parseGalleryQuery({
      name: this.input('find').value,
      genus: this.input('genus').value,
      p: this.input('p').value,
      q: this.input('q').value,
      realized: this.input('realized').checked,
      base: this.input('kind').value,
      sort: this.input('sort').value,
    });
    for (const field of ['find', 'genus', 'p', 'q']) {
      const key = field === 'find' ? 'name' : field;
      this.input(field).setAttribute('aria-invalid', String(Object.hasOwn(problems, key)));
    }
    this.query = query;
    const shown = filterGallery(this.entries, query);
    this.grid.setItems(shown);
    const found = shown.length === 0 ? 'No map matches.' : `${count(shown.length)} of ${count(this.entries.length)} maps`;
    this.part('gallery-count').textContent = [...Object.values(problems), found].join(' ');
  }

  // The filters as the link keeps them: what was read of each field (a field that could not be
  // read is left out), empty ones and the default order as null.
  fieldState() {
    const { name, genus, p, q, realized, base, sort } = this.query;
    const range = genus && (genus.min === genus.max ? `${genus.min}` : `${genus.min}-${genus.max}`);
    return {
      find: name ? this.input('find').value.trim() : null,
      genus: range || null,
      p: p === null ? null : String(p),
      q: q === null ? null : String(q),
      realized,
      kind: base,
      sort: sort === 'genus' ? null : sort,
    };
  }

  fillCard(card, entry) {
    const link = document.createElement('a');
    link.className = 'gallery-card';
    link.href = this.mapLink(entry.name);
    const r = entry.realization;
    link.setAttribute(
      'aria-label',
      `${entry.name}, type {${entry.p},${entry.q}}, genus ${entry.genus}` + (r ? `, drawn on ${r.target}` : ', not realized'),
    );
    link.append(this.thumbnail(entry), text('strong', entry.name), text('span', `{${entry.p},${entry.q}} · genus ${entry.genus}`));
    link.append(text('span', `|G| ${count(entry.order)} · V ${count(entry.vertices)} E ${count(entry.edges)} F ${count(entry.faces)}`));
    const badges = document.createElement('ul');
    badges.className = 'badges';
    if (r) {
      badges.append(text('li', `on ${r.target}`));
      if (r.kind) badges.append(text('li', BASE_LABELS[r.kind]));
      if (r.selfIntersections === 0) badges.append(text('li', 'no self-intersections'));
    } else {
      badges.append(text('li', 'tiling only'));
    }
    link.append(badges);
    card.replaceChildren(link);
  }

  // The build's thumbnail; else, for a realized map, one made on demand, shown in place of the
  // placeholder once it is there (if the card still shows the map); else the placeholder.
  thumbnail(entry) {
    const file = thumbnailFile(entry.name);
    if (this.thumbnails.has(file)) return thumbnailImage(`${this.base}thumbnails/${encodeURIComponent(file)}`, 'build');
    const made = this.rendered.get(entry.name);
    if (made) return thumbnailImage(made.url, made.source);
    const missing = text('span', `{${entry.p},${entry.q}}`);
    missing.className = 'thumbnail missing';
    missing.setAttribute('aria-hidden', 'true');
    if (entry.realization && this.maker) {
      this.maker.get(entry.name, file, () => missing.isConnected).then((thumbnail) => {
        if (!thumbnail) return;
        this.rendered.set(entry.name, thumbnail);
        if (missing.isConnected) missing.replaceWith(thumbnailImage(thumbnail.url, thumbnail.source));
      });
    }
    return missing;
  }

  // The thumbnails the static build holds (thumbnails/index.json, written by build:gallery); none
  // in the dev server or a build without them.
  async readThumbnails() {
    try {
      const response = await fetch(`${this.base}thumbnails/index.json`);
      if (!response.ok) return new Set();
      const { files } = await response.json();
      return new Set(Array.isArray(files) ? files.filter((f) => typeof f === 'string') : []);
    } catch {
      return new Set();
    }
  }

  input(field) {
    return this.part(`gallery-${field}`);
  }

}

let index = null;
/**
 * The cards' chunk (scripts/gallery-index-plugin.js), fetched once; the page calls it first thing
 * when it opens on the gallery, so that the fetch runs while the rest of the page starts.
 */
export function readGalleryIndex() {
  index ??= import('virtual:gallery-index');
  return index;
}

// A card's picture; source ('build', 'rendered', 'cache') says where it came from.
function thumbnailImage(src, source) {
  const image = document.createElement('img');
  image.className = 'thumbnail';
  image.loading = 'lazy';
  image.decoding = 'async';
  image.width = 192;
  image.height = 192;
  image.alt = '';
  image.dataset.source = source;
  image.src = src;
  return image;
}

function text(tag, content) {
  const element = document.createElement(tag);
  element.textContent = content;
  return element;
}
