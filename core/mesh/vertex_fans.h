// The fans of faces around each vertex, found from the edge table (edge_table.h) without halfedge
// connectivity, so that a mesh not yet known to be manifold can be checked without an exception:
// validation uses it to find the vertices where welding would pinch the surface.
//
// In:  a mesh whose indices are in range and whose faces repeat no vertex, and its edge table.
// Out: per vertex, the number of fans meeting there. The faces around a vertex are in one fan when
//      they are joined through edges at the vertex that have exactly two faces. A manifold vertex
//      has one fan (none if it is in no face); more is a pinch: two sheets touching at a point, or
//      two boundary stretches meeting (build_connectivity() refuses both).
#pragma once

#include <vector>

#include "mesh/edge_table.h"
#include "mesh/mesh.h"

namespace tessera {

std::vector<Index> vertex_fan_counts(const Mesh& mesh, const EdgeTable& table);

}  // namespace tessera
