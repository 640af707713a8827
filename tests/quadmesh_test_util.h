// Quad meshes built in code for the quad-mesh optimization tests (thesis Ch. 7): flat grids with
// boundary, and irregular vertices planted by rotating edges of a grid.
#pragma once

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "mesh/mesh.h"

namespace tessera::test {

// A flat n x m grid of unit quads in the plane z = 0, counterclockwise seen from +z; vertex
// (i, j) is i * (m + 1) + j. The quads (i, j) for which `skip` is true are left out (the vertices
// stay; only those of some quad count once the mesh is validated).
template <typename Skip>
Mesh flat_quad_grid(int n, int m, Skip skip) {
  Mesh mesh;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= m; ++j) mesh.add_vertex({double(i), double(j), 0.0});
  const auto at = [m](int i, int j) { return static_cast<Index>(i * (m + 1) + j); };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j)
      if (!skip(i, j)) mesh.add_face({at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
  return mesh;
}

inline Mesh flat_quad_grid(int n, int m) {
  return flat_quad_grid(n, m, [](int, int) { return false; });
}

// Rotates the edge a-b shared by two quads (a, b, c, d) and (b, a, e, f) into the edge d-f: a and
// b lose a quad (valence 4 -> 3), d and f gain one (4 -> 5). Throws if a-b is not such an edge.
inline void rotate_quad_edge(Mesh& mesh, Index a, Index b) {
  std::vector<std::vector<Index>> faces;
  for (std::size_t f = 0; f < mesh.face_count(); ++f)
    faces.emplace_back(mesh.face(f).begin(), mesh.face(f).end());
  // The face holding from -> to as consecutive corners, turned to start there.
  const auto find = [&faces](Index from, Index to) {
    for (std::size_t f = 0; f < faces.size(); ++f) {
      std::vector<Index>& face = faces[f];
      for (std::size_t k = 0; k < face.size(); ++k) {
        if (face[k] != from || face[(k + 1) % face.size()] != to) continue;
        std::rotate(face.begin(), face.begin() + long(k), face.end());
        return f;
      }
    }
    throw std::invalid_argument("rotate_quad_edge(): no quad holds the edge");
  };
  const std::size_t f1 = find(a, b), f2 = find(b, a);
  const Index c = faces[f1][2], d = faces[f1][3], e = faces[f2][2], f = faces[f2][3];
  faces[f1] = {f, b, c, d};
  faces[f2] = {d, a, e, f};
  Mesh rotated;
  rotated.positions = mesh.positions;
  for (const std::vector<Index>& face : faces) rotated.add_face(face);
  mesh = rotated;
}

}  // namespace tessera::test
