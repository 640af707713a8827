// Searching the regular-map catalog. Its rows come from the core (data/regmaps, one row per map up
// to duality, with p <= q): { name, genus, p, q, petrie, order, vertices, edges, faces }. A search for
// a name with a prime (R3.1') or for a type {p,q} with p > q lists the duals.

/** The dual of a catalog row: p and q swap, and so do vertices and faces. */
export function dualRow(row) {
  return { ...row, name: `${row.name}'`, p: row.q, q: row.p, vertices: row.faces, faces: row.vertices };
}

/** The row a name (R3.1, or R3.1' for the dual) stands for, or undefined when the catalog has none. */
export function findMap(rows, name) {
  const dual = String(name).endsWith("'");
  const base = dual ? name.slice(0, -1) : name;
  const row = rows.find((r) => r.name === base);
  return row && dual ? dualRow(row) : row;
}

/**
 * The search fields as typed ({ name, genus, type }, texts) -> { query, problems }.
 * query: { name: a prefix of the number after R, dual, genus: { min, max } | null, type: { p, q } | null };
 * problems: { name?, genus?, type? }, what could not be read in plain words (that field is not used).
 */
export function parseQuery({ name = '', genus = '', type = '' }) {
  const query = { name: '', dual: false, genus: null, type: null };
  const problems = {};
  const nameMatch = /^R?([\d.]*)('?)$/i.exec(name.trim());
  if (nameMatch) [query.name, query.dual] = [nameMatch[1], nameMatch[2] === "'"];
  else problems.name = "Name: write it as R3.1, or R3.1' for the dual.";
  const genusMatch = /^(\d{1,4})(?:\s*-\s*(\d{1,4}))?$/.exec(genus.trim());
  if (genusMatch) query.genus = { min: Number(genusMatch[1]), max: Number(genusMatch[2] ?? genusMatch[1]) };
  else if (genus.trim()) problems.genus = 'Genus: a number (3) or a range (2-10).';
  const typeMatch = /^\{?\s*(\d{1,4})\s*,\s*(\d{1,4})\s*\}?$/.exec(type.trim());
  if (typeMatch) query.type = { p: Number(typeMatch[1]), q: Number(typeMatch[2]) };
  else if (type.trim()) problems.type = 'Type: two numbers p,q such as 3,7 or {3,7}.';
  return { query, problems };
}

/** The catalog entries (rows, or their duals when the query asks for duals) that match a query. */
export function filterCatalog(rows, query) {
  const duals = query.dual || (query.type !== null && query.type.p > query.type.q);
  const entries = duals ? rows.map(dualRow) : rows;
  return entries.filter(
    (entry) =>
      entry.name.slice(1).startsWith(query.name) &&
      (query.genus === null || (entry.genus >= query.genus.min && entry.genus <= query.genus.max)) &&
      (query.type === null || (entry.p === query.type.p && entry.q === query.type.q)),
  );
}
