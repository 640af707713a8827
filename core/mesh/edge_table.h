// The undirected edges of an indexed mesh, found without halfedge connectivity, so that meshes that
// are not (yet) manifold or consistently oriented can be inspected: validation uses it to find
// non-manifold edges and to re-orient faces, build_connectivity() to pair halfedges.
//
// In:  a mesh whose indices are in range and whose faces have no two equal consecutive vertices.
// Out: edges numbered in the order of (smaller vertex, larger vertex); for each edge its two
//      vertices and the corners whose halfedge runs along it (any number, any direction).
#pragma once

#include <span>
#include <vector>

#include "mesh/mesh.h"

namespace tessera {

struct EdgeTable {
  std::vector<Index> corner_edge;                   // per corner: the edge its halfedge runs along
  std::vector<std::array<Index, 2>> edge_vertices;  // per edge: smaller, larger vertex
  std::vector<Index> edge_offsets{0};               // per edge: its corners are in edge_corners
  std::vector<Index> edge_corners;                  //   [edge_offsets[e], edge_offsets[e+1])

  std::size_t edge_count() const { return edge_vertices.size(); }
  std::span<const Index> corners(Index e) const {
    return {edge_corners.data() + edge_offsets[e], edge_offsets[e + 1] - edge_offsets[e]};
  }
};

EdgeTable build_edge_table(const Mesh& mesh);

// The face of every corner.
std::vector<Index> corner_faces(const Mesh& mesh);

// Closed: every edge has two faces; oriented: they run along it in opposite directions.
struct Closure {
  bool closed = true;
  bool oriented = true;
};
Closure closure(const Mesh& mesh);

}  // namespace tessera
