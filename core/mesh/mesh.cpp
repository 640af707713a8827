#include "mesh/mesh.h"

namespace tessera {

Index Mesh::add_vertex(const Eigen::Vector3d& p) {
  positions.push_back(p);
  return static_cast<Index>(positions.size() - 1);
}

Index Mesh::add_face(std::span<const Index> vertices) {
  face_vertices.insert(face_vertices.end(), vertices.begin(), vertices.end());
  face_offsets.push_back(static_cast<Index>(face_vertices.size()));
  return static_cast<Index>(face_count() - 1);
}

Mesh triangle_mesh(std::vector<Eigen::Vector3d> positions,
                   const std::vector<std::array<Index, 3>>& triangles) {
  Mesh mesh;
  mesh.positions = std::move(positions);
  mesh.face_vertices.reserve(3 * triangles.size());
  mesh.face_offsets.reserve(triangles.size() + 1);
  for (const auto& t : triangles) mesh.add_face(t);
  return mesh;
}

std::size_t remove_unreferenced_vertices(Mesh& mesh) {
  std::vector<Index> new_index(mesh.vertex_count(), kNoIndex);
  for (Index v : mesh.face_vertices) new_index[v] = 0;
  std::vector<Eigen::Vector3d> kept;
  kept.reserve(mesh.vertex_count());
  for (Index v = 0; v < mesh.vertex_count(); ++v) {
    if (new_index[v] == kNoIndex) continue;
    new_index[v] = static_cast<Index>(kept.size());
    kept.push_back(mesh.positions[v]);
  }
  const std::size_t removed = mesh.vertex_count() - kept.size();
  if (removed > 0) {
    for (Index& v : mesh.face_vertices) v = new_index[v];
    mesh.positions = std::move(kept);
  }
  return removed;
}

Mesh triangulate(const Mesh& mesh) {
  Mesh out;
  out.positions = mesh.positions;
  std::vector<std::size_t> source_face;
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const auto face = mesh.face(f);
    for (std::size_t i = 1; i + 1 < face.size(); ++i) {
      out.add_face({face[0], face[i], face[i + 1]});
      source_face.push_back(f);
    }
  }
  for (const auto& [name, values] : mesh.face_attributes) {
    auto& copied = out.face_attributes[name];
    copied.reserve(source_face.size());
    for (std::size_t f : source_face) copied.push_back(values[f]);
  }
  return out;
}

}  // namespace tessera
