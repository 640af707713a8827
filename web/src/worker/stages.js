// The core reports progress as (stage, fraction within that stage); the page shows one bar over
// the whole job with a label per stage. A plan says where each stage of a job lies on the bar.

/** The core's stages of the cross field and the seamless parameterization, in order. */
export const FIELD_STAGES = Object.freeze([['field', 'Designing the cross field']]);
export const PARAM_STAGES = Object.freeze([
  ['field', 'Designing the cross field'],
  ['cut graph', 'Cutting the surface open along the cut graph'],
  ['assembly', 'Assembling the Poisson system'],
  ['solve', 'Solving the Poisson system'],
  ['injectivity', 'Injectivity constraints near singularities (GLPK)'],
]);
// The core's stages of the graph of the ports (after the parameterization) and of the layout at
// one alpha, in order; the solver reports under its own name.
export const GRAPH_STAGES = Object.freeze([
  ['separatrices', 'Growing the separatrices (motorcycle growing)'],
  ['conflicts', 'Finding the illegal crossings'],
  ['arc crossings', 'Finding the crossings of the arcs on the surface'],
]);
export const SOLVE_STAGES = Object.freeze([
  ['exact', 'Solving program P1 (exact solver)'],
  ['arcs', 'Tracing the arcs and cutting the mesh into patches'],
]);
// The core's stages of a quad mesh from a layout (remesh_bindings.cpp), in order.
export const REMESH_STAGES = Object.freeze([
  ['remesh prep', 'Unfolding the patches and measuring their sides'],
  ['remesh', 'Integer side lengths and the patches mapped onto their rectangles'],
  ['hausdorff', 'Measuring the distance to the input'],
]);
// The core's stages of a regular surface, in order.
// A map drawn on a target's surface: the target's surface, then the drawing (mapped_map.cpp).
export const DRAWN_STAGES = Object.freeze([
  ['hyperbolic tiling', "Growing the target's hyperbolic tiling"],
  ['relaxation', "Relaxing the target's edge graph in space"],
  ['tubification', "Tubifying the target's edges"],
  ['template', "Cutting the map's tiling into the quarter tube"],
  ['quarter tubes', 'Placing the map in every quarter tube'],
  ['faces', "Labelling the map's faces and edges"],
  ['checks', 'Checking the drawing: faces, vertices, edges, genus'],
]);
// The print check of an STL export (export/print_check.h).
export const PRINT_STAGES = Object.freeze([
  ['self-intersections', 'Checking the solid for self-intersections'],
  ['thickness', 'Measuring the thinnest wall'],
]);

export const SURFACE_STAGES = Object.freeze([
  ['hyperbolic tiling', 'Growing the hyperbolic tiling'],
  ['relaxation', 'Relaxing the edge graph in space'],
  ['tubification', 'Tubifying the edges into quarter tubes'],
  ['self-intersections', 'Searching for self-intersections'],
]);

/**
 * A plan that gives the stages [coreStage, label] consecutive parts of the bar from `from` to
 * `to`, in proportion to `weights` (one per stage). Returns [[coreStage, label, start, end]].
 */
export function planStages(stages, weights, from, to) {
  const total = weights.reduce((sum, w) => sum + w, 0);
  let start = from;
  return stages.map(([stage, label], i) => {
    const end = start + ((to - from) * weights[i]) / total;
    const part = [stage, label, start, end];
    start = end;
    return part;
  });
}

/**
 * onProgress(stage, fraction) for the core, reporting progress(label, fraction of the job) by the
 * plan. A stage the plan does not know shows under its own name with the bar where it was.
 */
export function stagedProgress(plan, progress) {
  let last = plan.length > 0 ? plan[0][2] : 0;
  return (stage, fraction) => {
    const part = plan.find(([name]) => name === stage);
    if (!part) return progress(stage, last);
    const [, label, start, end] = part;
    last = start + (end - start) * Math.min(1, Math.max(0, Number(fraction) || 0));
    progress(label, last);
  };
}
