#include "mesh/self_intersection.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>

#include <Eigen/Geometry>

namespace tessera {

namespace {

using Eigen::Vector2d;
using Eigen::Vector3d;

// ---- One pair of triangles --------------------------------------------------------------------

using Triangle = std::array<Vector3d, 3>;

std::array<double, 3> plane_distances(const Triangle& plane, const Triangle& t) {
  const Vector3d n = (plane[1] - plane[0]).cross(plane[2] - plane[0]);
  return {n.dot(t[0] - plane[0]), n.dot(t[1] - plane[0]), n.dot(t[2] - plane[0])};
}

// Signed distances below a billionth of the triangles' size count as on the plane: otherwise
// rounding makes nearly coplanar neighbours on a smooth surface look as if they crossed.
constexpr double kOnPlane = 1e-9;
// Sine of the angle below which two planes count as parallel: their common line is too ill
// conditioned to compare intervals on (a sliver beside its neighbour across a nearly flat fold
// looked as if it crossed it). Projecting such a pair on one plane can only add crossings, never
// miss one: triangles that meet have projections that meet.
constexpr double kParallel = 1e-5;

void snap_to_plane(std::array<double, 3>& d, double normal_length, const Triangle& s,
                   const Triangle& t) {
  double size = 0.0;
  for (const Triangle* tri : {&s, &t})
    for (int i = 0; i < 3; ++i)
      size = std::max(size, ((*tri)[static_cast<std::size_t>(i)] -
                             (*tri)[static_cast<std::size_t>((i + 1) % 3)])
                                .norm());
  for (double& x : d)
    if (std::abs(x) <= kOnPlane * normal_length * size) x = 0.0;
}

bool strictly_one_side(const std::array<double, 3>& d) {
  return (d[0] > 0 && d[1] > 0 && d[2] > 0) || (d[0] < 0 && d[1] < 0 && d[2] < 0);
}

// The interval along `line` of the points where t meets the other triangle's plane (its vertices
// on the plane and its edges' crossings).
std::array<double, 2> crossing_interval(const Triangle& t, const std::array<double, 3>& d,
                                        const Vector3d& line) {
  std::array<double, 2> range = {std::numeric_limits<double>::infinity(),
                                 -std::numeric_limits<double>::infinity()};
  auto include = [&](const Vector3d& p) {
    const double x = line.dot(p);
    range[0] = std::min(range[0], x);
    range[1] = std::max(range[1], x);
  };
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    if (d[i] == 0) include(t[i]);
    if ((d[i] < 0 && d[j] > 0) || (d[i] > 0 && d[j] < 0))
      include(t[i] + (t[j] - t[i]) * (d[i] / (d[i] - d[j])));
  }
  return range;
}

double orient(const Vector2d& a, const Vector2d& b, const Vector2d& c) {
  return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}

// A point closer to a line than a billionth of the segments' size counts as on it (as kOnPlane
// for planes): otherwise rounding makes two disjoint segments on one line (the sides of two
// triangles on one edge of a subdivided triangle) look as if they crossed.
bool segments_meet(const Vector2d& a, const Vector2d& b, const Vector2d& c, const Vector2d& d) {
  const double size = std::max(
      {(b - a).squaredNorm(), (d - c).squaredNorm(), (c - a).squaredNorm(), (d - a).squaredNorm()});
  auto snapped = [&](double o) { return std::abs(o) <= kOnPlane * size ? 0.0 : o; };
  const double o1 = snapped(orient(a, b, c)), o2 = snapped(orient(a, b, d));
  const double o3 = snapped(orient(c, d, a)), o4 = snapped(orient(c, d, b));
  if (o1 == 0 && o2 == 0) {  // collinear: overlap of the projections on the longer axis
    const int axis = std::abs(b.x() - a.x()) >= std::abs(b.y() - a.y()) ? 0 : 1;
    const auto [lo1, hi1] = std::minmax(a[axis], b[axis]);
    const auto [lo2, hi2] = std::minmax(c[axis], d[axis]);
    return lo1 <= hi2 && lo2 <= hi1;
  }
  return ((o1 <= 0 && o2 >= 0) || (o1 >= 0 && o2 <= 0)) &&
         ((o3 <= 0 && o4 >= 0) || (o3 >= 0 && o4 <= 0));
}

bool inside_2d(const std::array<Vector2d, 3>& t, const Vector2d& p) {
  const double a = orient(t[0], t[1], p), b = orient(t[1], t[2], p), c = orient(t[2], t[0], p);
  return (a >= 0 && b >= 0 && c >= 0) || (a <= 0 && b <= 0 && c <= 0);
}

// Two triangles in one plane with normal n: drop n's largest coordinate.
bool coplanar_intersect(const Triangle& s, const Triangle& t, const Vector3d& n) {
  int drop = 0;
  n.cwiseAbs().maxCoeff(&drop);
  const int u = (drop + 1) % 3, v = (drop + 2) % 3;
  std::array<Vector2d, 3> p, q;
  for (int i = 0; i < 3; ++i) {
    p[static_cast<std::size_t>(i)] = {s[static_cast<std::size_t>(i)][u],
                                      s[static_cast<std::size_t>(i)][v]};
    q[static_cast<std::size_t>(i)] = {t[static_cast<std::size_t>(i)][u],
                                      t[static_cast<std::size_t>(i)][v]};
  }
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j)
      if (segments_meet(p[i], p[(i + 1) % 3], q[j], q[(j + 1) % 3])) return true;
  return inside_2d(p, q[0]) || inside_2d(q, p[0]);
}

// ---- The grid ---------------------------------------------------------------------------------

struct Box {
  Vector3d lo, hi;
};

using CellKey = std::uint64_t;
constexpr int kCellBits = 21;

class Grid {
 public:
  Grid(const Vector3d& origin, double cell) : origin_(origin), cell_(cell) {}

  std::array<std::int64_t, 3> cell_of(const Vector3d& p) const {
    std::array<std::int64_t, 3> c{};
    for (int i = 0; i < 3; ++i) {
      const double x = std::floor((p[i] - origin_[i]) / cell_);
      c[static_cast<std::size_t>(i)] =
          std::clamp<std::int64_t>(static_cast<std::int64_t>(x), 0, (1 << kCellBits) - 1);
    }
    return c;
  }
  static CellKey key(const std::array<std::int64_t, 3>& c) {
    return static_cast<CellKey>(c[0]) | static_cast<CellKey>(c[1]) << kCellBits |
           static_cast<CellKey>(c[2]) << (2 * kCellBits);
  }

 private:
  Vector3d origin_;
  double cell_;
};

struct Triangles {
  std::vector<std::array<Index, 3>> corners;
  std::vector<Index> face;
  std::vector<Box> box;
};

Triangles fan_triangles(const Mesh& mesh) {
  Triangles t;
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const auto face = mesh.face(f);
    for (std::size_t i = 1; i + 1 < face.size(); ++i) {
      t.corners.push_back({face[0], face[i], face[i + 1]});
      t.face.push_back(static_cast<Index>(f));
      Box b{mesh.positions[face[0]], mesh.positions[face[0]]};
      for (Index v : {face[i], face[i + 1]}) {
        b.lo = b.lo.cwiseMin(mesh.positions[v]);
        b.hi = b.hi.cwiseMax(mesh.positions[v]);
      }
      t.box.push_back(b);
    }
  }
  return t;
}

bool share_vertex(const std::array<Index, 3>& s, const std::array<Index, 3>& t) {
  for (Index a : s)
    for (Index b : t)
      if (a == b) return true;
  return false;
}

bool boxes_overlap(const Box& a, const Box& b) {
  return (a.lo.array() <= b.hi.array()).all() && (b.lo.array() <= a.hi.array()).all();
}

}  // namespace

bool triangles_intersect(const Vector3d& a, const Vector3d& b, const Vector3d& c, const Vector3d& d,
                         const Vector3d& e, const Vector3d& f) {
  const Triangle s = {a, b, c}, t = {d, e, f};
  const Vector3d ns = (b - a).cross(c - a), nt = (e - d).cross(f - d);
  if (ns.squaredNorm() == 0 || nt.squaredNorm() == 0) return false;  // degenerate: not tested
  std::array<double, 3> dt = plane_distances(s, t);
  snap_to_plane(dt, ns.norm(), s, t);
  if (strictly_one_side(dt)) return false;
  std::array<double, 3> ds = plane_distances(t, s);
  snap_to_plane(ds, nt.norm(), s, t);
  if (strictly_one_side(ds)) return false;
  const Vector3d line = ns.cross(nt);
  // Parallel planes (all distances on the plane) or planes too close to parallel for their common
  // line to be computed: the 2D test.
  if ((dt[0] == 0 && dt[1] == 0 && dt[2] == 0) || line.norm() <= kParallel * ns.norm() * nt.norm())
    return coplanar_intersect(s, t, ns);
  const std::array<double, 2> is = crossing_interval(s, ds, line);
  const std::array<double, 2> it = crossing_interval(t, dt, line);
  return is[0] <= it[1] && it[0] <= is[1];
}

SelfIntersections find_self_intersections(const Mesh& mesh, const Progress& progress) {
  const Triangles tris = fan_triangles(mesh);
  SelfIntersections result;
  if (tris.corners.empty()) return result;
  Vector3d lo = tris.box[0].lo, hi = tris.box[0].hi;
  double extent = 0.0;
  for (const Box& b : tris.box) {
    lo = lo.cwiseMin(b.lo);
    hi = hi.cwiseMax(b.hi);
    extent += (b.hi - b.lo).maxCoeff();
  }
  const double diagonal = (hi - lo).norm();
  const double cell = std::max(
      {extent / static_cast<double>(tris.box.size()), diagonal / (1 << kCellBits) * 2, 1e-300});
  const Grid grid(lo, cell);

  std::unordered_map<CellKey, std::vector<std::uint32_t>> cells;
  for (std::uint32_t i = 0; i < tris.box.size(); ++i) {
    const auto a = grid.cell_of(tris.box[i].lo), b = grid.cell_of(tris.box[i].hi);
    for (std::int64_t x = a[0]; x <= b[0]; ++x)
      for (std::int64_t y = a[1]; y <= b[1]; ++y)
        for (std::int64_t z = a[2]; z <= b[2]; ++z) cells[Grid::key({x, y, z})].push_back(i);
  }

  std::vector<bool> involved(mesh.face_count(), false);
  std::size_t visited = 0;
  for (const auto& [key, list] : cells) {
    if (++visited % 4096 == 0)
      progress.step("self-intersections", static_cast<double>(visited) / cells.size());
    for (std::size_t i = 0; i < list.size(); ++i) {
      for (std::size_t j = i + 1; j < list.size(); ++j) {
        const std::uint32_t s = list[i], t = list[j];
        if (!boxes_overlap(tris.box[s], tris.box[t])) continue;
        // Test each pair in one cell only: the cell of the corner where their boxes' overlap
        // begins.
        if (Grid::key(grid.cell_of(tris.box[s].lo.cwiseMax(tris.box[t].lo))) != key) continue;
        if (share_vertex(tris.corners[s], tris.corners[t])) continue;
        const auto& p = mesh.positions;
        const auto& cs = tris.corners[s];
        const auto& ct = tris.corners[t];
        if (!triangles_intersect(p[cs[0]], p[cs[1]], p[cs[2]], p[ct[0]], p[ct[1]], p[ct[2]]))
          continue;
        ++result.triangle_pairs;
        involved[tris.face[s]] = involved[tris.face[t]] = true;
      }
    }
  }
  for (std::size_t f = 0; f < involved.size(); ++f)
    if (involved[f]) result.faces.push_back(static_cast<Index>(f));
  return result;
}

}  // namespace tessera
