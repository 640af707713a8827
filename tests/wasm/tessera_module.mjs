// Loads the wasm build (web/public/wasm/tessera.mjs) under node for the tests of the module.
// Emscripten 3.1.6's ES6 output reads `require` and `__dirname` when it runs in node; we provide
// both, and pass the binary directly (node 20's fetch cannot read file URLs).
import fs from 'node:fs';
import path from 'node:path';
import { createRequire } from 'node:module';
import { fileURLToPath } from 'node:url';

const here = path.dirname(fileURLToPath(import.meta.url));
export const wasmDir = path.resolve(here, '../../web/public/wasm');

export async function loadTessera() {
  globalThis.require ??= createRequire(import.meta.url);
  globalThis.__dirname ??= wasmDir;
  const { default: createTessera } = await import(path.join(wasmDir, 'tessera.mjs'));
  const wasmBinary = fs.readFileSync(path.join(wasmDir, 'tessera.wasm'));
  return createTessera({ wasmBinary });
}

// A sample of the module (a mesh the core builds in code) written as <dir>/<name>.obj, so that the
// native CLI reads the very same mesh.
export function writeSampleObj(tessera, name, dir) {
  const mesh = tessera.sampleMesh(name);
  const lines = [];
  for (let i = 0; i < mesh.positions.length; i += 3) lines.push(`v ${mesh.positions[i]} ${mesh.positions[i + 1]} ${mesh.positions[i + 2]}`);
  for (let i = 0; i < mesh.triangles.length; i += 3) lines.push(`f ${mesh.triangles[i] + 1} ${mesh.triangles[i + 1] + 1} ${mesh.triangles[i + 2] + 1}`);
  const file = path.join(dir, `${name}.obj`);
  fs.writeFileSync(file, lines.join('\n'));
  return file;
}
