#include "remesh/smoothing.h"

#include <algorithm>
#include <limits>

#include <Eigen/Geometry>

#include "mesh/triangle_grid.h"
#include "remesh/quad_quality.h"

namespace tessera::remesh {
namespace {

using Eigen::Vector3d;

// A move is kept if the least scaled Jacobian of the quads at the vertex stays at least this, or
// does not fall: the pass never lowers the mesh's minimum below min(its minimum, this).
constexpr double kKeptJacobian = 0.5;

std::vector<std::vector<Index>> neighbours(const Mesh& quads) {
  std::vector<std::vector<Index>> result(quads.vertex_count());
  for (std::size_t f = 0; f < quads.face_count(); ++f) {
    const auto v = quads.face(f);
    for (std::size_t k = 0; k < v.size(); ++k) {
      const Index a = v[k], b = v[(k + 1) % v.size()];
      result[a].push_back(b);
      result[b].push_back(a);
    }
  }
  for (auto& list : result) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  return result;
}

// The nearest point of the surface to p among the triangles near it, with that triangle's
// normal; false if no triangle is within `radius`.
bool project(const TriangleGrid& grid, const Mesh& surface, const Vector3d& p, double radius,
             Vector3d& point, Vector3d& normal) {
  double best = radius * radius;
  bool found = false;
  grid.for_each_triangle_near(p, radius, [&](std::uint32_t t) {
    const auto& c = grid.corners[t];
    const Vector3d& a = surface.positions[c[0]];
    const Vector3d& b = surface.positions[c[1]];
    const Vector3d& d = surface.positions[c[2]];
    const Vector3d q = nearest_on_triangle(p, a, b, d);
    const double distance = (q - p).squaredNorm();
    if (distance > best) return;
    best = distance;
    point = q;
    normal = (b - a).cross(d - a).normalized();
    found = true;
  });
  return found;
}

// The least scaled Jacobian of the quads at v (quad_quality.h).
double least_around(const Mesh& quads, const std::vector<Vector3d>& normal,
                    const std::vector<Index>& faces) {
  double least = 1;
  for (Index f : faces) least = std::min(least, least_scaled_jacobian(quads, f, normal));
  return least;
}

}  // namespace

// Ericson, Real-Time Collision Detection, 5.1.5: by the Voronoi regions of the corners, edges and
// face.
Vector3d nearest_on_triangle(const Vector3d& p, const Vector3d& a, const Vector3d& b,
                             const Vector3d& c) {
  const Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + d1 / (d1 - d3) * ab;
  const Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + d2 / (d2 - d6) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0)
    return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
  const double denominator = 1 / (va + vb + vc);
  return a + ab * (vb * denominator) + ac * (vc * denominator);
}

void smooth_on_surface(Mesh& quads, std::vector<Vector3d>& normal, const std::vector<bool>& fixed,
                       const Mesh& surface, int rounds) {
  if (rounds <= 0) return;
  const TriangleGrid grid(surface);
  const std::vector<std::vector<Index>> around = neighbours(quads);
  std::vector<std::vector<Index>> faces(quads.vertex_count());
  for (Index f = 0; f < quads.face_count(); ++f)
    for (Index v : quads.face(f)) faces[v].push_back(f);
  for (int round = 0; round < rounds; ++round) {
    for (Index v = 0; v < quads.vertex_count(); ++v) {
      if (fixed[v] || around[v].empty()) continue;
      Vector3d mean = Vector3d::Zero();
      double reach = 0;  // the longest edge at v: how far the nearest surface point can be
      for (Index w : around[v]) {
        mean += quads.positions[w];
        reach = std::max(reach, (quads.positions[w] - quads.positions[v]).norm());
      }
      mean /= double(around[v].size());
      Vector3d point, n;
      if (!project(grid, surface, 0.5 * (quads.positions[v] + mean), reach, point, n)) continue;
      const double before = least_around(quads, normal, faces[v]);
      const Vector3d old_point = quads.positions[v], old_normal = normal[v];
      quads.positions[v] = point;
      normal[v] = n;
      if (least_around(quads, normal, faces[v]) < std::min(before, kKeptJacobian)) {
        quads.positions[v] = old_point;
        normal[v] = old_normal;
      }
    }
  }
}

}  // namespace tessera::remesh
