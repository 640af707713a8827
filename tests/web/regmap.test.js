import { describe, expect, it } from 'vitest';
import { dualRow, filterCatalog, findMap, parseQuery } from '../../web/src/ui/catalog-filter.js';
import { formatSeconds, mapFigureValues } from '../../web/src/ui/map-figures.js';
import { visibleRange } from '../../web/src/ui/virtual-list.js';
import { fitView, zoomAbout } from '../../web/src/ui/tiling-view.js';

// Catalog rows as the core gives them (p <= q, one row per map up to duality).
const row = (name, genus, p, q, order, vertices, edges, faces) => ({ name, genus, p, q, petrie: 2, order, vertices, edges, faces });
const ROWS = [
  row('R2.1', 2, 3, 8, 96, 6, 24, 16),
  row('R2.4', 2, 5, 10, 20, 1, 5, 2),
  row('R3.1', 3, 3, 7, 336, 24, 84, 56),
  row('R3.10', 3, 8, 8, 32, 2, 8, 2),
  row('R13.1', 13, 3, 12, 192, 8, 48, 32),
  row('R31.1', 31, 3, 7, 1, 1, 1, 1),
];
const names = (entries) => entries.map((entry) => entry.name);
const search = (fields) => {
  const { query, problems } = parseQuery(fields);
  expect(problems).toEqual({});
  return names(filterCatalog(ROWS, query));
};

describe('catalog search', () => {
  it('lists everything for empty fields', () => {
    expect(search({})).toEqual(names(ROWS));
    expect(search({ name: '  ', genus: '', type: ' ' })).toEqual(names(ROWS));
  });

  it('matches names by prefix, with or without the R, in any case', () => {
    expect(search({ name: 'R3.1' })).toEqual(['R3.1', 'R3.10']);
    expect(search({ name: 'r3' })).toEqual(['R3.1', 'R3.10', 'R31.1']);
    expect(search({ name: '13.' })).toEqual(['R13.1']);
    expect(search({ name: 'R4' })).toEqual([]);
  });

  it('filters by genus, one or a range', () => {
    expect(search({ genus: '3' })).toEqual(['R3.1', 'R3.10']);
    expect(search({ genus: '3 - 13' })).toEqual(['R3.1', 'R3.10', 'R13.1']);
    expect(search({ genus: '13-3' })).toEqual([]);
  });

  it('filters by type, with or without braces, and combines the fields', () => {
    expect(search({ type: '{3,7}' })).toEqual(['R3.1', 'R31.1']);
    expect(search({ type: '3, 7', genus: '3' })).toEqual(['R3.1']);
    expect(search({ type: '3,7', name: 'R31' })).toEqual(['R31.1']);
  });

  it('lists duals, with swapped type, vertices and faces, for a prime or a type with p > q', () => {
    expect(search({ type: '{7,3}' })).toEqual(["R3.1'", "R31.1'"]);
    expect(search({ name: "R2.4'" })).toEqual(["R2.4'"]);
    const [dual] = filterCatalog(ROWS, parseQuery({ name: "R2.4'" }).query);
    expect(dual).toMatchObject({ p: 10, q: 5, vertices: 2, edges: 5, faces: 1, order: 20, genus: 2 });
    expect(search({ type: '8,8' })).toEqual(['R3.10']);
  });

  it('names what it cannot read and leaves that field out', () => {
    const { query, problems } = parseQuery({ name: 'Klein', genus: 'three', type: '{3;7}' });
    expect(Object.keys(problems)).toEqual(['name', 'genus', 'type']);
    expect(problems.genus).toMatch(/a number \(3\) or a range \(2-10\)/);
    expect(names(filterCatalog(ROWS, query))).toEqual(names(ROWS));
  });

  it('finds maps and duals by exact name only', () => {
    expect(findMap(ROWS, 'R3.1')).toBe(ROWS[2]);
    expect(findMap(ROWS, "R3.1'")).toEqual(dualRow(ROWS[2]));
    expect(findMap(ROWS, "R3.1'").name).toBe("R3.1'");
    for (const name of ['R3', 'R3.2', "R3.1''", 'R999.1']) expect(findMap(ROWS, name), name).toBeUndefined();
  });

  it('filters 3,378 rows by type and genus range', () => {
    const many = Array.from({ length: 3378 }, (_, i) => row(`R${2 + (i % 100)}.${1 + Math.floor(i / 100)}`, 2 + (i % 100), 3, 7 + (i % 9), 4 * i, 1, i, 1));
    const { query } = parseQuery({ type: '8,3', genus: '2-60' });
    const found = filterCatalog(many, query);
    expect(found.length).toBe(many.filter((r) => r.q === 8 && r.genus <= 60).length);
    expect(found.every((entry) => entry.name.endsWith("'") && entry.p === 8)).toBe(true);
  });
});

describe('map figures', () => {
  it('formats enumeration times', () => {
    expect(formatSeconds(0.0156)).toBe('16 ms');
    expect(formatSeconds(0.0000853)).toBe('0.09 ms');
    expect(formatSeconds(2.345)).toBe('2.35 s');
    expect(formatSeconds(undefined)).toBe('–');
  });

  it('takes the type and the polygon into the figures', () => {
    const values = mapFigureValues({ info: { p: 3, q: 7, order: 336 }, polygon: { triangles: 336, boundaryPairs: 40 } });
    expect(values).toMatchObject({ type: '{3,7}', order: 336, triangles: 336, boundaryPairs: 40 });
  });
});

describe('virtual list range', () => {
  it('draws the rows in view plus a few beyond each edge, within the list', () => {
    expect(visibleRange(0, 240, 24, 3378)).toEqual({ first: 0, last: 16 });
    expect(visibleRange(2400, 240, 24, 3378)).toEqual({ first: 94, last: 116 });
    expect(visibleRange(3378 * 24 - 240, 240, 24, 3378)).toEqual({ first: 3362, last: 3378 });
    expect(visibleRange(0, 240, 24, 0)).toEqual({ first: 0, last: 0 });
  });
});

describe('tiling view', () => {
  it('fits the image centred in the smaller side', () => {
    expect(fitView(1000, 500, 1000, 1000)).toEqual({ scale: 0.48, x: 260, y: 10 });
  });

  it('zooms about a point that stays put, within its limits', () => {
    const view = { scale: 1, x: 100, y: 50 };
    const zoomed = zoomAbout(view, 2, 300, 250, 1);
    expect(zoomed).toEqual({ scale: 2, x: -100, y: -150 });
    // the point under (300, 250) is the same image point before and after
    expect((300 - view.x) / view.scale).toBe((300 - zoomed.x) / zoomed.scale);
    expect(zoomAbout(view, 1000, 0, 0, 1).scale).toBe(24);
    expect(zoomAbout(view, 0.001, 0, 0, 1).scale).toBe(0.5);
  });
});
