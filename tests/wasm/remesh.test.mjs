// Quad meshes from layouts in the wasm module (thesis Ch. 8): the same quad mesh as the native CLI
// (`tessera remesh --json -o`) on the same file (counts, figures, positions), another count from
// what the session keeps of the layout giving what a fresh remesh gives, OBJ and GLB (_PATCH)
// exports, clear errors.
import test from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import validator from 'gltf-validator';
import { loadTessera, writeSampleObj } from './tessera_module.mjs';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
const cli = path.join(root, 'build/native/cli/tessera');
const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'tessera-remesh-'));
const tessera = await loadTessera();

const sampleFile = (name) => writeSampleObj(tessera, name, dir);

// The layout of a file in the module at alpha, with the CLI's defaults (smooth field, sharp 35).
function wasmLayout(file, alpha) {
  tessera.loadMesh(fs.readFileSync(file), path.basename(file));
  tessera.crossField({ sharp: 35 }, undefined);
  tessera.seamlessParam({}, undefined);
  tessera.layoutGraph({}, undefined);
  return tessera.layoutSolve(alpha, {}, undefined).info;
}

// The CLI's quad mesh of a file: its figures and the OBJ it writes (vertices and faces).
function nativeRemesh(file, alpha, quads) {
  const obj = path.join(dir, `${path.basename(file, '.obj')}-${quads}-quads.obj`);
  const json = JSON.parse(
    execFileSync(cli, ['remesh', file, '--alpha', String(alpha), '--quads', String(quads), '--json', '-o', obj], {
      encoding: 'utf8',
      stdio: ['ignore', 'pipe', 'ignore'],
    }),
  );
  return { json, ...readObj(fs.readFileSync(obj, 'latin1')) };
}

function readObj(text) {
  const positions = [];
  const faces = [];
  for (const line of text.split('\n')) {
    const [tag, ...rest] = line.trim().split(/\s+/);
    if (tag === 'v') positions.push(rest.map(Number));
    if (tag === 'f') faces.push(rest.map((r) => Number(r.split('/')[0]) - 1));
  }
  return { positions, faces };
}

const diagonal = (positions) => {
  const lo = [Infinity, Infinity, Infinity];
  const hi = [-Infinity, -Infinity, -Infinity];
  for (const p of positions) for (let k = 0; k < 3; k++) [lo[k], hi[k]] = [Math.min(lo[k], p[k]), Math.max(hi[k], p[k])];
  return Math.hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
};

// Same counts, same quads (vertex indices), same positions within float precision.
function assertSameQuadMesh(wasm, native, what) {
  const w = wasm.info;
  const n = native.json;
  for (const key of ['quads', 'vertices', 'irregular_vertices', 'patches', 'chains', 'flipped_quads', 'nonpositive_jacobian_quads', 'euler_characteristic', 'manifold', 'boundary_edges', 'irregular_off_nodes']) {
    assert.deepEqual(w[key], n[key], `${what}: ${key}`);
  }
  for (const key of ['lambda', 'min_scaled_jacobian', 'mean_scaled_jacobian', 'max_angle_deviation', 'mean_angle_deviation', 'hausdorff_relative']) {
    assert.ok(Math.abs(w[key] - n[key]) <= 1e-4 * Math.max(1, Math.abs(n[key])), `${what}: ${key} ${w[key]} vs ${n[key]}`);
  }
  assert.equal(wasm.positions.length, 3 * native.positions.length, `${what}: vertices`);
  assert.equal(wasm.quads.length, 4 * native.faces.length, `${what}: quads`);
  assert.deepEqual([...wasm.quads], native.faces.flat(), `${what}: the quads' vertices`);
  const tolerance = 1e-5 * diagonal(native.positions);
  let worst = 0;
  native.positions.forEach((p, v) => {
    for (let k = 0; k < 3; k++) worst = Math.max(worst, Math.abs(wasm.positions[3 * v + k] - p[k]));
  });
  assert.ok(worst <= tolerance, `${what}: positions differ by up to ${worst} (tolerance ${tolerance})`);
  return worst;
}

for (const [name, alpha, quads] of [
  ['sphere', 10, 400],
  ['genus2', 10, 1200],
]) {
  test(`native and wasm give the same quad mesh of the ${name} sample`, () => {
    const file = sampleFile(name);
    assert.equal(wasmLayout(file, alpha).valid, true);
    const stages = [];
    const wasm = tessera.remeshLayout({ quads }, (stage, fraction) => stages.push([stage, fraction]));
    const worst = assertSameQuadMesh(wasm, nativeRemesh(file, alpha, quads), `${name} at ${quads} quads`);
    console.log(`# ${name}: ${wasm.info.quads} quads, largest position difference native vs wasm ${worst.toExponential(2)}`);
    assert.equal(wasm.info.prepared_before, false);
    assert.deepEqual([...new Set(stages.map(([stage]) => stage))], ['remesh prep', 'remesh', 'hausdorff']);
    assert.equal(wasm.patch.length, wasm.info.quads);
    assert.equal(new Set(wasm.patch).size, wasm.info.patches);
    assert.equal(wasm.patchColors.length, 3 * wasm.info.patches);
    assert.equal(wasm.info.flipped_quads, 0);
    assert.equal(wasm.info.euler_characteristic, wasm.info.input_euler_characteristic);
  });
}

test('another count remeshes from the kept layout as a fresh remesh does, and the CLI agrees', () => {
  const file = sampleFile('genus2');
  wasmLayout(file, 10);
  tessera.remeshLayout({ quads: 1200 }, undefined);
  const kept = tessera.remeshLayout({ quads: 3000 }, undefined);
  assert.equal(kept.info.prepared_before, true);
  assert.equal(kept.info.seconds.prep < 1e-3, true, 'the prep was made again');
  tessera.layoutSolve(10, {}, undefined); // a new layout: the prep is dropped
  const fresh = tessera.remeshLayout({ quads: 3000 }, undefined);
  assert.equal(fresh.info.prepared_before, false);
  assert.deepEqual([...kept.positions], [...fresh.positions]);
  assert.deepEqual([...kept.quads], [...fresh.quads]);
  assertSameQuadMesh(kept, nativeRemesh(file, 10, 3000), 'genus2 at 3000 quads');
});

test('the quad mesh exports as OBJ (its quads) and GLB (0 validator errors, _PATCH)', async () => {
  wasmLayout(sampleFile('sphere'), 10);
  const { info } = tessera.remeshLayout({ quads: 400 }, undefined);
  const obj = readObj(Buffer.from(tessera.remeshExport('obj')).toString('latin1'));
  assert.equal(obj.faces.length, info.quads);
  assert.ok(obj.faces.every((f) => f.length === 4));
  assert.equal(obj.positions.length, info.vertices);
  const glb = tessera.remeshExport('glb');
  const report = await validator.validateBytes(glb);
  assert.equal(report.issues.numErrors, 0, JSON.stringify(report.issues.messages.slice(0, 3)));
  assert.match(Buffer.from(glb).toString('latin1'), /_PATCH/);
});

test('remesh calls out of order and bad options are clear errors', () => {
  const input = (pattern) => (e) => e.kind === 'input' && pattern.test(e.message);
  tessera.sampleMesh('sphere');
  assert.throws(() => tessera.remeshLayout({ quads: 100 }, undefined), input(/no quad layout/));
  assert.throws(() => tessera.remeshExport('obj'), input(/no quad mesh/));
  wasmLayout(sampleFile('sphere'), 10);
  assert.throws(() => tessera.remeshLayout({ quads: 0 }, undefined), input(/quads/));
  assert.throws(() => tessera.remeshLayout({ quads: 2.5 }, undefined), input(/quads/));
  assert.throws(() => tessera.remeshLayout({ quads: 100, lambda: 1 }, undefined), input(/one of/));
  assert.throws(() => tessera.remeshLayout({ lambda: -1 }, undefined), input(/lambda/));
  tessera.remeshLayout({ quads: 100 }, undefined);
  assert.throws(() => tessera.remeshExport('stl'), input(/obj, ply or glb/));
  tessera.layoutSolve(0, {}, undefined);
  assert.throws(() => tessera.remeshExport('obj'), input(/no quad mesh/), 'a new layout keeps a stale quad mesh');
});
