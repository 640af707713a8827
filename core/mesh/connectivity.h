// Halfedge connectivity over an indexed mesh (kept apart from the positions, as in
// geometry-central).
//
// Halfedge h < mesh.corner_count() is corner h: it runs inside its face from the corner's vertex to
// the next corner's vertex, so per-corner data and per-halfedge data share one numbering. Every
// boundary edge adds one boundary halfedge (face() == kNoIndex) after the corner halfedges;
// boundary halfedges chain along their boundary loop through next/prev. Edges are numbered as in
// build_edge_table(). Rotating around a vertex: next_outgoing(h) = twin(prev(h)) turns
// counterclockwise (seen from outside a counterclockwise-oriented surface).
//
// In:  a mesh that validate_mesh() accepted (indices in range, no repeated vertex in a face,
//      manifold, consistently oriented).
// Out: the connectivity as plain arrays.
// Throws TopologyError if the mesh is not a consistently oriented 2-manifold (with boundary).
#pragma once

#include <cstddef>
#include <vector>

#include "mesh/mesh.h"

namespace tessera {

struct Connectivity {
  std::vector<Index> to_vertex;        // per halfedge
  std::vector<Index> next;             // per halfedge, within its face or boundary loop
  std::vector<Index> prev;             // per halfedge
  std::vector<Index> twin;             // per halfedge, the opposite halfedge of the same edge
  std::vector<Index> face;             // per halfedge, kNoIndex on the boundary
  std::vector<Index> edge;             // per halfedge
  std::vector<Index> edge_halfedge;    // per edge, a halfedge with a face
  std::vector<Index> vertex_halfedge;  // per vertex, an outgoing halfedge, the boundary one on the
                                       // boundary; kNoIndex for a vertex in no face
  std::size_t corner_count = 0;        // halfedges [0, corner_count) are the corners

  std::size_t halfedge_count() const { return to_vertex.size(); }
  std::size_t edge_count() const { return edge_halfedge.size(); }
  std::size_t vertex_count() const { return vertex_halfedge.size(); }

  Index from_vertex(Index h) const { return to_vertex[twin[h]]; }
  bool is_boundary_halfedge(Index h) const { return face[h] == kNoIndex; }
  bool is_boundary_edge(Index e) const {
    const Index h = edge_halfedge[e];
    return is_boundary_halfedge(h) || is_boundary_halfedge(twin[h]);
  }
  bool is_boundary_vertex(Index v) const {
    const Index h = vertex_halfedge[v];
    return h != kNoIndex && is_boundary_halfedge(h);
  }
  Index next_outgoing(Index h) const { return twin[prev[h]]; }
};

Connectivity build_connectivity(const Mesh& mesh);

// The halfedges leaving vertex v, counterclockwise, starting at vertex_halfedge[v].
std::vector<Index> outgoing_halfedges(const Connectivity& connectivity, Index v);
// The same into `out` (cleared first), for loops over every vertex that should not allocate.
void outgoing_halfedges(const Connectivity& connectivity, Index v, std::vector<Index>& out);

}  // namespace tessera
