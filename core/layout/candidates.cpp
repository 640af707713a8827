#include "layout/candidates.h"

#include <cmath>
#include <numbers>

namespace tessera::layout {
namespace {

// Lengths this close count as equal (case 3 of C1). The tolerance is the parameterization's
// accuracy, not the arithmetic's: on a symmetric mesh the lengths that should be equal differ by
// the solver's noise, and a singularity sitting on a 45-degree line must not slip through as case 1
// or 2 of its neighbour.
constexpr double kEqualLengths = 1e-6;
// Hypotenuse angles (radians) this close count as equal in the window reduction: a singularity on
// the hypotenuse of a later candidate closes the window to it.
constexpr double kEqualAngles = 1e-6;

bool nearly_equal(double a, double b) {
  return std::abs(a - b) <= kEqualLengths * std::max({1.0, a, b});
}

bool adjacent_ports(const PortGraph& graph, Index a, Index b) {
  return graph.ports.neighbour(a, 1) == b || graph.ports.neighbour(a, -1) == b;
}

}  // namespace

EdgeCollector::EdgeCollector(std::size_t line_count, double rho)
    : rho_(rho),
      // The first candidate on a side may have the full 45 degrees (Prop. 4.1).
      window_(line_count,
              {std::numbers::pi / 4 + 2 * kEqualAngles, std::numbers::pi / 4 + 2 * kEqualAngles}) {}

Index EdgeCollector::try_edge(PortGraph& graph, Index base, double base_length,
                              const Eigen::Vector2d& d_base, Index height, double height_length,
                              const Eigen::Vector2d& d_height) {
  // The far singularity s = m - L_height d_height lies on the right of the base line iff
  // cross(d_base, d_height) > 0; the edge then ends at the port after the height's, else before.
  const int side = cross(d_base, d_height) > 0 ? 1 : -1;
  double& window = window_[base][side > 0 ? 0 : 1];
  const double angle = std::atan2(height_length, base_length);
  if (angle >= window - kEqualAngles) return kNoIndex;
  window = angle;
  const Index other = graph.ports.neighbour(height, side);
  if (other == kNoIndex || other == base) return kNoIndex;
  graph.edges.push_back(crossing_edge(base, other, height, base_length, height_length, side));
  return static_cast<Index>(graph.edges.size() - 1);
}

void EdgeCollector::add_c1_edges(PortGraph& graph, const Crossing& m) {
  const bool diagonal = nearly_equal(m.length_a, m.length_b);
  Index from_a = kNoIndex, from_b = kNoIndex;
  if (diagonal || m.length_a > m.length_b)
    from_a =
        try_edge(graph, m.line_a, m.length_a, m.direction_a, m.line_b, m.length_b, m.direction_b);
  if (diagonal || m.length_b > m.length_a)
    from_b =
        try_edge(graph, m.line_b, m.length_b, m.direction_b, m.line_a, m.length_a, m.direction_a);
  if (diagonal && from_a != kNoIndex && from_b != kNoIndex) {
    graph.edges[from_a].diagonal = graph.edges[from_b].diagonal = true;
    graph.zero_area.push_back({std::min(from_a, from_b), std::max(from_a, from_b)});
  }
}

std::vector<Index> EdgeCollector::spiral_test(const PortGraph& graph, const Crossing& m) {
  const bool ordered = m.line_a < m.line_b;
  const std::pair<Index, Index> key =
      ordered ? std::pair{m.line_a, m.line_b} : std::pair{m.line_b, m.line_a};
  const std::pair<double, double> now =
      ordered ? std::pair{m.length_a, m.length_b} : std::pair{m.length_b, m.length_a};
  auto found = last_crossing_.find(key);
  std::pair<double, double> before;
  if (found != last_crossing_.end()) {
    before = found->second;
  } else if (adjacent_ports(graph, key.first, key.second)) {
    before = {0.0, 0.0};  // m0 = s_i = s_j (Sec. 6.8)
  } else {
    last_crossing_.emplace(key, now);
    return {};
  }
  last_crossing_[key] = now;
  const double grown_first = std::abs(now.first - before.first);
  const double grown_second = std::abs(now.second - before.second);
  if (grown_first > rho_ * grown_second) return {key.first};   // (6.7)
  if (grown_second > rho_ * grown_first) return {key.second};  // (6.8)
  return {};
}

std::vector<Index> EdgeCollector::on_crossing(PortGraph& graph, const Crossing& m) {
  ++graph.crossing_count;
  add_c1_edges(graph, m);
  if (m.line_a == m.line_b) return {};
  return spiral_test(graph, m);
}

void EdgeCollector::on_singularity(PortGraph& graph, Index line, Index port_hit, double length,
                                   double offset) {
  if (port_hit == kNoIndex || port_hit == line) return;
  // Both ends of a closed separatrix may be traced; it is one edge.
  if (!closed_pairs_.insert({std::min(line, port_hit), std::max(line, port_hit)}).second) return;
  GraphEdge edge;
  edge.kind = EdgeKind::singularity;
  edge.u = line;
  edge.v = port_hit;
  edge.base_line = line;
  edge.base = length;
  edge.height = std::abs(offset);
  edge.side = offset < 0 ? 1 : -1;
  graph.edges.push_back(edge);
}

void EdgeCollector::on_boundary(PortGraph& graph, Index line, double length, Index face,
                                const Eigen::Vector2d& point) {
  const Index node = static_cast<Index>(graph.node_count());
  graph.virtual_ports.push_back({line, length, face, point});
  GraphEdge edge;
  edge.kind = EdgeKind::boundary;
  edge.u = line;
  edge.v = node;
  edge.base_line = line;
  edge.base = length;
  graph.edges.push_back(edge);
}

}  // namespace tessera::layout
