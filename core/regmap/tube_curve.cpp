#include "regmap/tube_curve.h"

#include <algorithm>

namespace tessera::regmap {

using Eigen::Vector3d;

Vector3d Bezier::at(double t) const {
  const double s = 1 - t;
  return s * s * s * p[0] + 3 * s * s * t * p[1] + 3 * s * t * t * p[2] + t * t * t * p[3];
}

Vector3d Bezier::derivative(double t) const {
  const double s = 1 - t;
  return 3 * s * s * (p[1] - p[0]) + 6 * s * t * (p[2] - p[1]) + 3 * t * t * (p[3] - p[2]);
}

Vector3d unit_or(const Vector3d& v, const Vector3d& fallback) {
  return v.norm() > 1e-12 ? Vector3d(v.normalized()) : fallback;
}

std::vector<Bezier> edge_centreline(const EmbeddedGraph& embedded, const EdgeGraph& graph,
                                    const JunctionOrder& order, std::size_t edge) {
  constexpr double kHandle = 0.4;
  const auto [dart_a, dart_b] = order.edge_darts[edge];
  const Vector3d a = dart_direction(embedded, graph, order, dart_a);
  const Vector3d b = dart_direction(embedded, graph, order, dart_b);
  const auto node = [&](std::int32_t d) -> const Vector3d& {
    return embedded
        .node_position[static_cast<std::size_t>(graph.dart_node[static_cast<std::size_t>(d)])];
  };
  std::vector<Vector3d> knots = {node(dart_a) + embedded.reach * a};
  const std::vector<Vector3d>& path = embedded.edge_path[edge];
  knots.insert(knots.end(), path.begin(), path.end());
  knots.push_back(node(dart_b) + embedded.reach * b);
  const std::size_t last = knots.size() - 1;
  std::vector<Vector3d> tangent(knots.size());
  tangent.front() = a;
  tangent.back() = -b;
  for (std::size_t i = 1; i < last; ++i)
    tangent[i] = unit_or(knots[i + 1] - knots[i - 1], unit_or(knots[i + 1] - knots[i], a));
  std::vector<Bezier> arcs;
  for (std::size_t i = 0; i < last; ++i) {
    const double chord = (knots[i + 1] - knots[i]).norm();
    const double out = i == 0 ? std::min(embedded.arm, chord) : kHandle * chord;
    const double in = i + 1 == last ? std::min(embedded.arm, chord) : kHandle * chord;
    arcs.push_back(Bezier{
        {knots[i], knots[i] + out * tangent[i], knots[i + 1] - in * tangent[i + 1], knots[i + 1]}});
  }
  return arcs;
}

}  // namespace tessera::regmap
