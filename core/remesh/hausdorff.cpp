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

// The distance from p to the nearest triangle of the grid, when it is above `floor` (else some
// distance <= floor, which cannot raise a largest distance of `floor`): the cube of half-width r
// holds every point within r, so a nearest point found at distance <= r is the nearest; else r
// grows to it (to at least `fallback` from an empty one). Once a largest distance is known, the
// first look is the one cell around p (r = 0): most samples lie closer to the other mesh than
// that distance and are settled there, and only the few far ones grow the cube.
double distance_above(const TriangleGrid& grid, const Mesh& mesh, const Vector3d& p, double r,
                      double floor, double fallback) {
  for (;;) {
    double best = std::numeric_limits<double>::infinity();
    grid.for_each_triangle_near(p, r, [&](std::uint32_t t) {
      const auto& c = grid.corners[t];
      const Vector3d q =
          nearest_on_triangle(p, mesh.positions[c[0]], mesh.positions[c[1]], mesh.positions[c[2]]);
      best = std::min(best, (q - p).norm());
    });
    if (best <= r || best <= floor) return best;
    r = std::isfinite(best) ? best : std::max(2 * r, fallback);
  }
}

// The largest distance from the points `from` to the mesh `to`, or `floor` if that is larger.
double one_sided(const std::vector<Vector3d>& from, const TriangleGrid& grid, const Mesh& to,
                 double start, double floor = 0) {
  double largest = floor;
  for (const Vector3d& p : from)
    largest =
        std::max(largest, distance_above(grid, to, p, largest > 0 ? 0.0 : start, largest, start));
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
  // The other direction matters only where it exceeds this one: from_a is its floor.
  return one_sided(samples(b), grid_, *a_, start, from_a) / d;
}

double relative_hausdorff(const Mesh& a, const Mesh& b) {
  return HausdorffReference(a).relative_to(b);
}

}  // namespace tessera::remesh
