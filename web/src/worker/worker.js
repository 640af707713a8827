// The compute worker: runs the wasm core off the page's thread and answers the requests of
// protocol.js. No algorithm lives here: it calls the core and prepares data for the viewer.
import { COMMANDS, PAGE_ERROR_KINDS, errorEvent, ownedBuffers, progressEvent, resultEvent } from './protocol.js';
import { polygonEdges, vertexNormals } from './display.js';
import { cornerArrays, crossGlyphs, markerRadius, vertexPoints } from './field-display.js';
import { tiledSurface } from './surface-display.js';
import { catalogOf, catalogText, drawMap, dropCore, hasDrawn, loadCore, realizations } from './core.js';
import { quarterTubeColor } from '../viewer/palette.js';
import { arcSegments, patchSurface } from './layout-display.js';
import { quadEdges, quadSurface } from './quad-mesh-display.js';
import { MAX_PRESOLVE_SECONDS, presolveInTurn, presolveOrder } from './presolve.js';
import {
  FIELD_STAGES,
  GRAPH_STAGES,
  PARAM_STAGES,
  PRINT_STAGES,
  REMESH_STAGES,
  SOLVE_STAGES,
  SURFACE_STAGES,
  planStages,
  stagedProgress,
} from './stages.js';

const surfaces = new WeakMap(); // wasm module -> the key (surfaceKey) of the last surface it built
// The mesh the module's session holds (the core keeps the last mesh it built), with the arrays the
// field view is drawn from: { module, id, positions, triangles, normals, fieldKey, paramKey,
// graphKey, graph, layoutKey }, where id is the page's number of the mesh, and the keys name the
// options of the session's cross field, parameterization, graph of the ports (graph: its figures)
// and layout (the graph's key and alpha).
let session = null;
// presolveAround(): the running queue's number (a request stops it by taking the next), and what to
// start once the current request is answered.
let presolveToken = 0;
let afterReply = null;

const handlers = {
  async [COMMANDS.sampleNames]() {
    const module = await loadCore();
    return { names: [...module.sampleNames()] };
  },

  async [COMMANDS.sampleMesh]({ name, meshId }, progress) {
    progress('Starting the geometry core', 0);
    const module = await loadCore();
    progress(`Building the sample "${name}"`, 0.2);
    return remember(module, meshId, meshForViewer(module.sampleMesh(name), progress));
  },

  async [COMMANDS.loadMesh]({ file, meshId }, progress) {
    progress('Starting the geometry core', 0);
    const module = await loadCore();
    progress(`Reading ${file.name}`, 0.1);
    const bytes = new Uint8Array(await file.arrayBuffer());
    progress('Building the mesh', 0.3);
    return remember(module, meshId, meshForViewer(module.loadMesh(bytes, file.name), progress));
  },

  async [COMMANDS.crossField]({ mesh, field }, progress) {
    const shown = await sessionOf(mesh, progress);
    const plan = planStages(FIELD_STAGES, [1], 0.1, 0.9);
    const started = performance.now();
    const result = designField(shown, field, stagedProgress(plan, progress));
    const seconds = (performance.now() - started) / 1000;
    progress('Preparing the view', 0.9);
    const { positions, triangles } = shown;
    return {
      info: result.info,
      seconds,
      glyphs: crossGlyphs(positions, triangles, result.directions),
      singularities: {
        positions: vertexPoints(positions, result.singularityVertices),
        valences: result.singularityValences,
      },
      markerRadius: sessionMarkerRadius(shown),
    };
  },

  async [COMMANDS.seamlessParam]({ mesh, field, h }, progress) {
    const shown = await sessionOf(mesh, progress);
    // Shares of the bar as the stages' times on fertility (28k triangles).
    const onProgress = stagedProgress(planStages(PARAM_STAGES, [3, 0.2, 0.5, 1, 2.5], 0.1, 0.95), progress);
    if (shown.fieldKey !== fieldKey(field)) designField(shown, field, onProgress);
    const result = computeParam(shown, field, h, onProgress);
    progress('Preparing the view', 0.95);
    const corners = cornerArrays(shown.positions, shown.normals, shown.triangles);
    return { info: result.info, corners: { ...corners, uv: result.uv } };
  },

  async [COMMANDS.quadLayout]({ mesh, field, h, alpha, presolve }, progress) {
    const shown = await sessionOf(mesh, progress);
    const { result, resolved, solveSeconds } = layoutOf(shown, { field, h, alpha }, progress, 0.95);
    progress('Preparing the view', 0.95);
    if (solveSeconds <= MAX_PRESOLVE_SECONDS) afterReply = () => presolveAround(shown, alpha, presolve);
    return {
      info: result.info,
      graph: shown.graph,
      resolved,
      solveSeconds,
      surface: patchSurface(result.refined, result.patchColors),
      arcs: arcSegments(result.arcs.points, result.arcs.offsets),
      singularities: result.singularities,
      markerRadius: sessionMarkerRadius(shown),
    };
  },

  async [COMMANDS.layoutExport]({ mesh, field, h, alpha, format }, progress) {
    const shown = await sessionOf(mesh, progress);
    if (shown.layoutKey !== layoutKey(field, h, alpha)) layoutOf(shown, { field, h, alpha }, progress, 0.8);
    progress(`Writing the ${format === 'ply' ? 'PLY' : 'GLB'} file`, 0.8);
    return { bytes: format === 'ply' ? shown.module.layoutPly() : shown.module.layoutGlb() };
  },

  async [COMMANDS.quadMesh]({ mesh, field, h, alpha, quads }, progress) {
    const shown = await sessionOf(mesh, progress);
    const { result, remeshSeconds } = quadMeshOf(shown, { field, h, alpha, quads }, progress, 0.9);
    progress('Preparing the view', 0.9);
    return {
      info: result.info,
      remeshSeconds,
      surface: quadSurface(result, result.patchColors),
      edges: quadEdges(result.positions, result.quads),
    };
  },

  async [COMMANDS.quadMeshExport]({ mesh, field, h, alpha, quads, format }, progress) {
    const shown = await sessionOf(mesh, progress);
    if (shown.quadKey !== quadKey(field, h, alpha, quads)) quadMeshOf(shown, { field, h, alpha, quads }, progress, 0.8);
    progress(`Writing the ${String(format).toUpperCase()} file`, 0.8);
    return { bytes: shown.module.remeshExport(String(format)) };
  },

  async [COMMANDS.exportGlb](payload, progress) {
    progress('Writing the GLB file', 0);
    const module = await loadCore();
    return { bytes: module.exportGlb(payload) };
  },

  async [COMMANDS.regmapCatalog](_, progress) {
    progress('Starting the geometry core', 0);
    // The catalog's text and the manifest (which the drawn view, the mode's default, reads next)
    // load while the core starts.
    realizations().catch(() => {});
    const [module] = await Promise.all([loadCore(), catalogText()]);
    progress('Reading the catalog of regular maps', 0.3);
    return { rows: await catalogOf(module) };
  },

  async [COMMANDS.regmapTiling]({ map }, progress) {
    progress('Starting the geometry core', 0);
    const module = await loadCore();
    await catalogOf(module);
    progress('Enumerating the group and drawing its tiling', 0.3);
    return module.regmapTiling(String(map));
  },

  async [COMMANDS.regmapSurface]({ map, options }, progress) {
    const result = await buildSurface(map, options, progress, 0.9);
    progress('Preparing the view', 0.9);
    const { info, stats } = result;
    return { info, stats, surface: tiledSurface(result) };
  },

  async [COMMANDS.regmapDrawn]({ map, on }, progress) {
    const result = await drawMap(map, on, progress, 0.85);
    progress('Preparing the view', 0.85);
    const { info, drawn, others, positions, triangles, triangleFace, face, orbit, tile, edges } = result;
    // The faces coloured one by one, and (recolored) by their orbit under the surface's rotations.
    const orbitOfFace = new Int32Array(face.reduce((most, f) => Math.max(most, f + 1), 0));
    face.forEach((f, i) => (orbitOfFace[f] = orbit[i]));
    return {
      info,
      drawn,
      others,
      surface: tiledSurface({ positions, triangles, triangleFace, tile: face }, quarterTubeColor, (f) => quarterTubeColor(orbitOfFace[f])),
      bare: tiledSurface({ positions, triangles, triangleFace, tile }),
      edges,
    };
  },

  async [COMMANDS.regmapDrawnExport]({ map, on, format, print }, progress) {
    progress('Starting the geometry core', 0);
    const module = await loadCore();
    if (!hasDrawn(module, map, on)) await drawMap(map, on, progress, 0.5);
    progress(`Writing the ${String(format).toUpperCase()} file`, 0.5);
    const plan = planStages(PRINT_STAGES, [1, 1], 0.5, 1);
    return module.regmapDrawnExport(String(format), print ?? {}, stagedProgress(plan, progress));
  },

  async [COMMANDS.regmapSurfaceGlb]({ map, options }, progress) {
    progress('Starting the geometry core', 0);
    const module = await loadCore();
    if (surfaces.get(module) !== surfaceKey(map, options)) await buildSurface(map, options, progress, 0.8);
    progress('Writing the GLB file', 0.8);
    return { bytes: module.regmapSurfaceGlb() };
  },
};

// Builds the surface of a map in the core, its stages on the bar up to `to`, and returns the core's
// result. The core keeps the surface for its GLB.
async function buildSurface(map, options, progress, to) {
  progress('Starting the geometry core', 0);
  const module = await loadCore();
  await catalogOf(module);
  progress('Enumerating the group', 0.02);
  surfaces.delete(module);
  // Shares of the bar as the stages' times for R29.1 and R3.1 (the relaxation dominates).
  const plan = planStages(SURFACE_STAGES, [0.1, 6, 1, 1], 0.03, to);
  const { base, tubeRadius, smoothness } = options;
  const result = module.regmapSurface(String(map), { base, tubeRadius, smoothness }, stagedProgress(plan, progress));
  surfaces.set(module, surfaceKey(map, options));
  return result;
}

const surfaceKey = (map, { base, tubeRadius, smoothness }) => JSON.stringify([String(map), base, tubeRadius, smoothness]);

// The core's MeshResult plus what the viewer draws: vertex normals and the polygons' edges.
function meshForViewer(mesh, progress) {
  progress('Preparing the view', 0.8);
  const { name, info, positions, triangles, triangleFace } = mesh;
  return {
    name,
    info,
    positions,
    triangles,
    triangleFace,
    normals: vertexNormals(positions, triangles),
    edges: polygonEdges(triangles, triangleFace),
  };
}

// Keeps copies of what the field view needs of a mesh the session now holds (the mesh itself goes
// to the page, its arrays transferred).
function remember(module, id, mesh) {
  const { positions, triangles, normals } = mesh;
  session = {
    module,
    id,
    positions: positions.slice(),
    triangles: triangles.slice(),
    normals: normals.slice(),
    markerRadius: null, // sessionMarkerRadius()
    fieldKey: null,
    paramKey: null,
    graphKey: null,
    graph: null,
    layoutKey: null,
    quadKey: null,
  };
  return mesh;
}

// The size of the singularity markers on the session's mesh: a pass over its triangles, made the
// first time a view needs it and kept (it was made at every re-solve).
function sessionMarkerRadius(shown) {
  shown.markerRadius ??= markerRadius(shown.positions, shown.triangles);
  return shown.markerRadius;
}

// The session of the page's mesh { id, sample | file }: the current one, or, in a fresh worker or
// core, the mesh built again from where it came from.
async function sessionOf(mesh, progress) {
  progress('Starting the geometry core', 0);
  const module = await loadCore();
  if (session?.module === module && session.id === mesh.id) return session;
  progress('Building the mesh again in a fresh core', 0.02);
  const built = mesh.file
    ? module.loadMesh(new Uint8Array(await mesh.file.arrayBuffer()), mesh.file.name)
    : module.sampleMesh(mesh.sample);
  const { positions, triangles } = built;
  remember(module, mesh.id, { positions, triangles, normals: vertexNormals(positions, triangles) });
  return session;
}

// The layout of the session's mesh at alpha: the field, parameterization and graph of the ports
// computed unless the session holds them for these options, then P1 and the layout. Progress up to
// `to`. Returns { result (the core's), resolved (the graph was kept), solveSeconds }.
function layoutOf(shown, { field, h, alpha }, progress, to) {
  const key = paramKey(field, h);
  const resolved = shown.graphKey === key;
  shown.layoutKey = null;
  shown.quadKey = null;
  let from = 0.05;
  if (!resolved) {
    // Shares of the bar as the stages' times on fertility (28k triangles).
    const stages = [...PARAM_STAGES, ...GRAPH_STAGES];
    const onProgress = stagedProgress(planStages(stages, [3, 0.2, 0.5, 1, 2.5, 4, 1, 1], 0.05, 0.8), progress);
    if (shown.fieldKey !== fieldKey(field)) designField(shown, field, onProgress);
    if (shown.paramKey !== key) computeParam(shown, field, h, onProgress);
    shown.graph = shown.module.layoutGraph({}, onProgress).info;
    shown.graphKey = key;
    from = 0.8;
  }
  const onProgress = stagedProgress(planStages(SOLVE_STAGES, [1, 1], from, to), progress);
  const started = performance.now();
  const result = shown.module.layoutSolve(alpha, {}, onProgress);
  const solveSeconds = (performance.now() - started) / 1000;
  shown.layoutKey = layoutKey(field, h, alpha);
  return { result, resolved, solveSeconds };
}

// The quad mesh of the session's layout at { field, h, alpha } for a target count: the layout
// computed again unless the session holds it, then the remesh (which the core answers from what it
// keeps of the layout). Progress up to `to`. Returns { result (the core's), remeshSeconds }.
function quadMeshOf(shown, { field, h, alpha, quads }, progress, to) {
  let from = 0.05;
  if (shown.layoutKey !== layoutKey(field, h, alpha)) {
    layoutOf(shown, { field, h, alpha }, progress, 0.6);
    from = 0.6;
  }
  shown.quadKey = null;
  const onProgress = stagedProgress(planStages(REMESH_STAGES, [2, 2, 1], from, to), progress);
  const started = performance.now();
  const result = shown.module.remeshLayout({ quads: Number(quads) }, onProgress);
  const remeshSeconds = (performance.now() - started) / 1000;
  shown.quadKey = quadKey(field, h, alpha, quads);
  return { result, remeshSeconds };
}

const quadKey = (field, h, alpha, quads) => `${layoutKey(field, h, alpha)} ${quads}`;

// The slider's other positions solved ahead, nearest to alpha first, while no request comes in
// (presolve.js); any request stops it, a layout starts it again around its alpha. Each presolve
// stops at MAX_PRESOLVE_SECONDS, so that a request waits no longer than that for it.
function presolveAround(shown, alpha, alphas) {
  const token = ++presolveToken;
  const graphKey = shown.graphKey;
  const stillWanted = () => token === presolveToken && session === shown && shown.graphKey === graphKey;
  const options = { maxSeconds: MAX_PRESOLVE_SECONDS };
  presolveInTurn(presolveOrder(alphas, alpha), (a) => shown.module.layoutPresolve(a, options), stillWanted);
}

// The parameterization of the session's field with unit h; it replaces the graph and the layout.
function computeParam(shown, field, h, onProgress) {
  Object.assign(shown, { paramKey: null, graphKey: null, graph: null, layoutKey: null, quadKey: null });
  const result = shown.module.seamlessParam({ h }, onProgress);
  shown.paramKey = paramKey(field, h);
  return result;
}

const paramKey = (field, h) => `${fieldKey(field)} ${h}`;
const layoutKey = (field, h, alpha) => `${paramKey(field, h)} ${alpha}`;

function designField(shown, { align, sharp }, onProgress) {
  Object.assign(shown, { paramKey: null, graphKey: null, graph: null, layoutKey: null, quadKey: null });
  shown.fieldKey = null;
  const result = shown.module.crossField({ align, sharp }, onProgress);
  shown.fieldKey = fieldKey({ align, sharp });
  return result;
}

const fieldKey = ({ align, sharp }) => `${align} ${sharp}`;

// A trap or an error without a kind may leave the wasm module in a broken state: drop it, so that
// the next request starts a fresh one.
function describeFailure(error) {
  if (typeof error?.kind === 'string') return { kind: error.kind, message: error.message };
  dropCore();
  const detail = error?.message ?? String(error);
  if (error instanceof WebAssembly.RuntimeError) {
    return {
      kind: PAGE_ERROR_KINDS.crash,
      message: `The geometry core stopped (${detail}). A fresh one starts with the next job: try again.`,
    };
  }
  return { kind: 'internal', message: `Internal error: ${detail}` };
}

// The core starts loading with the worker: the first job of every mode needs it (a failure is
// reported by that job, which tries again).
loadCore().catch(() => {});

self.onmessage = async ({ data: { id, command, payload } }) => {
  const progress = (stage, fraction) => self.postMessage(progressEvent(id, stage, fraction));
  presolveToken += 1;
  afterReply = null;
  try {
    if (!Object.hasOwn(handlers, command)) throw new Error(`unknown command "${command}"`);
    const owned = ownedBuffers(await handlers[command](payload ?? {}, progress));
    self.postMessage(resultEvent(id, owned.payload), owned.transfer);
    afterReply?.();
  } catch (error) {
    const { kind, message } = describeFailure(error);
    self.postMessage(errorEvent(id, kind, message));
  }
  afterReply = null;
};
