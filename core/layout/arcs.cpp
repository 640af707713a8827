#include "layout/arcs.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "layout/trace.h"

namespace tessera::layout {
namespace {

// Where the arc starts, how far it goes and how it arrives.
struct ArcStart {
  LineCursor cursor;
  double length = 0;
  Index target = kNoIndex;  // the far singularity's vertex; kNoIndex: the arc ends at the boundary
  Index target_point = kNoIndex;  // the far singular point (graph.ports.points)
  double arrival_angle = 0;       // the unfolded angle at which the arc leaves the far end
  Eigen::Vector2d base = Eigen::Vector2d::Zero();  // the base's direction, in the cursor's chart
};

// A straight line that reaches the far singularity more than this away from the angle of its
// hypotenuse there (radians) has come in through another port's sector.
constexpr double kArrivalTolerance = std::numbers::pi / 8;

// The arc leaves the base port's singularity, or the far port's when `from_far_end`: the
// hypotenuse makes the same turn atan(height / base) with either port (LAYOUT_NOTES: s_i - s_j
// = L_base d_far - side L_height J d_far with d_far the far port's direction).
std::optional<ArcStart> arc_start(const Charts& charts, const PortGraph& graph,
                                  const GraphEdge& edge, bool from_far_end) {
  const Port& port = graph.ports.ports[from_far_end ? edge.v : edge.u];
  const SingularPoint& point = graph.ports.points[port.singular_point];
  const double turn = edge.height == 0 ? 0.0 : std::atan2(-edge.side * edge.height, edge.base);
  ArcStart start;
  start.length = std::hypot(edge.base, edge.height);
  if (edge.kind != EdgeKind::boundary) {
    const Port& far = graph.ports.ports[from_far_end ? edge.u : edge.v];
    start.target_point = far.singular_point;
    start.target = graph.ports.points[far.singular_point].ring.vertex;
    start.arrival_angle = far.angle + turn;
  }
  if (edge.height == 0) {
    start.cursor = cursor_at_corner(charts, port.corner, port.direction);
    start.base = port.direction;
    return start;
  }
  // In the port's own corner if the turned direction stays there (a flipped chart turns the
  // other way), else in the corner of its unfolded angle.
  const bool flipped = charts.signed_area(charts.connectivity.face[port.corner]) < 0;
  const double chart_turn = flipped ? -turn : turn;
  const Eigen::Vector2d d =
      std::cos(chart_turn) * port.direction + std::sin(chart_turn) * perp(port.direction);
  if (corner_contains(charts, port.corner, d)) {
    start.cursor = cursor_at_corner(charts, port.corner, d);
    start.base = port.direction;
    return start;
  }
  const double angle = port.angle + turn;
  const std::size_t k = corner_at_angle(charts, point.ring, angle);
  if (k == point.ring.corners.size()) return std::nullopt;
  start.cursor = cursor_at_corner(charts, point.ring.corners[k].corner,
                                  direction_in_corner(charts, point.ring, k, angle));
  start.base = direction_in_corner(charts, point.ring, k, port.angle);
  return start;
}

SurfacePoint exit_point(const Charts& charts, const LineStep& step) {
  if (step.vertex != kNoIndex) return {step.vertex, kNoIndex, 0};
  const Connectivity& c = charts.connectivity;
  const Index edge = c.edge[step.exit];
  return {kNoIndex, edge, c.edge_halfedge[edge] == step.exit ? step.t : 1 - step.t};
}

// The corner of face f at vertex v, or kNoIndex.
Index corner_of(const Charts& charts, Index f, Index v) {
  const Index first = charts.first_corner(f);
  for (Index h = first; h < first + 3; ++h)
    if (charts.vertex(h) == v) return h;
  return kNoIndex;
}

// True if the step passes a singularity other than the arc's ends closer than kNearSingularity:
// the hypotenuse is not straight there.
bool passes_singularity(const Charts& charts, const PortGraph& graph, const LineCursor& cursor,
                        const LineStep& step, Index start, Index target) {
  if (!(step.length > 0)) return false;
  const Eigen::Vector2d travel = (step.point - cursor.point) / step.length;
  for (Index h = charts.first_corner(cursor.face); h < charts.first_corner(cursor.face) + 3; ++h) {
    const Index v = charts.vertex(h);
    if (v == start || v == target || graph.ports.point_of_vertex[v] == kNoIndex) continue;
    const Eigen::Vector2d to = charts.uv(h) - cursor.point;
    const double along = to.dot(travel);
    if (along >= 0 && along <= step.length && std::abs(cross(travel, to)) <= kNearSingularity)
      return true;
  }
  return false;
}

// True if the line, arriving at the target in `corner` along `direction` (in the chart of that
// corner's face), leaves the target backwards at the hypotenuse's angle there.
bool arrives_along_hypotenuse(const Charts& charts, const PortGraph& graph, const ArcStart& start,
                              Index corner, const Eigen::Vector2d& direction) {
  const SingularPoint& point = graph.ports.points[start.target_point];
  for (std::size_t k = 0; k < point.ring.corners.size(); ++k) {
    if (point.ring.corners[k].corner != corner) continue;
    double d = unfolded_angle(charts, point.ring, k, -direction) - start.arrival_angle;
    if (point.cyclic()) d = std::remainder(d, point.ring.total);
    return std::abs(d) < kArrivalTolerance;
  }
  return false;
}

// The straight line from the start to its target (or to the boundary), as pieces per face; none
// if it reaches the target from another port's sector.
std::optional<std::vector<ArcPiece>> trace_straight(const Charts& charts, const PortGraph& graph,
                                                    ArcStart start) {
  LineCursor& cursor = start.cursor;
  std::vector<ArcPiece> pieces;
  const auto add = [&pieces](Index face, const SurfacePoint& from, const SurfacePoint& to,
                             const Eigen::Vector2d& from_uv, const Eigen::Vector2d& to_uv) {
    if (!(from == to)) pieces.push_back({face, from, to, from_uv, to_uv});
  };
  const Index origin = charts.vertex(cursor.entry);
  SurfacePoint from{origin, kNoIndex, 0};
  // Lengths within this of the end coincide with it (accumulated rounding along the arc).
  const double slack = 1e-6 * (1 + start.length);
  while (cursor.length <= start.length + slack) {
    if (start.target != kNoIndex) {
      const Index corner = corner_of(charts, cursor.face, start.target);
      const Eigen::Vector2d end = cursor.point + (start.length - cursor.length) * cursor.direction;
      if (corner != kNoIndex && (charts.uv(corner) - end).norm() <= slack) {
        if (!arrives_along_hypotenuse(charts, graph, start, corner, cursor.direction)) break;
        add(cursor.face, from, {start.target, kNoIndex, 0}, cursor.point, charts.uv(corner));
        return pieces;
      }
    }
    const LineStep step = line_step(charts, cursor);
    if (!step.valid || passes_singularity(charts, graph, cursor, step, origin, start.target)) break;
    const SurfacePoint to = exit_point(charts, step);
    add(cursor.face, from, to, cursor.point, step.point);
    if (start.target != kNoIndex && step.vertex == start.target)
      return arrives_along_hypotenuse(charts, graph, start,
                                      corner_of(charts, cursor.face, start.target),
                                      cursor.direction)
                 ? std::optional(pieces)
                 : std::nullopt;
    from = to;
    if (!cross_edge(charts, step, cursor)) {
      if (start.target == kNoIndex) return pieces;
      break;
    }
  }
  return std::nullopt;
}

std::vector<ArcPiece> reversed(std::vector<ArcPiece> pieces) {
  std::reverse(pieces.begin(), pieces.end());
  for (ArcPiece& piece : pieces) {
    std::swap(piece.from, piece.to);
    std::swap(piece.from_uv, piece.to_uv);
  }
  return pieces;
}

// The rotation from the start's direction to its base's. Reversing an arc traced from the far end
// turns both by a half turn, so it holds for the reversed pieces too (and the far base is parallel
// to the base).
double base_turn(const ArcStart& start) {
  const Eigen::Vector2d& d = start.cursor.direction;
  return std::atan2(cross(d, start.base), d.dot(start.base));
}

// The arc of `pieces` without the spare capacity they grew with (on dragon: 8.7 million pieces in
// the 63,000 arcs).
Arc arc_of(Index edge, std::vector<ArcPiece> pieces, double length, double turn) {
  pieces.shrink_to_fit();
  return Arc{edge, std::move(pieces), length, turn};
}

}  // namespace

// From the base port; where that fails (a folded singular ring at the start), from the far port.
std::optional<Arc> trace_arc(const Charts& charts, const PortGraph& graph, Index edge_index) {
  const GraphEdge& edge = graph.edges[edge_index];
  const double length = std::hypot(edge.base, edge.height);
  if (std::optional<ArcStart> start = arc_start(charts, graph, edge, false))
    if (std::optional<std::vector<ArcPiece>> pieces = trace_straight(charts, graph, *start))
      return arc_of(edge_index, std::move(*pieces), length, base_turn(*start));
  if (edge.kind == EdgeKind::boundary) return std::nullopt;
  if (std::optional<ArcStart> start = arc_start(charts, graph, edge, true))
    if (std::optional<std::vector<ArcPiece>> back = trace_straight(charts, graph, *start))
      return arc_of(edge_index, reversed(std::move(*back)), length, base_turn(*start));
  return std::nullopt;
}

std::vector<Arc> keep_edges_with_arcs(const Charts& charts, PortGraph& graph) {
  std::vector<Index> renumbered(graph.edges.size(), kNoIndex);
  std::vector<GraphEdge> kept;
  std::vector<Arc> arcs;
  for (Index e = 0; e < graph.edges.size(); ++e) {
    std::optional<Arc> arc = trace_arc(charts, graph, e);
    if (!arc) continue;
    renumbered[e] = static_cast<Index>(kept.size());
    arc->edge = renumbered[e];
    arcs.push_back(std::move(*arc));
    kept.push_back(graph.edges[e]);
  }
  graph.edges = std::move(kept);
  std::vector<EdgePair> pairs;
  for (const EdgePair& pair : graph.zero_area)
    if (renumbered[pair.first] != kNoIndex && renumbered[pair.second] != kNoIndex)
      pairs.push_back({renumbered[pair.first], renumbered[pair.second]});
  graph.zero_area = std::move(pairs);
  return arcs;
}

Eigen::Vector3d position_of(const Mesh& mesh, const Connectivity& connectivity,
                            const SurfacePoint& point) {
  if (point.vertex != kNoIndex) return mesh.positions[point.vertex];
  const Index h = connectivity.edge_halfedge[point.edge];
  return (1 - point.t) * mesh.positions[connectivity.from_vertex(h)] +
         point.t * mesh.positions[connectivity.to_vertex[h]];
}

std::vector<Eigen::Vector3d> arc_polyline(const Mesh& mesh, const Connectivity& connectivity,
                                          const Arc& arc) {
  std::vector<Eigen::Vector3d> polyline;
  if (arc.pieces.empty()) return polyline;
  polyline.push_back(position_of(mesh, connectivity, arc.pieces.front().from));
  for (const ArcPiece& piece : arc.pieces)
    polyline.push_back(position_of(mesh, connectivity, piece.to));
  return polyline;
}

}  // namespace tessera::layout
