// Regular maps in the wasm module: the shipped catalog loads, figures match the native rows, and
// a presentation of an infinite group ends with a clear limit error.
import test from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { loadTessera } from './tessera_module.mjs';

const here = path.dirname(fileURLToPath(import.meta.url));
const catalogText = fs.readFileSync(path.resolve(here, '../../data/regmaps/catalog_g2-101.tsv'), 'utf8');
const tessera = await loadTessera();
const rows = tessera.regmapLoadCatalog(catalogText);

test('the catalog loads with all 3378 maps', () => {
  assert.equal(rows.length, 3378);
  const klein = rows.find((r) => r.name === 'R3.1');
  assert.deepEqual([klein.p, klein.q, klein.order, klein.vertices, klein.edges, klein.faces], [3, 7, 336, 24, 84, 56]);
});

test('figures of catalog maps and their duals', () => {
  const klein = tessera.regmapInfo('R3.1');
  assert.deepEqual([klein.order, klein.vertices, klein.edges, klein.faces, klein.genus, klein.petrie], [336, 24, 84, 56, 3, 8]);
  const r24 = tessera.regmapInfo('R2.4');
  assert.deepEqual([r24.order, r24.vertices, r24.edges, r24.faces, r24.genus], [20, 1, 5, 2, 2]);
  const dual = tessera.regmapInfo("R2.4'");
  assert.deepEqual([dual.p, dual.q, dual.vertices, dual.faces], [10, 5, 2, 1]);
  for (const row of rows.filter((r) => r.genus <= 4)) {
    const info = tessera.regmapInfo(row.name);
    assert.deepEqual([info.order, info.vertices, info.edges, info.faces, info.genus], [row.order, row.vertices, row.edges, row.faces, row.genus], row.name);
  }
});

test('a presentation typed by hand: the cube, and an infinite group', () => {
  const cube = tessera.regmapInfo('Cube : Type {4,3} Order 48\n[ T^2, R^4, S^3, (R * S)^2, (R * T)^2, (S * T)^2 ]');
  assert.deepEqual([cube.order, cube.vertices, cube.edges, cube.faces, cube.euler], [48, 8, 12, 6, 2]);
  const start = Date.now();
  assert.throws(() => tessera.regmapInfo('Hyperbolic : Type {3,7}\n[ T^2, R^3, S^7, (R * S)^2, (R * T)^2, (S * T)^2 ]'),
    (e) => e.kind === 'limit' && /--max-cosets|--max-seconds|limit/.test(e.message));
  assert.ok(Date.now() - start < 15000);
  assert.throws(() => tessera.regmapInfo('X : Type {3,7}\n[ T^2, R^3, Q^7 ]'), (e) => e.kind === 'parse');
  assert.throws(() => tessera.regmapInfo('R999.1'), (e) => e.kind === 'input');
});

test('the tiling of R2.4 is one polygon with paired sides, drawn as SVG', () => {
  const { info, svg, polygon } = tessera.regmapTiling('R2.4');
  assert.equal(info.order, 20);
  assert.equal(polygon.triangles, 20);
  assert.equal(polygon.euler, 1);
  assert.equal(polygon.boundaryCycles, 1);
  assert.ok(polygon.boundaryPairs > 0);
  assert.match(svg, /^<\?xml|^<svg/);
});

test('the regular surface of R2.4 is a closed genus-5 surface of 20 quarter tubes, and exports', () => {
  const stages = new Set();
  const surface = tessera.regmapSurface('R2.4', { base: 'auto' }, (stage) => stages.add(stage));
  assert.equal(surface.stats.genus, 5);
  assert.equal(surface.stats.quarter_tubes, 20);
  assert.equal(surface.stats.closed, true);
  assert.equal(surface.stats.oriented, true);
  assert.equal(surface.stats.relations_hold, true);
  assert.equal(surface.tile.length, surface.triangleFace[surface.triangleFace.length - 1] + 1);
  assert.equal(new Set(surface.tile).size, 20);
  assert.ok(stages.size > 0);
  const glb = tessera.regmapSurfaceGlb();
  assert.equal(new TextDecoder().decode(glb.subarray(0, 4)), 'glTF');
  assert.throws(() => tessera.regmapSurface('R2.4', { base: 'hexagonal' }, undefined), (e) => e.kind === 'input');
});

test('native and wasm build the same regular surface: bouquet, spine, 2-Octahedron, relaxation', () => {
  const cli = path.resolve(here, '../../build/native/cli/tessera');
  for (const name of ['R2.4', 'R2.5', "R3.4'", 'R3.1']) {
    const wasm = tessera.regmapSurface(name, {}, undefined).stats;
    const native = JSON.parse(execFileSync(cli, ['regmap', 'surface', name, '--json'], { encoding: 'utf8' }));
    for (const key of ['base', 'genus', 'closed', 'oriented', 'quarter_tubes', 'vertices', 'faces',
      'relations_hold', 'self_intersections', 'symmetries_verified'])
      assert.deepEqual(wasm[key], native[key], `${name}.${key}`);
  }
});

// Thesis Sec. 9.5-9.6: the Klein quartic on the tetrahedron and R9.3' on the 2-Cube, drawn in the
// module as natively (the same target, pairing and figures), and again from the shipped manifest's
// pairing without a search.
test('native and wasm draw a map on the same surface through the same pairing', () => {
  const cli = path.resolve(here, '../../build/native/cli/tessera');
  const manifest = JSON.parse(fs.readFileSync(path.resolve(here, '../../data/regmaps/realizations.json'), 'utf8'));
  for (const name of ['R3.1', "R9.3'"]) {
    const wasm = tessera.regmapDrawn(name, {}, undefined);
    const native = JSON.parse(execFileSync(cli, ['regmap', 'map', name, '--json', '--no-self-intersections'], { encoding: 'utf8' }));
    for (const key of ['target', 'genus', 'V', 'E', 'F', 'faces_are_disks', 'covers_once', 'closed', 'oriented', 'mesh_faces'])
      assert.deepEqual(wasm.drawn[key], native[key], `${name}.${key}`);
    for (const key of ['kind', 'x', 'y']) assert.equal(wasm.drawn.pairing[key], native.pairing[key], `${name}.pairing.${key}`);
    assert.deepEqual([wasm.drawn.V, wasm.drawn.E, wasm.drawn.F], [native.expected.V, native.expected.E, native.expected.F]);
    assert.equal(new Set(wasm.face).size, native.F);
    assert.equal(wasm.face.length, wasm.triangleFace[wasm.triangleFace.length - 1] + 1);
    assert.ok(wasm.edges.length > 0 && wasm.edges.length % 6 === 0);

    const entry = manifest.maps.find((m) => m.source === name);
    const fromManifest = tessera.regmapDrawn(name, { pairing: JSON.stringify(entry.pairing) }, undefined);
    assert.equal(fromManifest.drawn.target, entry.target);
    assert.equal(fromManifest.drawn.F, native.F);
  }
  const glb = tessera.regmapDrawnExport('glb', {}, undefined);
  assert.equal(new TextDecoder().decode(glb.bytes.subarray(0, 4)), 'glTF');
  assert.equal(glb.print, null);
  const ply = tessera.regmapDrawnExport('ply', {}, undefined);
  assert.match(new TextDecoder().decode(ply.bytes.subarray(0, 400)), /^ply\n[^]*property int face/);
  // The STL to print: 50 triangles' bytes each after the 84-byte header, checked at the size asked.
  const stl = tessera.regmapDrawnExport('stl', { sizeMm: 80, wallMm: 1 }, undefined);
  const triangles = new DataView(stl.bytes.buffer, stl.bytes.byteOffset).getUint32(80, true);
  assert.equal(stl.bytes.length, 84 + 50 * triangles);
  assert.equal(Math.max(...stl.print.extent_mm).toFixed(6), '80.000000');
  assert.ok(stl.print.closed && stl.print.oriented && stl.print.thinnest_mm > 1, JSON.stringify(stl.print));
  assert.equal(stl.print.printable, stl.print.self_intersections === 0);
  const thin = tessera.regmapDrawnExport('stl', { sizeMm: 80, wallMm: 2 * stl.print.thinnest_mm }, undefined);
  assert.equal(thin.print.printable, false);
  assert.match(thin.print.problems.at(-1), /thinner than the/);
  assert.throws(() => tessera.regmapDrawnExport('stl', { sizeMm: -1 }, undefined), (e) => e.kind === 'input');
  assert.throws(() => tessera.regmapDrawnExport('exe', {}, undefined), (e) => e.kind === 'input');
  assert.throws(() => tessera.regmapDrawn('R3.1', { pairing: '{"target": "Tetrahedron"}' }, undefined), (e) => e.kind === 'input');
  assert.throws(() => tessera.regmapDrawn('R3.1', { on: 'Cube' }, undefined), (e) => e.kind === 'input');
});
