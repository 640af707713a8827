// The wasm module under node: the mesh figures agree with what the native core computes for the
// same generated meshes, and bad input becomes a JS Error with the core's message and kind.
import test from 'node:test';
import assert from 'node:assert/strict';
import { loadTessera } from './tessera_module.mjs';

const tessera = await loadTessera();

test('the samples are valid meshes with the right topology', () => {
  const expected = {
    sphere: { genus: 0, boundary_loops: 0, euler_characteristic: 2 },
    torus: { genus: 1, boundary_loops: 0, euler_characteristic: 0 },
    genus2: { genus: 2, boundary_loops: 0, euler_characteristic: -2 },
    part: { genus: 2, boundary_loops: 0, euler_characteristic: -2 },
    annulus: { genus: 0, boundary_loops: 2, euler_characteristic: 0 },
  };
  assert.deepEqual([...tessera.sampleNames()].sort(), Object.keys(expected).sort());
  for (const [name, figures] of Object.entries(expected)) {
    const mesh = tessera.sampleMesh(name);
    for (const [key, value] of Object.entries(figures)) assert.equal(mesh.info[key], value, `${name}.${key}`);
    assert.equal(mesh.positions.length, 3 * mesh.info.vertices);
    assert.equal(mesh.triangleFace.length * 3, mesh.triangles.length);
    assert.ok(mesh.triangles.every((v) => v < mesh.info.vertices));
  }
});

test('info of an OBJ with polygons and negative indices', () => {
  // A cube of six quads, faces written with negative (relative) indices.
  const obj = [
    'v 0 0 0', 'v 1 0 0', 'v 1 1 0', 'v 0 1 0', 'v 0 0 1', 'v 1 0 1', 'v 1 1 1', 'v 0 1 1',
    'f -8 -5 -6 -7', 'f -4 -3 -2 -1', 'f -8 -7 -3 -4', 'f -7 -6 -2 -3', 'f -6 -5 -1 -2', 'f -5 -8 -4 -1',
  ].join('\n');
  const mesh = tessera.loadMesh(new TextEncoder().encode(obj), 'cube.obj');
  assert.equal(mesh.info.vertices, 8);
  assert.equal(mesh.info.faces, 6);
  assert.equal(mesh.info.edges, 12);
  assert.equal(mesh.info.genus, 0);
  assert.deepEqual(mesh.info.face_sizes, { 4: 6 });
  assert.equal(mesh.triangles.length, 6 * 2 * 3);
  assert.ok(Math.abs(mesh.info.bbox_diagonal - Math.sqrt(3)) < 1e-12);
});

test('bad input is a JS Error with the message and kind of the core', () => {
  const bad = new TextEncoder().encode('v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n');
  assert.throws(() => tessera.loadMesh(bad, 'bad.obj'), (e) => {
    assert.ok(e instanceof Error);
    assert.equal(e.kind, 'parse');
    assert.match(e.message, /bad\.obj:4/);
    return true;
  });
  assert.throws(() => tessera.loadMesh(new Uint8Array(0), 'empty.stl'), (e) => e.kind === 'parse');
  assert.throws(() => tessera.sampleMesh('<img src=x>'), (e) => e.kind === 'input');
});

test('a GLB written by the module has the GLB header and reads back', () => {
  const torus = tessera.sampleMesh('torus');
  const glb = tessera.exportGlb({
    positions: torus.positions,
    triangles: torus.triangles,
    faceIds: torus.triangleFace,
    extras: { source: 'torus' },
  });
  assert.ok(glb instanceof Uint8Array);
  assert.equal(new TextDecoder().decode(glb.subarray(0, 4)), 'glTF');
  const back = tessera.loadMesh(glb, 'torus.glb');
  assert.equal(back.info.faces, torus.info.faces);
  assert.equal(back.info.genus, 1);
});
