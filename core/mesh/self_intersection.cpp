#include "mesh/self_intersection.h"

#include "mesh/triangle_grid.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

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

bool share_vertex(const std::array<Index, 3>& s, const std::array<Index, 3>& t) {
  for (Index a : s)
    for (Index b : t)
      if (a == b) return true;
  return false;
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
  const TriangleGrid grid(mesh);
  SelfIntersections result;
  std::vector<bool> involved(mesh.face_count(), false);
  std::size_t cells = 0;
  const auto test = [&](std::uint32_t s, std::uint32_t t) {
    const auto& cs = grid.corners[s];
    const auto& ct = grid.corners[t];
    if (share_vertex(cs, ct)) return;
    const auto& p = mesh.positions;
    if (!triangles_intersect(p[cs[0]], p[cs[1]], p[cs[2]], p[ct[0]], p[ct[1]], p[ct[2]])) return;
    ++result.triangle_pairs;
    involved[grid.face[s]] = involved[grid.face[t]] = true;
  };
  grid.for_each_overlapping_pair(test, [&](double done) {
    if (++cells % 4096 == 0) progress.step("self-intersections", done);
  });
  for (std::size_t f = 0; f < involved.size(); ++f)
    if (involved[f]) result.faces.push_back(static_cast<Index>(f));
  return result;
}

}  // namespace tessera
