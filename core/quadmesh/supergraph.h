// The supergraph G of the trivial base complex B (thesis Sec. 7.3 step 2, Sec. 7.4): the graph of
// the ports (Ch. 4) built along the separatrices of B in the integer metric.
//  - Every separatrix of B is an edge: between the ports at its two ends (height 0), or from its
//    port to a virtual port where it reaches the boundary (Sec. 4.4).
//  - At every regular vertex m where two separatrices of B cross (lines a and b, or one line
//    crossing itself), with L_a(m), L_b(m) the edges counted from their irregular vertices, the
//    ratio test C1 of Sec. 4.1: the longer line is the base, the edge joins its port to the port
//    next to b's at the far end (case 1, 2); L_a = L_b gives both edges, a zero-area pair of
//    diagonal edges (case 3, Remark 4.2, Sec. 7.5 "Isosceles Triangles").
//  - Window reduction (Prop. 4.1): per base line and side, walking its crossings in the order of
//    L_base, a candidate is kept only if its slope L_height / L_base is below that of the last one
//    kept (at most 1 for the first), exactly, in integers.
//  - Multi-edges are kept (helices, Fig. 7.3): the same two ports may be joined at many crossings,
//    with different weights, so that a new alpha needs no new graph.
// The ports are the layout stage's (layout/ports.h) on the integer charts (integer_charts.h), so
// that its arcs, conflicts (Sec. 4.6, Algorithm 1 read on the surface) and P1 apply unchanged.
//
// In:  the quad mesh, its connectivity, its integer charts, its base complex, options.
// Out: the port graph (edges, virtual ports, zero-area pairs; no conflicts yet) and counts.
#pragma once

#include "layout/port_graph.h"
#include "quadmesh/base_complex.h"
#include "quadmesh/integer_charts.h"

namespace tessera::quadmesh {

struct SupergraphOptions {
  bool diagonals = true;  // false: no case-3 edges (Sec. 7.5, Fig. 7.6, 7.7)
};

struct Supergraph {
  layout::PortGraph graph;
  std::size_t crossing_edges = 0;      // edges made by C1 at crossings
  std::size_t separatrix_edges = 0;    // edges that are separatrices of B (to a port or boundary)
  std::size_t diagonal_edges = 0;      // case 3
  std::size_t rejected_by_window = 0;  // C1 candidates the window reduction turned down
};

Supergraph build_supergraph(const Mesh& quads, const Connectivity& connectivity,
                            const IntegerCharts& charts, const BaseComplex& base,
                            const SupergraphOptions& options);

}  // namespace tessera::quadmesh
