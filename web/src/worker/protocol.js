/**
 * The one message protocol between the page and the compute worker.
 *
 * Page -> worker, one message per request:
 *   { id, command, payload }
 *     id       a number, unique per client
 *     command  a name from COMMANDS
 *     payload  the command's argument (plain data, typed arrays, File objects)
 *
 * Worker -> page, any number of progress events, then exactly one result or error:
 *   { id, type: 'progress', stage, fraction }   stage: a short text; fraction: 0..1 over the whole job
 *   { id, type: 'result', payload }             typed arrays in payload are transferred, not copied
 *   { id, type: 'error', kind, message }        kind: the core's error kind ('parse', 'input',
 *                                               'topology', 'geometry', 'limit', 'internal') or one of ours below
 *
 * Cancellation is not a message: the page terminates the worker and starts a fresh one (a stage
 * inside the wasm module cannot be interrupted any other way), and every pending request is
 * rejected with kind 'cancelled'. A worker that dies (script error, wasm trap) is replaced the same
 * way and its pending requests are rejected with kind 'crash'.
 */

export const COMMANDS = Object.freeze({
  sampleNames: 'sampleNames', // payload: none -> { names: string[] }
  // The page numbers the meshes it asks for (meshId). The worker's core keeps the last mesh it
  // built for the stages below; a fresh worker (after Cancel or a crash) rebuilds it from `mesh`.
  sampleMesh: 'sampleMesh', // payload: { name, meshId } -> mesh (see worker.js)
  loadMesh: 'loadMesh', // payload: { file: File, meshId } -> mesh
  // Quad layout stages of the mesh shown. mesh: { id, sample } or { id, file } as it was loaded;
  // field: { align: 'smooth'|'curvature', sharp: degrees }; h: the sizing, relative to the bounding box.
  crossField: 'crossField', // payload: { mesh, field } -> { info, seconds, glyphs, singularities: { positions, valences }, markerRadius }
  seamlessParam: 'seamlessParam', // payload: { mesh, field, h } -> { info, corners: { positions, normals, uv } }
  // The quad layout of the mesh shown at alpha. The worker keeps the graph of the ports of
  // { mesh, field, h }: a new alpha only solves P1 again (resolved: true). info: the core's layout
  // figures (`tessera layout --json` plus problem_count, patches_not_quads); graph: the graph's;
  // solveSeconds: the re-solve in the worker (P1, arcs, patches, check); surface: the refined mesh
  // coloured by patch { positions, normals, colors, triangles }; arcs: line segments (Float32Array).
  // presolve: the slider's positions (alphas), solved ahead while the worker is idle (presolve.js).
  quadLayout: 'quadLayout', // payload: { mesh, field, h, alpha, presolve? } -> { info, graph, resolved, solveSeconds, surface, arcs, singularities: { positions, valences }, markerRadius }
  // The layout of { mesh, field, h, alpha } as a file ('glb' or 'ply'), computed again if the core
  // holds another one.
  layoutExport: 'layoutExport', // payload: { mesh, field, h, alpha, format } -> { bytes }
  // The quad mesh (thesis Ch. 8) of the layout of { mesh, field, h, alpha } (laid out again if the
  // core holds another one; it must be valid) for a target quad count. The worker keeps what the
  // count does not change: another count only solves the integer lengths again and places the
  // points. info: `tessera remesh --json`'s figures plus prepared_before; remeshSeconds: the
  // remesh in the worker; surface: the quads coloured by the layout's patches { positions,
  // normals, colors, triangles }; edges: the quads' edges, each once (Float32Array, 6 per edge).
  quadMesh: 'quadMesh', // payload: { mesh, field, h, alpha, quads } -> { info, remeshSeconds, surface, edges }
  // That quad mesh as a file ('obj' or 'glb', with _PATCH per face as `tessera remesh -o`).
  quadMeshExport: 'quadMeshExport', // payload: { mesh, field, h, alpha, quads, format } -> { bytes }
  exportGlb: 'exportGlb', // payload: { positions, triangles, faceIds?, colors?, extras? } -> { bytes }
  // Regular maps. A map is a catalog name (R3.1, R3.1' for the dual) or a presentation in Conder's
  // text format; its info is { name, p, q, order, vertices, edges, faces, genus, orientable, euler,
  // petrie, seconds }.
  regmapCatalog: 'regmapCatalog', // payload: none -> { rows: [{ name, genus, p, q, petrie, order, vertices, edges, faces }] }
  regmapTiling: 'regmapTiling', // payload: { map } -> { info, svg, polygon: { triangles, boundaryPairs, euler, boundaryCycles } }
  // The regular surface of a map (tubified edge graph). options: { base: 'auto'|'platonic'|'relax',
  // tubeRadius (0: automatic), smoothness (quads across a quarter tube) }; stats: the core's figures
  // (genus, euler_characteristic, quarter_tubes, closed, oriented, relations_hold, ...); surface: the
  // mesh coloured by quarter tube { positions, normals, colors, triangles } (see surface-display.js).
  regmapSurface: 'regmapSurface', // payload: { map, options } -> { info, stats, surface }
  // The surface of { map, options } as GLB; a worker whose core holds another surface builds it again.
  regmapSurfaceGlb: 'regmapSurfaceGlb', // payload: { map, options } -> { bytes }
  // The map drawn on the regular surface of a target of its genus (thesis Sec. 9.5-9.6): the
  // shipped manifest's realization (data/regmaps/realizations.json) when `on` is null or its
  // target, else a search over `on` (or every target). drawn: the core's figures (target, V, E, F
  // found, faces_are_disks, covers_once, closed, oriented, genus, pairing, seconds, ...); others:
  // the other targets that work; surface: coloured by the map's faces; bare: the same mesh
  // coloured by quarter tube; edges: the map's edges (Float32Array, 6 per segment).
  regmapDrawn: 'regmapDrawn', // payload: { map, on } -> { info, drawn, others, surface, bare, edges }
  regmapDrawnExport: 'regmapDrawnExport', // payload: { map, on, format, print: { sizeMm, wallMm } } -> { bytes, print }
});

/** Error kinds that the page adds to the core's. */
export const PAGE_ERROR_KINDS = Object.freeze({
  cancelled: 'cancelled', // the user cancelled the job
  crash: 'crash', // the worker or the wasm module died; a fresh one took its place
  unsupported: 'unsupported', // the page cannot take this input (file type, several files)
});

export const progressEvent = (id, stage, fraction) => ({ id, type: 'progress', stage, fraction });
export const resultEvent = (id, payload) => ({ id, type: 'result', payload });
export const errorEvent = (id, kind, message) => ({ id, type: 'error', kind, message });

/** An Error with the protocol's `kind`, as the client rejects a request with. */
export function jobError(kind, message) {
  const error = new Error(message);
  error.kind = kind;
  return error;
}

/**
 * Makes every typed array in `payload` own its buffer (copying views into a larger buffer such as
 * the wasm heap, which must never be transferred) and returns the buffers to transfer.
 */
export function ownedBuffers(payload) {
  const buffers = new Set();
  const visit = (value) => {
    if (ArrayBuffer.isView(value)) return own(value, buffers);
    if (value === null || typeof value !== 'object') return value;
    if (Array.isArray(value)) return value.map(visit);
    if (Object.getPrototypeOf(value) !== Object.prototype) return value;
    return Object.fromEntries(Object.entries(value).map(([key, v]) => [key, visit(v)]));
  };
  const owned = visit(payload);
  return { payload: owned, transfer: [...buffers] };
}

function own(view, buffers) {
  const whole = view.byteOffset === 0 && view.byteLength === view.buffer.byteLength;
  const owned = whole && view.buffer instanceof ArrayBuffer ? view : view.slice();
  buffers.add(owned.buffer);
  return owned;
}
