// Twin edges of G: condition C1 finds an edge at either free corner of its rectangle (thesis
// Sec. 4.2). At m = gamma_a cap gamma_b the edge joins port a of s_i to the port of s_j along -d_a;
// at the opposite corner m' (the line of s_i along -d_b meets the line of s_j along -d_a) it joins
// the same two ports with the same base and height, and its hypotenuse is the same segment: the
// arc leaves each port at the same turn atan(L_height / L_base) to the same side. Such twins are
// one edge of the layout: P1 would otherwise hold two copies of every arc (four conflict pairs for
// one crossing of two twinned arcs), and a loop round that forbids one copy would let the solver
// take the other.
//
// In:  the graph before its conflicts, one arc per edge. Out: the first edge of each set of twins
//      kept, the others removed and the edges renumbered; the zero-area pairs of removed twins move
//      to the kept one. Returns how many edges were removed.
#pragma once

#include <vector>

#include "layout/arcs.h"

namespace tessera::layout {

std::size_t merge_twin_edges(PortGraph& graph, std::vector<Arc>& arcs);

}  // namespace tessera::layout
