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
