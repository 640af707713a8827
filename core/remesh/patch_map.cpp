#include "remesh/patch_map.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <queue>
#include <string>

#include "base/error.h"
#include "layout/charts.h"
#include "mesh/geometry.h"
#include "param/poisson.h"

namespace tessera::remesh {
namespace {

using Eigen::Vector2d;
using Eigen::Vector3d;

// The corner halfedge from a to b (in a face), or its twin's face's if a -> b is on the boundary.
Index halfedge_between(const Connectivity& c, Index a, Index b) {
  for (Index h : outgoing_halfedges(c, a))
    if (c.to_vertex[h] == b) return h;
  throw Error("remesh: the refined mesh has no edge from vertex " + std::to_string(a) +
              " to vertex " + std::to_string(b));
}

double parametric_length(const layout::RefinedMesh& refined, const Connectivity& c, Index a,
                         Index b) {
  Index h = halfedge_between(c, a, b);
  if (c.is_boundary_halfedge(h)) h = c.twin[h];
  const Index f = c.face[h];
  return (refined.uv[refined.mesh.next_corner(h, f)] - refined.uv[h]).norm();
}

Vector3d face_normal_at(const layout::RefinedMesh& refined, const Connectivity& c, Index a,
                        Index b) {
  Index h = halfedge_between(c, a, b);
  if (c.is_boundary_halfedge(h)) h = c.twin[h];
  return face_normal(refined.mesh, c.face[h]).normalized();
}

// A rigid motion of the plane by quarter turns: x -> J^r x + t.
struct ChartMotion {
  int r = 0;
  Vector2d t = Vector2d::Zero();
  Vector2d operator()(const Vector2d& x) const { return quarter_turns(x, r) + t; }
};

// The motion taking the chart of face(twin h) to the patch chart, given face(h)'s: the shared edge
// must land on itself. The turn is a multiple of 90 degrees (the transitions are J^r p + t).
ChartMotion motion_across(const layout::RefinedMesh& refined, const Connectivity& c, Index h,
                          const ChartMotion& here) {
  const Mesh& mesh = refined.mesh;
  const Index t = c.twin[h];
  const Vector2d pa = here(refined.uv[h]);
  const Vector2d pb = here(refined.uv[mesh.next_corner(h, c.face[h])]);
  const Vector2d qb = refined.uv[t];
  const Vector2d qa = refined.uv[mesh.next_corner(t, c.face[t])];
  const Vector2d p = pb - pa, q = qb - qa;
  const double turn = std::atan2(layout::cross(q, p), q.dot(p));
  ChartMotion motion;
  motion.r = ((static_cast<int>(std::lround(turn / (M_PI / 2))) % 4) + 4) % 4;
  motion.t = pa - quarter_turns(qa, motion.r);
  return motion;
}

// Per corner of the patch's faces its uv in one chart of the whole patch (breadth-first from the
// first face).
std::map<Index, Vector2d> unfold_patch(const layout::RefinedMesh& refined, const Connectivity& c,
                                       const std::vector<Index>& faces) {
  const Mesh& mesh = refined.mesh;
  std::map<Index, ChartMotion> motion;
  std::queue<Index> open;
  motion[faces.front()] = {};
  open.push(faces.front());
  const std::vector<std::int32_t>& patch = mesh.face_attributes.at("patch");
  while (!open.empty()) {
    const Index f = open.front();
    open.pop();
    for (Index h = mesh.face_offsets[f]; h < mesh.face_offsets[f + 1]; ++h) {
      const Index g = c.face[c.twin[h]];
      if (g == kNoIndex || patch[g] != patch[f] || motion.count(g)) continue;
      motion[g] = motion_across(refined, c, h, motion[f]);
      open.push(g);
    }
  }
  std::map<Index, Vector2d> uv;
  for (const auto& [f, m] : motion)
    for (Index h = mesh.face_offsets[f]; h < mesh.face_offsets[f + 1]; ++h)
      uv.emplace(mesh.face_vertices[h], m(refined.uv[h]));
  return uv;
}

double signed_area(const Vector2d& a, const Vector2d& b, const Vector2d& x) {
  return 0.5 * layout::cross(b - a, x - a);
}

Vector3d barycentric(const Vector2d& a, const Vector2d& b, const Vector2d& c, const Vector2d& x) {
  const double area = signed_area(a, b, c);
  return Vector3d(signed_area(b, c, x), signed_area(c, a, x), signed_area(a, b, x)) / area;
}

struct MappedTriangle {
  Index face = 0;
  std::array<Vector2d, 3> rect;  // the corners in the rectangle
};

SurfaceSample sample(const layout::RefinedMesh& refined, const MappedTriangle& t,
                     const Vector3d& weight) {
  const Mesh& mesh = refined.mesh;
  const auto corners = mesh.face(t.face);
  SurfaceSample s;
  for (int k = 0; k < 3; ++k) s.position += weight[k] * mesh.positions[corners[k]];
  s.normal = face_normal(mesh, t.face).normalized();
  return s;
}

// The barycentric weights of x clamped into the triangle, and how far outside it x was (0 inside).
double clamp_into(Vector3d& w) {
  const double outside = -std::min(0.0, w.minCoeff());
  w = w.cwiseMax(0.0);
  w /= w.sum();
  return outside;
}

}  // namespace

Eigen::Vector4d wachspress(const std::array<Vector2d, 4>& q, const Vector2d& x) {
  Eigen::Vector4d w;
  for (int i = 0; i < 4; ++i) {
    const Vector2d& before = q[(i + 3) % 4];
    const Vector2d& after = q[(i + 1) % 4];
    const Vector2d& opposite = q[(i + 2) % 4];
    w[i] = signed_area(before, q[i], after) * signed_area(x, after, opposite) *
           signed_area(x, opposite, before);
  }
  return w / w.sum();
}

SideTrack side_track(const layout::RefinedMesh& refined, const Connectivity& connectivity,
                     const LayoutSide& side) {
  const std::vector<Index>& v = side.vertices;
  SideTrack track;
  track.at.push_back(0);
  for (std::size_t k = 0; k + 1 < v.size(); ++k) {
    track.at.push_back(track.at.back() + parametric_length(refined, connectivity, v[k], v[k + 1]));
    track.normal.push_back(face_normal_at(refined, connectivity, v[k], v[k + 1]));
  }
  return track;
}

double side_length_3d(const layout::RefinedMesh& refined, const LayoutSide& side) {
  const std::vector<Index>& v = side.vertices;
  double length = 0;
  for (std::size_t k = 0; k + 1 < v.size(); ++k)
    length += (refined.mesh.positions[v[k + 1]] - refined.mesh.positions[v[k]]).norm();
  return length;
}

std::vector<SurfaceSample> side_points(const layout::RefinedMesh& refined, const LayoutSide& side,
                                       const SideTrack& track, int segments) {
  const std::vector<Index>& v = side.vertices;
  const std::vector<double>& at = track.at;
  std::vector<SurfaceSample> points;
  std::size_t k = 0;
  for (int i = 0; i <= segments; ++i) {
    const double s = at.back() * i / segments;
    while (k + 2 < v.size() && at[k + 1] < s) ++k;
    const double span = at[k + 1] - at[k];
    const double t = span > 0 ? std::clamp((s - at[k]) / span, 0.0, 1.0) : 0.0;
    const Vector3d& a = refined.mesh.positions[v[k]];
    const Vector3d& b = refined.mesh.positions[v[k + 1]];
    points.push_back({(1 - t) * a + t * b, track.normal[k]});
  }
  points.front().position = refined.mesh.positions[v.front()];
  points.back().position = refined.mesh.positions[v.back()];
  return points;
}

PatchChart patch_chart(const layout::RefinedMesh& refined, const Connectivity& connectivity,
                       const std::vector<Index>& faces, const std::vector<Index>& corners) {
  const std::map<Index, Vector2d> uv = unfold_patch(refined, connectivity, faces);
  const std::array<Vector2d, 4> quad{uv.at(corners[0]), uv.at(corners[1]), uv.at(corners[2]),
                                     uv.at(corners[3])};
  PatchChart chart;
  chart.faces = faces;
  std::map<Index, std::uint32_t> local;
  for (const auto& [v, x] : uv) {
    local[v] = static_cast<std::uint32_t>(chart.weights.size());
    chart.weights.push_back(wachspress(quad, x));
  }
  for (Index f : faces) {
    const auto c = refined.mesh.face(f);
    chart.local.push_back({local.at(c[0]), local.at(c[1]), local.at(c[2])});
  }
  return chart;
}

std::vector<SurfaceSample> patch_interior_points(const layout::RefinedMesh& refined,
                                                 const PatchChart& chart, int n, int m,
                                                 std::size_t& unlocated) {
  const std::array<Vector2d, 4> rect{Vector2d(0, 0), Vector2d(n, 0), Vector2d(n, m),
                                     Vector2d(0, m)};
  std::vector<Vector2d> in_rect;
  in_rect.reserve(chart.weights.size());
  for (const Eigen::Vector4d& w : chart.weights) {
    Vector2d y = Vector2d::Zero();
    for (int i = 0; i < 4; ++i) y += w[i] * rect[i];
    in_rect.push_back(y);
  }
  std::vector<MappedTriangle> triangles;
  triangles.reserve(chart.faces.size());
  for (std::size_t k = 0; k < chart.faces.size(); ++k) {
    const auto& c = chart.local[k];
    triangles.push_back({chart.faces[k], {in_rect[c[0]], in_rect[c[1]], in_rect[c[2]]}});
  }
  const int columns = n - 1, rows = m - 1;
  std::vector<SurfaceSample> points(std::size_t(std::max(0, columns)) * std::max(0, rows));
  std::vector<bool> found(points.size(), false);
  for (const MappedTriangle& t : triangles) {
    if (!(std::abs(signed_area(t.rect[0], t.rect[1], t.rect[2])) > 0)) continue;
    Eigen::AlignedBox2d box;
    for (const Vector2d& x : t.rect) box.extend(x);
    const int i0 = std::max(1, int(std::ceil(box.min().x()))),
              i1 = std::min(n - 1, int(box.max().x()));
    const int j0 = std::max(1, int(std::ceil(box.min().y()))),
              j1 = std::min(m - 1, int(box.max().y()));
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) {
        const std::size_t k = std::size_t(i - 1) + std::size_t(j - 1) * columns;
        if (found[k]) continue;
        Vector3d w = barycentric(t.rect[0], t.rect[1], t.rect[2], Vector2d(i, j));
        if (w.minCoeff() < -1e-9) continue;
        clamp_into(w);
        points[k] = sample(refined, t, w);
        found[k] = true;
      }
  }
  unlocated = 0;
  for (std::size_t k = 0; k < points.size(); ++k) {
    if (found[k]) continue;
    ++unlocated;
    const Vector2d x(double(k % columns + 1), double(k / columns + 1));
    double best = std::numeric_limits<double>::infinity();
    for (const MappedTriangle& t : triangles) {
      if (!(std::abs(signed_area(t.rect[0], t.rect[1], t.rect[2])) > 0)) continue;
      Vector3d w = barycentric(t.rect[0], t.rect[1], t.rect[2], x);
      const double outside = clamp_into(w);
      if (outside < best) {
        best = outside;
        points[k] = sample(refined, t, w);
      }
    }
  }
  return points;
}

}  // namespace tessera::remesh
