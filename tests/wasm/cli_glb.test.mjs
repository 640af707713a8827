// GLB files written by the native CLI (`tessera convert`) pass gltf-validator with 0 errors: a plain
// mesh (shared vertices, smooth normals) and one with an integer face property (vertices split per
// face, the property as the custom attribute _PATCH). Runs the CLI of build/native.
import test from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import validator from 'gltf-validator';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
const cli = path.join(root, 'build/native/cli/tessera');
const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'tessera-cli-glb-'));

// A torus of n x m quads, as OBJ text and as ascii PLY with a per-face "patch" property.
function torusGrid(n, m) {
  const vertices = [];
  const faces = [];
  for (let i = 0; i < n; ++i) {
    for (let j = 0; j < m; ++j) {
      const u = (2 * Math.PI * i) / n;
      const v = (2 * Math.PI * j) / m;
      const r = 1 + 0.3 * Math.cos(v);
      vertices.push([r * Math.cos(u), r * Math.sin(u), 0.3 * Math.sin(v)]);
    }
  }
  const at = (i, j) => (i % n) * m + (j % m);
  for (let i = 0; i < n; ++i) for (let j = 0; j < m; ++j) faces.push([at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)]);
  return { vertices, faces };
}

async function validate(file) {
  const report = await validator.validateBytes(new Uint8Array(fs.readFileSync(file)));
  return report.issues;
}

test('tessera convert writes a GLB with 0 validator errors', async () => {
  const { vertices, faces } = torusGrid(24, 12);
  const obj = path.join(dir, 'torus.obj');
  fs.writeFileSync(obj, [...vertices.map((p) => `v ${p.join(' ')}`), ...faces.map((f) => `f ${f.map((v) => v + 1).join(' ')}`)].join('\n'));
  const glb = path.join(dir, 'torus.glb');
  execFileSync(cli, ['convert', obj, glb]);
  const issues = await validate(glb);
  assert.equal(issues.numErrors, 0, JSON.stringify(issues.messages.slice(0, 5)));
});

test('face properties become a _PATCH attribute that gltf-validator accepts', async () => {
  const { vertices, faces } = torusGrid(16, 8);
  const ply = path.join(dir, 'patches.ply');
  const header = ['ply', 'format ascii 1.0', `element vertex ${vertices.length}`, 'property double x', 'property double y',
    'property double z', `element face ${faces.length}`, 'property list uchar int vertex_indices', 'property int patch', 'end_header'];
  fs.writeFileSync(ply, [...header, ...vertices.map((p) => p.join(' ')), ...faces.map((f, k) => `4 ${f.join(' ')} ${k % 7}`)].join('\n') + '\n');
  const glb = path.join(dir, 'patches.glb');
  execFileSync(cli, ['convert', ply, glb]);
  const issues = await validate(glb);
  assert.equal(issues.numErrors, 0, JSON.stringify(issues.messages.slice(0, 5)));
  // The JSON chunk names the custom attribute.
  const bytes = fs.readFileSync(glb);
  const jsonLength = bytes.readUInt32LE(12);
  const json = JSON.parse(bytes.subarray(20, 20 + jsonLength).toString('utf8'));
  assert.ok('_PATCH' in json.meshes[0].primitives[0].attributes);
});
