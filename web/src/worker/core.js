// The geometry core (the wasm module) of one worker and what it reads once: the regular-map
// catalog and the realization manifest, and the last map it drew on a surface. The page's job
// worker (worker.js) and the gallery's thumbnail worker (thumbnail-worker.js) each hold their own.
import { DRAWN_STAGES, planStages, stagedProgress } from './stages.js';

// The wasm build is a static file (web/public/wasm), not a source module: an absolute URL keeps
// Vite's dev server from treating the import as one of its own. The static build has relative
// URLs (it is hosted under any path): there this worker is a file in assets/, beside wasm/.
const CORE_URL = new URL(import.meta.env.DEV ? '/wasm/tessera.mjs' : '../wasm/tessera.mjs', self.location.href).href;

let core = null; // Promise of the wasm module, created on first use, dropped after a trap
const catalogs = new WeakMap(); // wasm module -> its catalog rows, read into it once
const drawings = new WeakMap(); // wasm module -> the key (drawnKey) of the last map it drew
let manifest = null; // Promise of the shipped realizations: map name -> { target, others, pairing }

/** The wasm module, started on first use (a failure is an error of kind internal, retried next time). */
export function loadCore() {
  core ??= import(/* @vite-ignore */ CORE_URL)
    .then(({ default: createTessera }) => createTessera())
    .catch((cause) => {
      core = null;
      const error = new Error(
        `The geometry core (${CORE_URL}) could not be started: ${cause?.message ?? cause}. ` +
          'Build it with `npm start` (or scripts/build.sh) and reload the page.',
      );
      error.kind = 'internal';
      throw error;
    });
  return core;
}

/** Forgets the core (after a trap), so that the next job starts a fresh one. */
export function dropCore() {
  core = null;
}

// Draws a map on a target's surface in the core (which keeps it for its GLB): the manifest's
// pairing when it has one for this map and target, so that the page does not search.
export async function drawMap(map, on, progress, to) {
  progress('Starting the geometry core', 0);
  const module = await loadCore();
  progress('Finding the surface to draw on', 0.05);
  const [byName] = await Promise.all([realizations(), catalogOf(module)]);
  const entry = byName.get(String(map));
  const known = entry && (on === null || on === undefined || on === entry.target);
  const options = known ? { pairing: JSON.stringify(entry.pairing) } : { on: on ?? undefined };
  drawings.delete(module);
  // Shares of the bar as the stages' times for R3.1 on the tetrahedron.
  const plan = planStages(DRAWN_STAGES, [0.1, 3, 1, 2, 0.5, 1, 3], 0.1, to);
  const result = module.regmapDrawn(String(map), options, stagedProgress(plan, progress));
  drawings.set(module, drawnKey(map, on));
  if (known) result.others = entry.others;
  return result;
}

const drawnKey = (map, on) => JSON.stringify([String(map), on ?? null]);

/** Whether the core's last drawing is of `map` on `on` (null: the best target). */
export const hasDrawn = (module, map, on) => drawings.get(module) === drawnKey(map, on);

// The shipped manifest of `tessera regmap realize`, bundled as text (a chunk of its own).
export function realizations() {
  manifest ??= import('../../../data/regmaps/realizations.json?raw').then(({ default: text }) => {
    const byName = new Map();
    for (const m of JSON.parse(text).maps ?? []) byName.set(m.source, m);
    return byName;
  });
  return manifest;
}

// The shipped catalog, bundled with the page as text (a chunk of its own, loaded on first use) and
// read by the core, which also needs it to resolve map names.
export async function catalogOf(module) {
  if (!catalogs.has(module)) catalogs.set(module, module.regmapLoadCatalog(await catalogText()));
  return catalogs.get(module);
}

let catalogChunk = null;
export const catalogText = () => {
  catalogChunk ??= import('../../../data/regmaps/catalog_g2-101.tsv?raw').then(
    ({ default: text }) => text,
    (error) => {
      catalogChunk = null;
      throw error;
    },
  );
  return catalogChunk;
};
