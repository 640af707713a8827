// The vertices of the mesh cut open along the cut graph (Sec. 6.6): the corners around a vertex
// fall into wedges, separated by cut and boundary edges. One uv per wedge makes the
// parameterization continuous inside the cut-open disk; each cut edge joins two wedge pairs by a
// transition.
//
// In:  connectivity of a triangle mesh and the cut edges (cut_graph.h).
// Out: the wedge of every corner, numbered by first corner; nothing throws.
#pragma once

#include <cstdint>
#include <vector>

#include "mesh/connectivity.h"

namespace tessera {

struct Wedges {
  std::vector<Index> corner_wedge;  // per corner
  std::size_t count = 0;
};

Wedges cut_wedges(const Connectivity& connectivity, const std::vector<std::uint8_t>& cut);

}  // namespace tessera
