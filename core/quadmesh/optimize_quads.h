// Quad-mesh structure optimization (thesis Ch. 7), in two steps so that a new alpha reruns only
// the second (SPEC "Data flow"):
//  1. build_quad_graph(): the integer charts (Sec. 7.1, 7.2), the trivial base complex B
//     (Sec. 7.2, 7.3 step 1), the supergraph G along B (Sec. 7.3 step 2, 7.4), the arcs of its
//     edges (straight in the integer metric) and the illegal crossings I with the zero-area pairs
//     Z (Sec. 7.3 step 3, Sec. 4.6), as the layout stage builds them;
//  2. optimize_quad_layout(): program P1 (Sec. 7.3 step 4, Theorem 5.1) by core/matching and the
//     layout stage's rounds, the mesh cut along the chosen arcs, the check, the angle RSD; and the
//     layout over the quad mesh itself: every quad no arc crosses keeps its patch as a quad, the
//     quads an arc cuts through (the arcs of edges of height > 0 are diagonal in the grid) are
//     given as the refined triangles, so that every arc runs along edges of the result. (Giving
//     every cut quad to the patch covering most of it instead, so that the arcs become staircases
//     of quad edges, broke the layout on all six shared quad meshes: patches a quad wide pinch at
//     a vertex, and a crossing of two arcs inside a quad leaves corners off the nodes.)
//
// In:  a pure quad mesh (quad_input.h) that validate_mesh() accepted, options.
// Out: plain values. Throws InputError for a mesh without irregular vertices (no separatrices:
//      nothing to optimize), the layout stage's LimitError and CancelledError.
#pragma once

#include <vector>

#include "base/limits.h"
#include "base/progress.h"
#include "layout/quad_layout.h"
#include "matching/solver.h"
#include "quadmesh/base_complex.h"
#include "quadmesh/integer_charts.h"
#include "quadmesh/supergraph.h"

namespace tessera::quadmesh {

struct QuadGraph {
  Mesh quads;
  Connectivity connectivity;
  IntegerCharts charts;
  BaseComplex base;
  Supergraph supergraph;  // its graph moved into layout_graph
  layout::LayoutGraph layout_graph;
};

struct QuadLayoutResult {
  layout::QuadLayout layout;  // over the refined triangles of the integer charts
  Mesh mesh;                  // over the quad mesh: face attributes "patch" and "quad"
  std::size_t cut_quads = 0;  // quads given as refined triangles
  layout::LayoutCheck check;  // of `mesh`
  std::vector<layout::StageSeconds> seconds;
};

QuadGraph build_quad_graph(Mesh quads, const SupergraphOptions& options, const Progress& progress);

QuadLayoutResult optimize_quad_layout(const QuadGraph& graph, double alpha,
                                      matching::SolverKind solver, const Limits& limits,
                                      const Progress& progress);

// The layout's faces (refined triangles with their patch) over the quad mesh: the two triangles
// of a quad no arc cut, in one patch, become the quad again.
Mesh layout_over_quads(const Mesh& quads, const layout::RefinedMesh& refined,
                       const std::vector<std::int32_t>& patch, std::size_t& cut_quads);

}  // namespace tessera::quadmesh
