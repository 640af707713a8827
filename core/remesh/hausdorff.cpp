#include "remesh/hausdorff.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <Eigen/Geometry>

#include "remesh/smoothing.h"

namespace tessera::remesh {
namespace {

using Eigen::Vector3d;

std::vector<Vector3d> samples(const Mesh& mesh) {
  std::vector<Vector3d> points = mesh.positions;
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    Vector3d centroid = Vector3d::Zero();
    for (Index v : mesh.face(f)) centroid += mesh.positions[v];
    points.push_back(centroid / double(mesh.face_size(f)));
  }
  return points;
}

double diagonal(const Mesh& mesh) {
  Eigen::AlignedBox3d box;
  for (const Vector3d& x : mesh.positions) box.extend(x);
  return box.diagonal().norm();
}

// The distance from p to the nearest triangle of the grid: the cube of half-width r holds every
// point within r, so a nearest point found at distance <= r is the nearest; else r grows to it.
double distance_to(const TriangleGrid& grid, const Mesh& mesh, const Vector3d& p, double r) {
  for (;;) {
    double best = std::numeric_limits<double>::infinity();
    grid.for_each_triangle_near(p, r, [&](std::uint32_t t) {
      const auto& c = grid.corners[t];
      const Vector3d q =
          nearest_on_triangle(p, mesh.positions[c[0]], mesh.positions[c[1]], mesh.positions[c[2]]);
      best = std::min(best, (q - p).norm());
    });
    if (best <= r) return best;
    r = std::isfinite(best) ? best : 2 * r;
  }
}

double one_sided(const std::vector<Vector3d>& from, const TriangleGrid& grid, const Mesh& to,
                 double start) {
  double largest = 0;
  for (const Vector3d& p : from) largest = std::max(largest, distance_to(grid, to, p, start));
  return largest;
}

}  // namespace

HausdorffReference::HausdorffReference(const Mesh& a)
    : a_(&a), grid_(a), samples_(samples(a)), diagonal_(diagonal(a)) {}

double HausdorffReference::relative_to(const Mesh& b) const {
  const double d = diagonal_;
  if (!(d > 0) || b.face_count() == 0) return std::numeric_limits<double>::infinity();
  const double start = 1e-3 * d;
  const double from_a = one_sided(samples_, TriangleGrid(b), b, start);
  return std::max(from_a, one_sided(samples(b), grid_, *a_, start)) / d;
}

double relative_hausdorff(const Mesh& a, const Mesh& b) {
  return HausdorffReference(a).relative_to(b);
}

}  // namespace tessera::remesh
