import { describe, expect, it } from 'vitest';
import { baseKind, filterGallery, galleryEntries, packGallery, parseGalleryQuery, sortGallery, thumbnailFile, unpackGallery } from '../../web/src/ui/gallery-data.js';
import { cameraOf, cameraText, formatHash, parseHash } from '../../web/src/ui/hash.js';
import { drawnDescription } from '../../web/src/ui/drawn-figures.js';

// A manifest as `tessera regmap realize` writes it (pairings left out): realized maps with their
// targets, the others with their figures only.
const fig = (source, genus, p, q, order, V, E, F) => ({ source, genus, p, q, order, V, E, F });
const MANIFEST = {
  version: 2,
  maps: [
    { ...fig('R3.1', 3, 3, 7, 336, 24, 84, 56), target: 'Tetrahedron', target_kind: 'platonic', others: [], surface: { base: 'relaxation', self_intersections: 0 } },
    { ...fig("R9.3'", 9, 6, 4, 240, 30, 80, 40), target: "R2.1'", target_kind: 'catalog', others: ['{2,10}'], surface: { base: '2-Cube', self_intersections: 0 } },
    { ...fig('R2.1', 2, 3, 8, 96, 6, 24, 16), target: '{6,3}_(1,0)', target_kind: 'torus', others: [], surface: { base: 'spine', self_intersections: 3 } },
    { ...fig('R10.2', 10, 3, 4, 48, 4, 6, 4), target: '{2,11}', target_kind: 'hosohedron', others: [] },
  ],
  unrealized: [
    fig("R2.1'", 2, 8, 3, 96, 16, 24, 6),
    fig('R2.4', 2, 5, 10, 20, 1, 5, 2),
    fig("R2.4'", 2, 10, 5, 20, 2, 5, 1),
    fig("R3.1'", 3, 7, 3, 336, 56, 84, 24),
    fig("R10.2'", 10, 4, 3, 48, 4, 6, 4),
    fig('R9.3', 9, 4, 6, 240, 40, 80, 30),
    { source: '<b>broken</b>', genus: 'x' },
  ],
};
const entries = galleryEntries(MANIFEST);
const names = (list) => list.map((e) => e.name);
const query = (fields) => {
  const { query: q, problems } = parseGalleryQuery(fields);
  expect(problems).toEqual({});
  return names(filterGallery(entries, q));
};

describe('gallery cards', () => {
  it('has every map of the manifest, realized or not, and drops malformed entries', () => {
    expect(entries).toHaveLength(10);
    const dual = entries.find((e) => e.name === "R2.1'");
    expect([dual.p, dual.q, dual.order, dual.vertices, dual.edges, dual.faces]).toEqual([8, 3, 96, 16, 24, 6]);
    expect(dual.realization).toBeNull();
  });

  it('packs the cards into rows the page unpacks to the same cards', () => {
    const rows = packGallery(entries);
    expect(rows.find((row) => row[0] === "R2.1'")).toEqual(["R2.1'", 2, 8, 3, 96, 16, 24, 6]);
    expect(rows.find((row) => row[0] === 'R2.1').slice(8)).toEqual(['{6,3}_(1,0)', 'spine', 3]);
    expect(unpackGallery(JSON.parse(JSON.stringify(rows)))).toEqual(entries);
  });

  it('joins the realizations by name, with the kind of their base', () => {
    const klein = entries.find((e) => e.name === 'R3.1').realization;
    expect(klein).toMatchObject({ target: 'Tetrahedron', kind: 'relaxation', selfIntersections: 0 });
    expect(entries.find((e) => e.name === "R9.3'").realization.kind).toBe('symmetric');
    expect(entries.find((e) => e.name === 'R9.3').realization).toBeNull();
    // A manifest without surfaces: realized, base unknown.
    expect(entries.find((e) => e.name === 'R10.2').realization).toMatchObject({ kind: null, selfIntersections: null });
    expect(['bouquet', '2-Octahedron', 'spine', 'relaxation'].map(baseKind)).toEqual(['symmetric', 'symmetric', 'spine', 'relaxation']);
  });

  it('filters by genus, p, q, name, realization and base kind', () => {
    expect(query({ genus: '3' })).toEqual(['R3.1', "R3.1'"]);
    expect(query({ genus: '2-3', p: '3' })).toEqual(['R2.1', 'R3.1']);
    expect(query({ genus: '9..10', q: '3' })).toEqual(["R10.2'"]);
    expect(query({ name: "r9.3'" })).toEqual(["R9.3'"]);
    expect(query({ realized: true })).toEqual(['R2.1', 'R3.1', "R9.3'", 'R10.2']);
    expect(query({ base: 'symmetric' })).toEqual(["R9.3'"]);
    expect(query({ base: 'spine', genus: '3' })).toEqual([]);
  });

  it('orders by genus, |G| or name, numbers as numbers', () => {
    expect(names(sortGallery(entries, 'name')).slice(0, 6)).toEqual(['R2.1', "R2.1'", 'R2.4', "R2.4'", 'R3.1', "R3.1'"]);
    expect(names(sortGallery(entries, 'name')).slice(-2)).toEqual(['R10.2', "R10.2'"]);
    expect(names(sortGallery(entries, 'order')).slice(0, 4)).toEqual(['R2.4', "R2.4'", 'R10.2', "R10.2'"]);
    expect(query({ sort: 'genus' }).slice(-2)).toEqual(['R10.2', "R10.2'"]);
  });

  it('names what it cannot read and leaves that field out', () => {
    const { query: q, problems } = parseGalleryQuery({ name: '<img src=x>', genus: 'three', p: '-1', q: '7', base: 'nope', sort: 'size' });
    expect(Object.keys(problems).sort()).toEqual(['genus', 'name', 'p']);
    expect(q).toMatchObject({ name: '', genus: null, p: null, q: 7, base: null, sort: 'genus' });
  });

  it('names thumbnails without quotes', () => {
    expect(thumbnailFile('R3.1')).toBe('R3.1.webp');
    expect(thumbnailFile("R3.1'")).toBe('R3.1d.webp');
  });
});

describe('gallery links', () => {
  it('keep the filters and drop malformed ones', () => {
    const hash = formatHash({ ...parseHash('').state, mode: 'gallery', genus: '2-5', p: '3', realized: true, kind: 'symmetric', sort: 'order', find: "R3.1'" });
    const { state, problems } = parseHash(hash);
    expect(problems).toEqual([]);
    expect(state).toMatchObject({ mode: 'gallery', genus: '2-5', p: '3', realized: true, kind: 'symmetric', sort: 'order', find: "R3.1'" });
    const bad = parseHash('#mode=gallery&genus=2-x&kind=<b>&sort=genus&find=%3Cscript%3E');
    expect(bad.problems).toHaveLength(4);
    expect(bad.state).toMatchObject({ genus: null, kind: null, sort: null, find: null });
  });
});

describe('camera links', () => {
  it('keep the camera to 1e-4 and refuse anything else', () => {
    const view = { position: [1.5, -2, 3.125], target: [0, 0.001, -0.5] };
    const hash = formatHash({ ...parseHash('').state, mode: 'regmap', map: 'R3.1', cam: cameraText(view), spin: true });
    expect(hash).toBe('#mode=regmap&map=R3.1&cam=1.5_-2_3.125_0_0.001_-0.5&spin=1');
    expect(cameraOf(parseHash(hash).state.cam)).toEqual(view);
    for (const cam of ['1_2_3', '1_2_3_4_5_6_7', '1e3_0_0_0_0_0', 'NaN_0_0_0_0_0', '1.23456_0_0_0_0_0', '123456_0_0_0_0_0']) {
      const { state, problems } = parseHash(`#cam=${cam}`);
      expect(state.cam, cam).toBeNull();
      expect(problems, cam).toHaveLength(1);
    }
    expect(cameraOf('<b>')).toBeNull();
  });
});

describe('the drawn view in words', () => {
  it('says what p, q and the genus are and what is drawn, with the map figures', () => {
    const drawn = { target: 'Tetrahedron', target_kind: 'platonic', genus: 3, pairing: { kind: 'rotations' }, expected: { V: 24, E: 84, F: 56 } };
    const [map, drawing] = drawnDescription('R3.1', { p: 3, q: 7 }, drawn);
    expect(map).toMatch(/^R3\.1 is a regular map of type \{3,7\}: 56 triangular faces \(p = 3 sides each\), 7 of them around each of its 24 vertices \(q = 7\), joined by 84 edges, on a closed surface of genus 3 \(a sphere with 3 handles\)/);
    expect(drawing).toMatch(/regular surface of Tetrahedron .* rotations of R3\.1: each of the 56 faces .* the 84 edges/);
    const [one] = drawnDescription('R2.4', { p: 5, q: 10 }, { ...drawn, genus: 2, expected: { V: 1, E: 5, F: 2 } });
    expect(one).toMatch(/2 pentagonal faces .* its 1 vertex .* 5 edges/);
  });
});
