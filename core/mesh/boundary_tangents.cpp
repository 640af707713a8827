#include "mesh/boundary_tangents.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "mesh/geometry.h"
#include "mesh/topology.h"

namespace tessera {
namespace {

constexpr double kChordEdges = 4;
constexpr double kCornerDegrees = 55;
constexpr double kVertexDegrees = 45;

// The median length of the boundary edges: the layout's refinement splits only the few where arcs
// end on the boundary, so that chords of a multiple of it span the same stretch of boundary on the
// refined mesh as on the input.
double median_boundary_edge_length(const Mesh& mesh, const Connectivity& c) {
  std::vector<double> length;
  for (Index e = 0; e < c.edge_count(); ++e) {
    if (!c.is_boundary_edge(e)) continue;
    const Index h = c.edge_halfedge[e];
    length.push_back((mesh.positions[c.to_vertex[h]] - mesh.positions[c.from_vertex(h)]).norm());
  }
  if (length.empty()) return 0;
  std::nth_element(length.begin(), length.begin() + length.size() / 2, length.end());
  return length[length.size() / 2];
}

// One boundary loop's vertices p (edge i runs from p[i] to p[i + 1]) and how far a chord reaches.
struct Loop {
  std::vector<Eigen::Vector3d> p;
  std::vector<double> edge_length;
  double reach = 0;       // arc length a chord spans beyond its start
  std::size_t steps = 0;  // at most this many edges: a chord may not wrap round a short loop
  std::size_t size() const { return p.size(); }
  std::size_t step(std::size_t i, int dir) const {
    return dir < 0 ? (i + size() - 1) % size() : (i + 1) % size();
  }
  double length_to(std::size_t i, int dir) const { return edge_length[dir < 0 ? step(i, dir) : i]; }

  // The vertices after i walking back (dir = -1) or ahead (+1) within `reach` of it, at most
  // `steps` of them.
  std::size_t vertices_within(std::size_t i, int dir) const {
    std::size_t k = 0;
    for (double walked = 0; k < steps && (walked += length_to(i, dir)) < reach; ++k)
      i = step(i, dir);
    return k;
  }

  // The point `reach` along the loop from vertex i, back (dir = -1) or ahead (+1), or the corner
  // (or the `steps`-th vertex) that comes first. A point on the polyline, not its nearest vertex:
  // a vertex added on an edge (the layout's refinement adds them where arcs end on the boundary)
  // moves no chord.
  Eigen::Vector3d chord_end(std::size_t i, int dir, const std::vector<std::uint8_t>& corner) const {
    double walked = 0;
    for (std::size_t k = 0; k < steps && !corner[i]; ++k) {
      const std::size_t next = step(i, dir);
      const double length = length_to(i, dir);
      if (walked + length >= reach) return p[i] + (reach - walked) / length * (p[next] - p[i]);
      walked += length;
      i = next;
    }
    return p[i];
  }
};

// How far the boundary turns at vertex v on the surface (its geodesic turn): pi minus its surface
// angle (the sum of its corner angles), positive where the surface is convex.
double vertex_turn(const Mesh& mesh, const Connectivity& c, Index v) {
  double angle = 0;
  for (Index h : outgoing_halfedges(c, v))
    if (!c.is_boundary_halfedge(h)) angle += corner_angle(mesh, c, h);
  return std::numbers::pi - angle;
}

// The turns within a chord's reach of each vertex, weighted by 1 - distance / reach: the steps of a
// staircase turn by alternately +60 and -60 degrees or so and cancel, a corner keeps its turn, a
// curve adds what it turns within the reach.
std::vector<double> smoothed_turns(const Loop& loop, const std::vector<double>& turn) {
  const std::size_t n = loop.size();
  std::vector<double> smoothed(turn);
  for (std::size_t i = 0; i < n; ++i) {
    for (const int dir : {-1, +1}) {
      double walked = 0;
      for (std::size_t k = 0, j = i; k < loop.steps; ++k) {
        walked += loop.length_to(j, dir);
        j = loop.step(j, dir);
        if (walked >= loop.reach) break;
        smoothed[i] += (1 - walked / loop.reach) * turn[j];
      }
    }
  }
  return smoothed;
}

// Corners: vertices that turn by more than kVertexDegrees themselves and by more than
// kCornerDegrees smoothed (smoothed_turns()), the largest smoothed turn among such vertices within
// a chord's reach (ties: both, as at the ends of a short side).
std::vector<std::uint8_t> loop_corners(const Loop& loop, const std::vector<double>& turn) {
  const std::size_t n = loop.size();
  const std::vector<double> smoothed = smoothed_turns(loop, turn);
  std::vector<std::uint8_t> candidate(n, 0), corner(n, 0);
  for (std::size_t i = 0; i < n; ++i)
    candidate[i] = std::abs(smoothed[i]) > kCornerDegrees * std::numbers::pi / 180 &&
                   std::abs(turn[i]) > kVertexDegrees * std::numbers::pi / 180;
  for (std::size_t i = 0; i < n; ++i) {
    if (!candidate[i]) continue;
    bool peak = true;
    for (std::size_t k = 1, j = i, m = loop.vertices_within(i, -1); k <= m && peak; ++k) {
      j = loop.step(j, -1);
      peak = !candidate[j] || std::abs(smoothed[i]) >= std::abs(smoothed[j]);
    }
    for (std::size_t k = 1, j = i, m = loop.vertices_within(i, +1); k <= m && peak; ++k) {
      j = loop.step(j, +1);
      peak = !candidate[j] || std::abs(smoothed[i]) >= std::abs(smoothed[j]);
    }
    corner[i] = peak;
  }
  return corner;
}

}  // namespace

BoundaryTangents boundary_tangents(const Mesh& mesh, const Connectivity& c) {
  BoundaryTangents out;
  out.edge_tangent.assign(c.edge_count(), Eigen::Vector3d::Zero());
  out.corner.assign(c.vertex_count(), 0);
  const double reach = kChordEdges * median_boundary_edge_length(mesh, c);
  for (const std::vector<Index>& halfedges : boundary_loops(c)) {
    const std::size_t n = halfedges.size();
    // Loop vertex i is where boundary halfedge i starts.
    Loop loop;
    loop.reach = reach;
    loop.steps = (n - 1) / 4;
    for (std::size_t i = 0; i < n; ++i)
      loop.p.push_back(mesh.positions[c.from_vertex(halfedges[i])]);
    for (std::size_t i = 0; i < n; ++i)
      loop.edge_length.push_back((loop.p[(i + 1) % n] - loop.p[i]).norm());
    std::vector<double> turn_at_vertex(n);
    for (std::size_t i = 0; i < n; ++i)
      turn_at_vertex[i] = vertex_turn(mesh, c, c.from_vertex(halfedges[i]));
    const std::vector<std::uint8_t> corner = loop_corners(loop, turn_at_vertex);
    for (std::size_t i = 0; i < n; ++i) {
      if (corner[i]) out.corner[c.from_vertex(halfedges[i])] = 1;
      Eigen::Vector3d chord =
          loop.chord_end((i + 1) % n, +1, corner) - loop.chord_end(i, -1, corner);
      if (!(chord.norm() > 0)) chord = loop.p[(i + 1) % n] - loop.p[i];
      out.edge_tangent[c.edge[halfedges[i]]] = chord.normalized();
    }
  }
  return out;
}

}  // namespace tessera
