// Cross field and seamless parameterization in the wasm module: Poincare-Hopf and seamlessness on
// the samples, the same singularities as the native CLI on the same file, clear errors.
import test from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { loadTessera } from './tessera_module.mjs';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
const cli = path.join(root, 'build/native/cli/tessera');
const tessera = await loadTessera();

test('fields on the samples satisfy Poincare-Hopf; progress is reported', () => {
  for (const name of ['sphere', 'torus', 'genus2', 'part', 'annulus']) {
    const mesh = tessera.sampleMesh(name);
    const stages = [];
    const field = tessera.crossField({}, (stage, fraction) => stages.push([stage, fraction]));
    assert.equal(field.info.index_sum, mesh.info.euler_characteristic, name);
    const indexSum = field.info.singularities.reduce((sum, s) => sum + s.index, 0);
    assert.ok(Math.abs(indexSum - mesh.info.euler_characteristic) < 1e-9, name);
    assert.equal(field.directions.length, 3 * (mesh.triangles.length / 3));
    assert.equal(field.singularityVertices.length, field.info.singularities.length);
    assert.ok(stages.length > 0, `${name}: progress`);
  }
  tessera.sampleMesh('torus');
  assert.equal(tessera.crossField({}, undefined).info.singularities.length, 0, 'smoothest field of a torus');
});

test('the seamless parameterization of the genus-2 sample is seamless and unflipped', () => {
  const mesh = tessera.sampleMesh('genus2');
  const param = tessera.seamlessParam({}, undefined);
  assert.equal(param.uv.length, 2 * mesh.triangles.length);
  assert.ok(param.info.max_seam_error < 1e-8);
  assert.equal(param.info.flipped_outside_singular_rings, 0);
  assert.ok(param.uv.every(Number.isFinite));
});

test('native and wasm find the same singularities on the same file', () => {
  const part = tessera.sampleMesh('part');
  const lines = [];
  for (let i = 0; i < part.positions.length; i += 3) lines.push(`v ${part.positions[i]} ${part.positions[i + 1]} ${part.positions[i + 2]}`);
  for (let i = 0; i < part.triangles.length; i += 3) lines.push(`f ${part.triangles[i] + 1} ${part.triangles[i + 1] + 1} ${part.triangles[i + 2] + 1}`);
  const file = path.join(fs.mkdtempSync(path.join(os.tmpdir(), 'tessera-field-')), 'part.obj');
  fs.writeFileSync(file, lines.join('\n'));
  tessera.loadMesh(fs.readFileSync(file), 'part.obj');
  const wasm = tessera.crossField({ sharp: 35 }, undefined).info;
  const native = JSON.parse(execFileSync(cli, ['field', file, '--sharp', '35', '--json'], { encoding: 'utf8' }));
  assert.deepEqual(wasm.singularities, native.singularities);
  assert.equal(wasm.index_sum, native.index_sum);
});

test('bad options are clear errors', () => {
  tessera.sampleMesh('sphere');
  assert.throws(() => tessera.crossField({ align: 'sideways' }, undefined), (e) => e.kind === 'input' && /align/.test(e.message));
  assert.throws(() => tessera.seamlessParam({ h: -1 }, undefined), (e) => e.kind === 'input' && /'h'/.test(e.message));
  assert.throws(() => tessera.seamlessParam({ h: 'big' }, undefined), (e) => e.kind === 'input');
});
