#include "mesh/triangle_grid.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

namespace tessera {
namespace {

using Eigen::Vector3d;

bool boxes_overlap(const Box& a, const Box& b) {
  return (a.lo.array() <= b.hi.array()).all() && (b.lo.array() <= a.hi.array()).all();
}

// Barycentric slack: a ray through a vertex or along an edge (as on a symmetric mesh, from a vertex
// through the centre to the opposite one) meets the triangles there despite rounding.
constexpr double kBarycentricSlack = 1e-9;

// The distance along the ray to triangle abc (Moeller-Trumbore), infinity if it misses.
double ray_distance(const Vector3d& origin, const Vector3d& direction, const Vector3d& a,
                    const Vector3d& b, const Vector3d& c) {
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  const Vector3d e1 = b - a, e2 = c - a;
  const Vector3d p = direction.cross(e2);
  const double det = e1.dot(p);
  if (std::abs(det) <= 1e-300) return kInfinity;
  const Vector3d s = origin - a;
  const double u = s.dot(p) / det;
  if (u < -kBarycentricSlack || u > 1 + kBarycentricSlack) return kInfinity;
  const Vector3d q = s.cross(e1);
  const double v = direction.dot(q) / det;
  if (v < -kBarycentricSlack || u + v > 1 + kBarycentricSlack) return kInfinity;
  const double t = e2.dot(q) / det;
  return t > 0 ? t : kInfinity;
}

}  // namespace

TriangleGrid::TriangleGrid(const Mesh& mesh) : mesh_(mesh) {
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const auto polygon = mesh.face(f);
    for (std::size_t i = 1; i + 1 < polygon.size(); ++i) {
      corners.push_back({polygon[0], polygon[i], polygon[i + 1]});
      face.push_back(static_cast<Index>(f));
      Box b{mesh.positions[polygon[0]], mesh.positions[polygon[0]]};
      for (Index v : {polygon[i], polygon[i + 1]}) {
        b.lo = b.lo.cwiseMin(mesh.positions[v]);
        b.hi = b.hi.cwiseMax(mesh.positions[v]);
      }
      box.push_back(b);
    }
  }
  if (box.empty()) return;
  Vector3d lo = box[0].lo, hi = box[0].hi;
  double extent = 0.0;
  for (const Box& b : box) {
    lo = lo.cwiseMin(b.lo);
    hi = hi.cwiseMax(b.hi);
    extent += (b.hi - b.lo).maxCoeff();
  }
  origin_ = lo;
  cell_ = std::max(
      {extent / static_cast<double>(box.size()), (hi - lo).norm() / (1 << kCellBits) * 2, 1e-300});
  for (std::uint32_t i = 0; i < box.size(); ++i) {
    const Cell a = cell_of(box[i].lo), b = cell_of(box[i].hi);
    for (std::int64_t x = a[0]; x <= b[0]; ++x)
      for (std::int64_t y = a[1]; y <= b[1]; ++y)
        for (std::int64_t z = a[2]; z <= b[2]; ++z) cells_[key({x, y, z})].push_back(i);
  }
}

TriangleGrid::Cell TriangleGrid::cell_of(const Vector3d& p) const {
  Cell c{};
  for (int i = 0; i < 3; ++i) {
    const double x = std::floor((p[i] - origin_[i]) / cell_);
    c[static_cast<std::size_t>(i)] =
        std::clamp<std::int64_t>(static_cast<std::int64_t>(x), 0, (1 << kCellBits) - 1);
  }
  return c;
}

TriangleGrid::CellKey TriangleGrid::key(const Cell& c) {
  return static_cast<CellKey>(c[0]) | static_cast<CellKey>(c[1]) << kCellBits |
         static_cast<CellKey>(c[2]) << (2 * kCellBits);
}

void TriangleGrid::for_each_overlapping_pair(
    const std::function<void(std::uint32_t, std::uint32_t)>& visit,
    const std::function<void(double)>& visit_cell) const {
  std::size_t visited = 0;
  for (const auto& [cell, list] : cells_) {
    for (std::size_t i = 0; i < list.size(); ++i) {
      for (std::size_t j = i + 1; j < list.size(); ++j) {
        const std::uint32_t s = list[i], t = list[j];
        if (!boxes_overlap(box[s], box[t])) continue;
        // Each pair in one cell only: the cell of the corner where their boxes' overlap begins.
        if (key(cell_of(box[s].lo.cwiseMax(box[t].lo))) != cell) continue;
        visit(s, t);
      }
    }
    visit_cell(static_cast<double>(++visited) / static_cast<double>(cells_.size()));
  }
}

// Walks the cells the ray passes through in order (Amanatides and Woo's traversal) and stops at
// the first cell past which no nearer hit can lie.
TriangleGrid::Hit TriangleGrid::first_hit(const Vector3d& origin, const Vector3d& direction,
                                          double max_distance, Index skip) const {
  Hit hit;
  if (box.empty()) return hit;
  Cell cell = cell_of(origin);
  Cell step{};
  Vector3d next, delta;  // distance to the next cell boundary per axis, and between boundaries
  for (int i = 0; i < 3; ++i) {
    const auto k = static_cast<std::size_t>(i);
    const double d = direction[i];
    step[k] = d > 0 ? 1 : -1;
    const double boundary = origin_[i] + (static_cast<double>(cell[k]) + (d > 0 ? 1 : 0)) * cell_;
    next[i] = d == 0 ? std::numeric_limits<double>::infinity() : (boundary - origin[i]) / d;
    delta[i] = d == 0 ? std::numeric_limits<double>::infinity() : cell_ / std::abs(d);
  }
  constexpr std::int64_t kLast = (1 << kCellBits) - 1;
  double entered = 0.0;  // the distance at which the ray entered `cell`
  while (entered <= std::min(max_distance, hit.distance)) {
    if (const auto found = cells_.find(key(cell)); found != cells_.end()) {
      for (std::uint32_t t : found->second) {
        const auto& c = corners[t];
        if (c[0] == skip || c[1] == skip || c[2] == skip) continue;
        const auto& p = mesh_.positions;
        const double d = ray_distance(origin, direction, p[c[0]], p[c[1]], p[c[2]]);
        if (d <= max_distance && d < hit.distance) hit = {static_cast<Index>(t), d};
      }
    }
    int axis = 0;
    if (next[1] < next[axis]) axis = 1;
    if (next[2] < next[axis]) axis = 2;
    const auto k = static_cast<std::size_t>(axis);
    cell[k] += step[k];
    if (cell[k] < 0 || cell[k] > kLast) break;
    entered = next[axis];
    next[axis] += delta[axis];
  }
  return hit;
}

void TriangleGrid::for_each_triangle_near(const Vector3d& p, double radius,
                                          const std::function<void(std::uint32_t)>& visit) const {
  const Vector3d r = Vector3d::Constant(radius);
  const Cell a = cell_of(p - r), b = cell_of(p + r);
  for (std::int64_t x = a[0]; x <= b[0]; ++x)
    for (std::int64_t y = a[1]; y <= b[1]; ++y)
      for (std::int64_t z = a[2]; z <= b[2]; ++z)
        if (const auto found = cells_.find(key({x, y, z})); found != cells_.end())
          for (std::uint32_t t : found->second) visit(t);
}

}  // namespace tessera
