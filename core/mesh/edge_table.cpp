#include "mesh/edge_table.h"

#include <algorithm>
#include <utility>

namespace tessera {

std::vector<Index> corner_faces(const Mesh& mesh) {
  std::vector<Index> faces(mesh.corner_count());
  for (std::size_t f = 0; f < mesh.face_count(); ++f)
    std::fill(faces.begin() + mesh.face_offsets[f], faces.begin() + mesh.face_offsets[f + 1],
              static_cast<Index>(f));
  return faces;
}

EdgeTable build_edge_table(const Mesh& mesh) {
  const std::size_t corners = mesh.corner_count();
  // Bucket the corners by the smaller vertex of their halfedge (a counting sort), then group each
  // bucket by the larger vertex: linear in the mesh size, deterministic, no hashing.
  std::vector<Index> other(corners);
  std::vector<Index> bucket_offsets(mesh.vertex_count() + 1, 0);
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    for (Index c = mesh.face_offsets[f]; c < mesh.face_offsets[f + 1]; ++c) {
      const Index a = mesh.face_vertices[c];
      const Index b = mesh.face_vertices[mesh.next_corner(c, f)];
      other[c] = std::max(a, b);
      ++bucket_offsets[std::min(a, b) + 1];
    }
  }
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v) bucket_offsets[v + 1] += bucket_offsets[v];
  std::vector<Index> bucketed(corners);
  {
    std::vector<Index> fill(bucket_offsets.begin(), bucket_offsets.end() - 1);
    for (std::size_t f = 0; f < mesh.face_count(); ++f) {
      for (Index c = mesh.face_offsets[f]; c < mesh.face_offsets[f + 1]; ++c) {
        const Index a = mesh.face_vertices[c];
        const Index b = mesh.face_vertices[mesh.next_corner(c, f)];
        bucketed[fill[std::min(a, b)]++] = c;
      }
    }
  }

  EdgeTable table;
  table.corner_edge.assign(corners, kNoIndex);
  table.edge_corners.reserve(corners);
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
    const auto begin = bucketed.begin() + bucket_offsets[v];
    const auto end = bucketed.begin() + bucket_offsets[v + 1];
    std::sort(begin, end,
              [&](Index x, Index y) { return std::pair(other[x], x) < std::pair(other[y], y); });
    for (auto it = begin; it != end;) {
      const Index hi = other[*it];
      const Index e = static_cast<Index>(table.edge_vertices.size());
      table.edge_vertices.push_back({static_cast<Index>(v), hi});
      for (; it != end && other[*it] == hi; ++it) {
        table.corner_edge[*it] = e;
        table.edge_corners.push_back(*it);
      }
      table.edge_offsets.push_back(static_cast<Index>(table.edge_corners.size()));
    }
  }
  return table;
}

Closure closure(const Mesh& mesh) {
  const EdgeTable table = build_edge_table(mesh);
  Closure result;
  for (Index e = 0; e < table.edge_count(); ++e) {
    const auto corners = table.corners(e);
    if (corners.size() != 2) {
      result.closed = false;
      continue;
    }
    if (mesh.face_vertices[corners[0]] == mesh.face_vertices[corners[1]]) result.oriented = false;
  }
  return result;
}

}  // namespace tessera
