#include "regmap/embedded_graph.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <Eigen/SVD>

#include "base/error.h"

namespace tessera::regmap {

namespace {

Eigen::Vector3d to_eigen(const Vec3& v) {
  return {v.x, v.y, v.z};
}

// The direction of slot k in a frame's own coordinates.
Eigen::Vector3d slot_direction(int k, int valence) {
  const double angle = 2.0 * std::numbers::pi * k / valence;
  return {std::cos(angle), std::sin(angle), 0.0};
}

// The median length of the darts, node to midpoint.
double median_dart_length(const EmbeddedGraph& embedded, const EdgeGraph& graph) {
  std::vector<double> lengths;
  for (std::size_t d = 0; d < graph.dart_node.size(); ++d) {
    const auto v = static_cast<std::size_t>(graph.dart_node[d]);
    const auto e = static_cast<std::size_t>(graph.dart_edge[d]);
    lengths.push_back((embedded.midpoint(e) - embedded.node_position[v]).norm());
  }
  const auto middle = lengths.begin() + static_cast<std::ptrdiff_t>(lengths.size() / 2);
  std::nth_element(lengths.begin(), middle, lengths.end());
  return *middle;
}

}  // namespace

JunctionOrder junction_order(const EdgeGraph& graph) {
  const std::size_t darts = graph.dart_node.size();
  JunctionOrder order;
  order.node_darts.resize(graph.node_count);
  order.slot.assign(darts, -1);
  order.prev_around.assign(darts, -1);
  for (std::size_t d = 0; d < darts; ++d)
    order.prev_around[static_cast<std::size_t>(graph.next_around[d])] =
        static_cast<std::int32_t>(d);
  for (std::size_t start = 0; start < darts; ++start) {
    std::vector<std::int32_t>& star =
        order.node_darts[static_cast<std::size_t>(graph.dart_node[start])];
    if (!star.empty()) continue;
    auto d = static_cast<std::int32_t>(start);
    do {
      order.slot[static_cast<std::size_t>(d)] = static_cast<int>(star.size());
      star.push_back(d);
      d = graph.next_around[static_cast<std::size_t>(d)];
    } while (d != static_cast<std::int32_t>(start));
  }
  order.valence = order.node_darts.empty() ? 0 : static_cast<int>(order.node_darts[0].size());
  order.edge_darts.assign(graph.edge_count, {-1, -1});
  for (std::size_t d = 0; d < darts; ++d) {
    auto& ends = order.edge_darts[static_cast<std::size_t>(graph.dart_edge[d])];
    (ends[0] < 0 ? ends[0] : ends[1]) = static_cast<std::int32_t>(d);
  }
  return order;
}

Eigen::Vector3d dart_direction(const EmbeddedGraph& embedded, const EdgeGraph& graph,
                               const JunctionOrder& order, std::int32_t dart) {
  const auto d = static_cast<std::size_t>(dart);
  const auto v = static_cast<std::size_t>(graph.dart_node[d]);
  return embedded.node_frame[v] * slot_direction(order.slot[d], order.valence);
}

const Eigen::Vector3d& first_waypoint(const EmbeddedGraph& embedded, const EdgeGraph& graph,
                                      const JunctionOrder& order, std::int32_t dart) {
  const auto e = static_cast<std::size_t>(graph.dart_edge[static_cast<std::size_t>(dart)]);
  const std::vector<Eigen::Vector3d>& path = embedded.edge_path[e];
  return order.edge_darts[e][0] == dart ? path.front() : path.back();
}

Eigen::Matrix3d fit_rotation(const std::vector<Eigen::Vector3d>& a,
                             const std::vector<Eigen::Vector3d>& b,
                             const std::vector<double>& weights) {
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (std::size_t i = 0; i < a.size(); ++i) covariance += weights[i] * a[i] * b[i].transpose();
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(covariance,
                                              Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d sign = Eigen::Matrix3d::Identity();
  sign(2, 2) = (svd.matrixV() * svd.matrixU().transpose()).determinant() < 0 ? -1.0 : 1.0;
  return svd.matrixV() * sign * svd.matrixU().transpose();
}

void fit_junction_frames(EmbeddedGraph& embedded, const EdgeGraph& graph,
                         const JunctionOrder& order, const std::vector<Eigen::Vector3d>& normal,
                         double normal_weight) {
  for (std::size_t v = 0; v < graph.node_count; ++v) {
    std::vector<Eigen::Vector3d> from, to;
    std::vector<double> weights;
    for (std::int32_t d : order.node_darts[v]) {
      const Eigen::Vector3d towards =
          first_waypoint(embedded, graph, order, d) - embedded.node_position[v];
      if (towards.norm() == 0.0) continue;
      from.push_back(slot_direction(order.slot[static_cast<std::size_t>(d)], order.valence));
      to.push_back(towards.normalized());
      weights.push_back(1.0);
    }
    from.push_back(Eigen::Vector3d::UnitZ());
    to.push_back(normal[v]);
    weights.push_back(normal_weight);
    embedded.node_frame[v] = fit_rotation(from, to, weights);
  }
}

EmbeddedGraph jemisphere_embedding(const EdgeGraph& graph, const JunctionOrder& order,
                                   Geometry geometry, double reach, double arm) {
  EmbeddedGraph embedded;
  embedded.reach = reach;
  embedded.arm = arm;
  for (const Vec3& p : graph.node_position) embedded.node_position.push_back(to_eigen(p));
  for (const Vec3& p : graph.edge_position) embedded.edge_path.push_back({to_eigen(p)});
  embedded.node_frame.assign(graph.node_count, Eigen::Matrix3d::Identity());
  const double length = median_dart_length(embedded, graph);
  if (!(length > 0.0))
    throw GeometryError("the Jemisphere positions of the edge graph coincide; cannot place it");
  const double scale = (reach + arm + 1.0) / length;
  for (Eigen::Vector3d& p : embedded.node_position) p *= scale;
  for (std::vector<Eigen::Vector3d>& path : embedded.edge_path) path[0] *= scale;
  // The sphere's outward normal (the plane's for torus maps) is the junction's first guess.
  std::vector<Eigen::Vector3d> normal;
  for (const Eigen::Vector3d& p : embedded.node_position)
    normal.push_back(geometry == Geometry::Euclidean || p.norm() == 0.0 ? Eigen::Vector3d::UnitZ()
                                                                        : p.normalized());
  fit_junction_frames(embedded, graph, order, normal, order.valence);
  return embedded;
}

}  // namespace tessera::regmap
