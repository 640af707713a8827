// The one surface-mesh type of Tessera: vertex positions and polygon faces as indexed lists.
//
// Faces are stored flat: face f has the corners face_offsets[f] .. face_offsets[f+1]-1, and corner
// c sits at vertex face_vertices[c]. Triangles are the common case; quads and other polygons are
// representable (quad meshes, Ch. 7). Corners are numbered so that later stages can keep per-corner
// data (uv, Sec. 6.6) in plain arrays, and the halfedge of corner c is halfedge c (connectivity.h).
// Optional per-face integer attributes (e.g. "patch", "tile") travel with the mesh through readers
// and writers; each holds exactly one value per face.
//
// A Mesh is plain data: it may be invalid (out-of-range indices, NaN, non-manifold) until
// validate_mesh() (validate.h) has accepted it. Connectivity is built separately (connectivity.h).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <map>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace tessera {

using Index = std::uint32_t;
inline constexpr Index kNoIndex = std::numeric_limits<Index>::max();

struct Mesh {
  std::vector<Eigen::Vector3d> positions;
  std::vector<Index> face_offsets{0};  // face_count() + 1 entries, first 0
  std::vector<Index> face_vertices;    // one vertex index per corner
  std::map<std::string, std::vector<std::int32_t>> face_attributes;  // name -> one value per face

  std::size_t vertex_count() const { return positions.size(); }
  std::size_t face_count() const { return face_offsets.size() - 1; }
  std::size_t corner_count() const { return face_vertices.size(); }
  std::size_t face_size(std::size_t f) const { return face_offsets[f + 1] - face_offsets[f]; }
  std::span<const Index> face(std::size_t f) const {
    return {face_vertices.data() + face_offsets[f], face_size(f)};
  }
  // The corner after corner c in its face f (cyclically): the halfedge of corner c ends there.
  Index next_corner(Index c, std::size_t f) const {
    return c + 1 == face_offsets[f + 1] ? face_offsets[f] : c + 1;
  }

  Index add_vertex(const Eigen::Vector3d& p);
  // Appends a face; attributes are not touched (fill them after the faces, one value per face).
  Index add_face(std::span<const Index> vertices);
  Index add_face(std::initializer_list<Index> vertices) {
    return add_face(std::span<const Index>(vertices.begin(), vertices.size()));
  }
  bool is_triangle_mesh() const { return corner_count() == 3 * face_count(); }
};

// A triangle mesh from positions and vertex triples (no checks; see validate_mesh()).
Mesh triangle_mesh(std::vector<Eigen::Vector3d> positions,
                   const std::vector<std::array<Index, 3>>& triangles);

// Removes the vertices that no face uses, renumbering the others in order; returns how many.
std::size_t remove_unreferenced_vertices(Mesh& mesh);

// Each polygon with n > 3 corners becomes n - 2 triangles fanned from its first corner; face
// attributes are copied to every triangle of their polygon. Triangles stay as they are.
Mesh triangulate(const Mesh& mesh);

}  // namespace tessera
