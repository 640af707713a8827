#include "mesh/shapes.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <utility>

#include "mesh/edge_table.h"

namespace tessera {
namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

Mesh icosahedron() {
  const double t = std::numbers::phi;
  Mesh mesh;
  for (const auto& p : std::vector<Eigen::Vector3d>{{-1, t, 0},
                                                    {1, t, 0},
                                                    {-1, -t, 0},
                                                    {1, -t, 0},
                                                    {0, -1, t},
                                                    {0, 1, t},
                                                    {0, -1, -t},
                                                    {0, 1, -t},
                                                    {t, 0, -1},
                                                    {t, 0, 1},
                                                    {-t, 0, -1},
                                                    {-t, 0, 1}})
    mesh.add_vertex(p);
  // Five triangles around vertex 0, the five below them, five around vertex 3, five above those.
  const Index faces[20][3] = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                              {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                              {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                              {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (const auto& f : faces) mesh.add_face({f[0], f[1], f[2]});
  return mesh;
}

// Each triangle into four through its edge midpoints (shared between neighbours).
Mesh subdivide(const Mesh& mesh) {
  Mesh fine;
  fine.positions = mesh.positions;
  std::map<std::pair<Index, Index>, Index> midpoint;
  auto middle = [&](Index a, Index b) {
    const auto key = std::minmax(a, b);
    const auto [it, inserted] = midpoint.try_emplace(key, static_cast<Index>(fine.vertex_count()));
    if (inserted) fine.add_vertex(0.5 * (mesh.positions[a] + mesh.positions[b]));
    return it->second;
  };
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const auto t = mesh.face(f);
    const Index ab = middle(t[0], t[1]), bc = middle(t[1], t[2]), ca = middle(t[2], t[0]);
    fine.add_face({t[0], ab, ca});
    fine.add_face({ab, t[1], bc});
    fine.add_face({ca, bc, t[2]});
    fine.add_face({ab, bc, ca});
  }
  return fine;
}

// A periodic grid of quads on torus coordinates, leaving out the quads where `skip` says so.
template <class Skip>
Mesh torus_grid(double major_radius, double minor_radius, int major_segments, int minor_segments,
                Skip skip) {
  Mesh mesh;
  for (int i = 0; i < major_segments; ++i) {
    const double u = kTwoPi * i / major_segments;
    for (int j = 0; j < minor_segments; ++j) {
      const double v = kTwoPi * j / minor_segments;
      const double ring = major_radius + minor_radius * std::cos(v);
      mesh.add_vertex({ring * std::cos(u), ring * std::sin(u), minor_radius * std::sin(v)});
    }
  }
  auto at = [&](int i, int j) {
    return static_cast<Index>((i % major_segments) * minor_segments + j % minor_segments);
  };
  // (d/du x d/dv) points outward, so this corner order is counterclockwise from outside.
  for (int i = 0; i < major_segments; ++i)
    for (int j = 0; j < minor_segments; ++j)
      if (!skip(i, j)) mesh.add_face({at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
  return mesh;
}

// The mirror image of a mesh in the plane x = 0, with faces reversed to stay outward-oriented.
Mesh mirrored_in_x(const Mesh& mesh) {
  Mesh mirror;
  for (const Eigen::Vector3d& p : mesh.positions) mirror.add_vertex({-p.x(), p.y(), p.z()});
  std::vector<Index> corners;
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const auto face = mesh.face(f);
    corners.assign(face.rbegin(), face.rend());
    mirror.add_face(corners);
  }
  return mirror;
}

// Appends `part` to `mesh`; returns the index offset of its vertices.
Index append(Mesh& mesh, const Mesh& part) {
  const Index offset = static_cast<Index>(mesh.vertex_count());
  mesh.positions.insert(mesh.positions.end(), part.positions.begin(), part.positions.end());
  std::vector<Index> corners;
  for (std::size_t f = 0; f < part.face_count(); ++f) {
    corners.clear();
    for (Index v : part.face(f)) corners.push_back(v + offset);
    mesh.add_face(corners);
  }
  return offset;
}

bool bracket_occupied(int x, int y, int z) {
  const bool base = x >= 0 && x < 8 && y >= 0 && y < 6 && z >= 0 && z < 2;
  const bool upright = x >= 0 && x < 2 && y >= 0 && y < 6 && z >= 2 && z < 8;
  const bool base_hole = x >= 4 && x < 6 && y >= 2 && y < 4;
  const bool upright_hole = y >= 2 && y < 4 && z >= 4 && z < 6;
  return (base && !base_hole) || (upright && !upright_hole);
}

}  // namespace

Mesh icosphere(int subdivisions, double radius) {
  Mesh mesh = icosahedron();
  for (int s = 0; s < subdivisions; ++s) mesh = subdivide(mesh);
  for (Eigen::Vector3d& p : mesh.positions) p = radius * p.normalized();
  return mesh;
}

Mesh quad_torus(double major_radius, double minor_radius, int major_segments, int minor_segments) {
  return torus_grid(major_radius, minor_radius, std::max(major_segments, 3),
                    std::max(minor_segments, 3), [](int, int) { return false; });
}

Mesh torus(double major_radius, double minor_radius, int major_segments, int minor_segments) {
  return triangulate(quad_torus(major_radius, minor_radius, major_segments, minor_segments));
}

Mesh double_torus(int resolution) {
  resolution = std::max(resolution, 1);
  const double major = 1.0, minor = 0.5;
  const int major_segments = 8 * resolution, minor_segments = 4 * resolution;
  const int half_hole = std::max(resolution / 2, 1);
  // The cut-out patch faces +x: quads around u = 0 (outermost) and v = 0 (equator).
  auto in_hole = [&](int i, int j) {
    const bool near_u = i < half_hole || i >= major_segments - half_hole;
    const bool near_v = j < half_hole || j >= minor_segments - half_hole;
    return near_u && near_v;
  };
  Mesh left = torus_grid(major, minor, major_segments, minor_segments, in_hole);
  const double shift = major + minor;  // the two cut-outs meet at x = 0
  for (Eigen::Vector3d& p : left.positions) p.x() -= shift;

  Mesh mesh = left;
  const Index offset = append(mesh, mirrored_in_x(left));
  // The neck: each boundary edge p->q of the left torus (as its face runs along it) meets its
  // mirror image; the quad (q, p, p', q') runs along both opposite to their faces, keeping the
  // orientation.
  const EdgeTable table = build_edge_table(left);
  for (Index e = 0; e < table.edge_count(); ++e) {
    const auto corners = table.corners(e);
    if (corners.size() != 1) continue;
    const Index c = corners[0];
    const Index p = left.face_vertices[c];
    const Index q = left.face_vertices[c % 4 == 3 ? c - 3 : c + 1];  // all faces are quads
    mesh.add_face({q, p, p + offset, q + offset});
  }
  remove_unreferenced_vertices(mesh);  // those inside the cut-out patches
  return triangulate(mesh);
}

Mesh mechanical_part(int resolution) {
  resolution = std::max(resolution, 1);
  auto occupied = [&](int x, int y, int z) {
    auto coarse = [&](int a) { return a >= 0 ? a / resolution : -1; };
    return bracket_occupied(coarse(x), coarse(y), coarse(z));
  };
  Mesh mesh;
  std::map<std::array<int, 3>, Index> vertex_at;
  auto vertex = [&](const std::array<int, 3>& g) {
    const auto [it, inserted] = vertex_at.try_emplace(g, static_cast<Index>(mesh.vertex_count()));
    if (inserted)
      mesh.add_vertex(Eigen::Vector3d(g[0], g[1], g[2]) / static_cast<double>(resolution));
    return it->second;
  };
  const int n = 8 * resolution;
  // One square per face between an occupied and an empty voxel, ordered so that its normal
  // e_b x e_c = e_a points out of the solid.
  for (int x = 0; x < n; ++x)
    for (int y = 0; y < n; ++y)
      for (int z = 0; z < n; ++z) {
        if (!occupied(x, y, z)) continue;
        for (int axis = 0; axis < 3; ++axis)
          for (int side : {-1, 1}) {
            std::array<int, 3> neighbour{x, y, z};
            neighbour[axis] += side;
            if (occupied(neighbour[0], neighbour[1], neighbour[2])) continue;
            const int b = (axis + 1) % 3, c = (axis + 2) % 3;
            std::array<int, 3> corner{x, y, z};
            if (side > 0) ++corner[axis];
            std::array<std::array<int, 3>, 4> square{corner, corner, corner, corner};
            ++square[1][b];
            ++square[2][b];
            ++square[2][c];
            ++square[3][c];
            if (side > 0)
              mesh.add_face(
                  {vertex(square[0]), vertex(square[1]), vertex(square[2]), vertex(square[3])});
            else
              mesh.add_face(
                  {vertex(square[0]), vertex(square[3]), vertex(square[2]), vertex(square[1])});
          }
      }
  return triangulate(mesh);
}

Mesh open_cylinder(double radius, double height, int segments, int rings) {
  segments = std::max(segments, 3);
  rings = std::max(rings, 1);
  Mesh mesh;
  for (int j = 0; j <= rings; ++j)
    for (int i = 0; i < segments; ++i) {
      const double u = kTwoPi * i / segments;
      mesh.add_vertex({radius * std::cos(u), radius * std::sin(u), height * j / rings});
    }
  auto at = [&](int i, int j) { return static_cast<Index>(j * segments + i % segments); };
  for (int j = 0; j < rings; ++j)
    for (int i = 0; i < segments; ++i)
      mesh.add_face({at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
  return triangulate(mesh);
}

}  // namespace tessera
