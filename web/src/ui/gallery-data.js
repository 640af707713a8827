// The gallery's cards: every map of the catalog and its dual, with what the shipped realization
// manifest (data/regmaps/realizations.json, `tessera regmap realize`) says about it, and the
// gallery's filters and orders over them.

// The kinds of surface a map is drawn on, by the base its target's regular surface is built on:
// a symmetric base (a Platonic double cover, a bouquet), the spine, or the relaxation.
export const BASE_KINDS = Object.freeze(['symmetric', 'spine', 'relaxation']);
export const SORT_KEYS = Object.freeze(['genus', 'order', 'name']);

/** 'symmetric', 'spine' or 'relaxation' for a surface's base name ("2-Cube", "bouquet", ...). */
export const baseKind = (base) => (base === 'spine' || base === 'relaxation' ? base : 'symmetric');

/**
 * The cards, from the manifest (`tessera regmap realize`: maps realized, with their targets, and
 * unrealized, each with source, genus, p, q, order, V, E, F): { name, genus, p, q, order, vertices,
 * edges, faces, realization }, realization null or { target, base, kind, selfIntersections } (base
 * and selfIntersections null where the manifest predates them).
 */
export function galleryEntries(manifest) {
  const card = (m, realization) => ({
    name: m.source,
    genus: m.genus,
    p: m.p,
    q: m.q,
    order: m.order,
    vertices: m.V,
    edges: m.E,
    faces: m.F,
    realization,
  });
  const realized = (m) => {
    const base = m.surface?.base ?? null;
    return {
      target: m.target,
      base,
      kind: base === null ? null : baseKind(base),
      selfIntersections: m.surface?.self_intersections ?? null,
    };
  };
  const cards = [...(manifest.maps ?? []).map((m) => card(m, realized(m))), ...(manifest.unrealized ?? []).map((m) => card(m, null))];
  return cards.filter((c) => typeof c.name === 'string' && Number.isInteger(c.genus) && Number.isInteger(c.p) && Number.isInteger(c.q));
}

// The cards as the page loads them before its first paint (scripts/gallery-index-plugin.js packs
// them at build time): one row per card, [name, genus, p, q, order, V, E, F] and, for a realized
// map, [target, base, selfIntersections] after them; a fifth of the manifest's size.
export const packGallery = (entries) =>
  entries.map((e) => {
    const row = [e.name, e.genus, e.p, e.q, e.order, e.vertices, e.edges, e.faces];
    const r = e.realization;
    return r ? [...row, r.target, r.base, r.selfIntersections] : row;
  });

/** The cards of packGallery's rows. */
export const unpackGallery = (rows) =>
  rows.map(([name, genus, p, q, order, vertices, edges, faces, target, base, selfIntersections]) => ({
    name,
    genus,
    p,
    q,
    order,
    vertices,
    edges,
    faces,
    realization:
      target === undefined ? null : { target, base, kind: base === null ? null : baseKind(base), selfIntersections },
  }));

/**
 * The gallery's filter fields as typed ({ name, genus, p, q, realized, base, sort }) ->
 * { query, problems }. query: { name (lower case text the name must contain), genus: { min, max }
 * | null, p, q (numbers or null), realized (bool), base (a BASE_KINDS value or null), sort };
 * problems names each field that could not be read (that field is then not used).
 */
export function parseGalleryQuery({ name = '', genus = '', p = '', q = '', realized = false, base = '', sort = 'genus' }) {
  const query = { name: '', genus: null, p: null, q: null, realized: Boolean(realized), base: null, sort: 'genus' };
  const problems = {};
  const text = String(name).trim();
  if (/^[A-Za-z0-9.']{0,16}$/.test(text)) query.name = text.toLowerCase();
  else problems.name = "Name: letters, digits, dots and a prime, such as R3.1 or R3.1'.";
  const genusMatch = /^(\d{1,4})(?:\s*(?:-|\.\.)\s*(\d{1,4}))?$/.exec(String(genus).trim());
  if (genusMatch) query.genus = { min: Number(genusMatch[1]), max: Number(genusMatch[2] ?? genusMatch[1]) };
  else if (String(genus).trim()) problems.genus = 'Genus: a number (3) or a range (2-10).';
  for (const [key, value] of [['p', p], ['q', q]]) {
    const t = String(value).trim();
    if (/^\d{1,4}$/.test(t)) query[key] = Number(t);
    else if (t) problems[key] = `${key}: a whole number such as 3.`;
  }
  if (BASE_KINDS.includes(base)) query.base = base;
  if (SORT_KEYS.includes(sort)) query.sort = sort;
  return { query, problems };
}

/** The entries that pass a query, in its order (stable within equal keys: catalog order). */
export function filterGallery(entries, query) {
  const kept = entries.filter(
    (e) =>
      (query.name === '' || e.name.toLowerCase().includes(query.name)) &&
      (query.genus === null || (e.genus >= query.genus.min && e.genus <= query.genus.max)) &&
      (query.p === null || e.p === query.p) &&
      (query.q === null || e.q === query.q) &&
      (!query.realized || e.realization !== null) &&
      (query.base === null || e.realization?.kind === query.base),
  );
  return sortGallery(kept, query.sort);
}

/** Ordered by genus, by |G|, or by name (R2.1, R2.1', R2.2, ..., R10.1: numbers as numbers). */
export function sortGallery(entries, key) {
  const byName = (a, b) => compareNames(a.name, b.name);
  const compare = {
    genus: (a, b) => a.genus - b.genus || byName(a, b),
    order: (a, b) => a.order - b.order || byName(a, b),
    name: byName,
  }[key] ?? byName;
  return [...entries].sort(compare);
}

function compareNames(a, b) {
  const parse = (name) => {
    const m = /^R(\d+)\.(\d+)('?)$/.exec(name);
    return m ? [Number(m[1]), Number(m[2]), m[3] ? 1 : 0] : [Infinity, 0, 0];
  };
  const [x, y] = [parse(a), parse(b)];
  return x[0] - y[0] || x[1] - y[1] || x[2] - y[2] || (a < b ? -1 : a > b ? 1 : 0);
}

/** The thumbnail's file name for a map: R3.1 -> R3.1.webp, R3.1' -> R3.1d.webp (no quote in a URL). */
export const thumbnailFile = (name) => `${String(name).replace(/'$/, 'd')}.webp`;
