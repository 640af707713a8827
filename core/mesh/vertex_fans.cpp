#include "mesh/vertex_fans.h"

#include "base/disjoint_sets.h"

namespace tessera {

// Corners are the faces' visits to their vertices: two faces on an edge join their corners at
// each of its two vertices, and a vertex has as many fans as its corners have sets.
std::vector<Index> vertex_fan_counts(const Mesh& mesh, const EdgeTable& table) {
  const std::vector<Index> corner_face = corner_faces(mesh);
  DisjointSets fans(mesh.corner_count());
  for (Index e = 0; e < table.edge_count(); ++e) {
    const auto corners = table.corners(e);
    if (corners.size() != 2) continue;
    const Index c = corners[0], d = corners[1];
    const Index c_next = mesh.next_corner(c, corner_face[c]);
    const Index d_next = mesh.next_corner(d, corner_face[d]);
    if (mesh.face_vertices[c] == mesh.face_vertices[d]) {
      fans.join(c, d);
      fans.join(c_next, d_next);
    } else {
      fans.join(c, d_next);
      fans.join(c_next, d);
    }
  }
  std::vector<Index> counts(mesh.vertex_count(), 0);
  for (Index c = 0; c < mesh.corner_count(); ++c)
    if (fans.find(c) == c) ++counts[mesh.face_vertices[c]];
  return counts;
}

}  // namespace tessera
