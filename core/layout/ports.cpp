#include "layout/ports.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "layout/trace.h"
#include "mesh/topology.h"
#include "param/poisson.h"

namespace tessera::layout {
namespace {

constexpr double kQuarter = std::numbers::pi / 2;
constexpr double kAngleTolerance = 1e-9;

double angle_between(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return std::atan2(cross(a, b), a.dot(b));
}

Eigen::Vector2d first_edge(const Charts& charts, Index corner) {
  return charts.uv(charts.connectivity.next[corner]) - charts.uv(corner);
}

Eigen::Vector2d nearest_axis(const Eigen::Vector2d& d) {
  if (std::abs(d.x()) >= std::abs(d.y())) return {d.x() >= 0 ? 1.0 : -1.0, 0.0};
  return {0.0, d.y() >= 0 ? 1.0 : -1.0};
}

// Brings an angle of an interior vertex's cone into [start of the ring, start + cone).
double into_cone(const VertexRing& ring, double angle) {
  if (ring.boundary || ring.corners.empty() || !(ring.total > 0)) return angle;
  const double low = ring.corners.front().start - kAngleTolerance;
  return angle - std::floor((angle - low) / ring.total) * ring.total;
}

bool contains_at(const Charts& charts, const VertexRing& ring, std::size_t k, double angle,
                 bool axis) {
  if (k >= ring.corners.size()) return false;
  Eigen::Vector2d d = direction_in_corner(charts, ring, k, angle);
  if (axis) d = nearest_axis(d);
  return corner_contains(charts, ring.corners[k].corner, d);
}

std::size_t corner_for(const Charts& charts, const VertexRing& ring, double angle, bool axis) {
  angle = into_cone(ring, angle);
  const std::size_t n = ring.corners.size();
  for (std::size_t k = 0; k < n; ++k) {
    const RingCorner& c = ring.corners[k];
    if (!(c.angle > 0)) continue;
    if (angle < c.start - kAngleTolerance || angle >= c.start + c.angle - kAngleTolerance) continue;
    // At a corner's edge the orientation test decides; it may pick the neighbouring corner.
    for (std::size_t candidate : {k, k + 1, k + n - 1}) {
      const std::size_t j = ring.boundary ? candidate : candidate % n;
      if (contains_at(charts, ring, j, angle, axis)) return j;
    }
  }
  return n;
}

// True if `d` runs along the boundary edge that starts the first corner of a boundary ring or
// ends its last corner.
bool along_boundary_edge(const Charts& charts, const VertexRing& ring, std::size_t k,
                         const Eigen::Vector2d& d) {
  const Index corner = ring.corners[k].corner;
  const auto along = [&d](const Eigen::Vector2d& edge) {
    return std::abs(angle_between(edge, d)) < 1e-6;
  };
  if (k == 0 && along(first_edge(charts, corner))) return true;
  const Eigen::Vector2d last = charts.uv(charts.connectivity.prev[corner]) - charts.uv(corner);
  return k + 1 == ring.corners.size() && along(last);
}

// The isoline directions leaving the vertex inside ring corner k: the axis directions of its chart
// whose ray crosses the far edge (backwards in a flipped chart), in the order the surface turns
// through them. In an unfolded ring every axis direction of the cone lies in exactly one corner.
void add_corner_ports(const Charts& charts, Index point_index, std::size_t k, Ports& result) {
  SingularPoint& point = result.points[point_index];
  const RingCorner& corner = point.ring.corners[k];
  const Eigen::Vector2d e1 = first_edge(charts, corner.corner);
  std::vector<std::pair<double, Eigen::Vector2d>> found;
  for (int turn = 0; turn < 4; ++turn) {
    const Eigen::Vector2d d = quarter_turns({1, 0}, turn);
    if (!corner_contains(charts, corner.corner, d)) continue;
    const double angle = angle_between(e1, d);
    // On the boundary the directions along the two boundary edges are not ports (Sec. 4.4).
    if (point.ring.boundary && along_boundary_edge(charts, point.ring, k, d)) continue;
    found.push_back({angle, d});
  }
  const bool flipped = charts.signed_area(charts.connectivity.face[corner.corner]) < 0;
  std::sort(found.begin(), found.end(), [flipped](const auto& a, const auto& b) {
    return flipped ? a.first > b.first : a.first < b.first;
  });
  for (const auto& [angle, d] : found) {
    Port port;
    port.singular_point = point_index;
    port.number = static_cast<int>(point.ports.size());
    port.angle = corner.start + angle;
    port.corner = corner.corner;
    port.direction = d;
    port.folded = flipped;
    point.ports.push_back(static_cast<Index>(result.ports.size()));
    result.ports.push_back(port);
  }
}

// Gives the missing full turns to the ring's first flipped corner (see vertex_ring()).
void sweep_flipped_corner(VertexRing& ring, double cone_angle) {
  const double missing =
      std::round((cone_angle - ring.total) / (2 * std::numbers::pi)) * 2 * std::numbers::pi;
  if (missing == 0) return;
  double shift = 0;
  for (RingCorner& corner : ring.corners) {
    corner.start += shift;
    if (shift == 0 && corner.angle < 0) {
      corner.angle += missing;
      shift = missing;
    }
  }
  ring.total += shift;
}

}  // namespace

VertexRing vertex_ring(const Charts& charts, Index vertex, double cone_angle) {
  const Connectivity& c = charts.connectivity;
  VertexRing ring;
  ring.vertex = vertex;
  ring.boundary = c.is_boundary_vertex(vertex);
  double start = 0;
  for (Index h : outgoing_halfedges(c, vertex)) {
    if (c.is_boundary_halfedge(h)) continue;
    const Eigen::Vector2d e1 = first_edge(charts, h);
    const Eigen::Vector2d e2 = charts.uv(c.prev[h]) - charts.uv(h);
    if (ring.corners.empty()) start = std::atan2(e1.y(), e1.x());
    const double angle = angle_between(e1, e2);
    ring.corners.push_back({h, start, angle});
    start += angle;
    ring.total += angle;
  }
  sweep_flipped_corner(ring, cone_angle);
  return ring;
}

Eigen::Vector2d direction_in_corner(const Charts& charts, const VertexRing& ring, std::size_t k,
                                    double angle) {
  const RingCorner& corner = ring.corners[k];
  const Eigen::Vector2d e1 = first_edge(charts, corner.corner).normalized();
  const double turn = angle - corner.start;
  return std::cos(turn) * e1 + std::sin(turn) * perp(e1);
}

double unfolded_angle(const Charts& charts, const VertexRing& ring, std::size_t k,
                      const Eigen::Vector2d& direction) {
  const RingCorner& corner = ring.corners[k];
  return corner.start + angle_between(first_edge(charts, corner.corner), direction);
}

std::size_t corner_at_angle(const Charts& charts, const VertexRing& ring, double angle) {
  return corner_for(charts, ring, angle, false);
}

Index Ports::neighbour(Index port, int step) const {
  const Port& p = ports[port];
  const SingularPoint& point = points[p.singular_point];
  const int n = static_cast<int>(point.ports.size());
  int k = p.number + step;
  if (point.cyclic()) {
    k = ((k % n) + n) % n;
  } else if (k < 0 || k >= n) {
    return kNoIndex;
  }
  return point.ports[k];
}

Index Ports::nearest_port(Index point_index, double angle) const {
  const SingularPoint& point = points[point_index];
  Index nearest = kNoIndex;
  double distance = std::numbers::pi / 4;  // beyond this no port is near
  for (Index port : point.ports) {
    double d = angle - ports[port].angle;
    if (point.cyclic()) d = std::remainder(d, point.ring.total);
    if (std::abs(d) < distance) {
      distance = std::abs(d);
      nearest = port;
    }
  }
  return nearest;
}

namespace {

// The vertex half way along a boundary loop (by length) from its first vertex.
Index halfway_round(const Mesh& mesh, const Connectivity& c, const std::vector<Index>& loop) {
  const auto length = [&](Index h) {
    return (mesh.positions[c.to_vertex[h]] - mesh.positions[c.from_vertex(h)]).norm();
  };
  double total = 0;
  for (Index h : loop) total += length(h);
  double walked = 0;
  for (Index h : loop)
    if ((walked += length(h)) >= total / 2) return c.to_vertex[h];
  return c.to_vertex[loop.back()];
}

// Stand-in nodes: a component with boundary but no singularity (an annulus whose field runs along
// both boundaries, index sum 0) gives no separatrix to grow, and its layout would be the annulus
// itself. Two regular vertices half way round its first boundary loop from each other stand in as
// nodes of valence 2: each has the one port of a regular boundary vertex, into the surface, and
// their two separatrices cut the annulus into two patches.
std::vector<Singularity> stand_in_nodes(const Charts& charts) {
  const Connectivity& c = charts.connectivity;
  const Components components = connected_components(charts.mesh, c);
  std::vector<std::uint8_t> has_singularity(components.count, 0);
  for (const Singularity& s : charts.param.singularities)
    has_singularity[components.vertex_component[s.vertex]] = 1;
  std::vector<Singularity> stand_ins;
  for (const std::vector<Index>& loop : boundary_loops(c)) {
    const Index first = c.from_vertex(loop.front());
    const Index component = components.vertex_component[first];
    if (has_singularity[component] || loop.size() < 4) continue;
    has_singularity[component] = 1;  // one loop's pair per component
    stand_ins.push_back({first, 0.0, 2});
    stand_ins.push_back({halfway_round(charts.mesh, c, loop), 0.0, 2});
  }
  return stand_ins;
}

void add_point(const Charts& charts, const Singularity& s, Ports& result) {
  const Index index = static_cast<Index>(result.points.size());
  result.point_of_vertex[s.vertex] = index;
  result.points.push_back({vertex_ring(charts, s.vertex, s.valence * kQuarter), s.valence, {}});
  for (std::size_t k = 0; k < result.points[index].ring.corners.size(); ++k)
    add_corner_ports(charts, index, k, result);
}

}  // namespace

Ports find_ports(const Charts& charts) {
  Ports result;
  result.point_of_vertex.assign(charts.mesh.vertex_count(), kNoIndex);
  for (const Singularity& s : charts.param.singularities) add_point(charts, s, result);
  for (const Singularity& s : stand_in_nodes(charts)) add_point(charts, s, result);
  return result;
}

}  // namespace tessera::layout
