#include "regmap/bouquet_base.h"

#include <algorithm>
#include <numbers>

#include <Eigen/Geometry>

namespace tessera::regmap {

namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

bool is_bouquet(const EdgeGraph& graph, const JunctionOrder& order) {
  if (graph.node_count != 1) return false;
  const int q = order.valence;
  for (std::size_t d = 0; d < graph.dart_node.size(); ++d)
    if (order.slot[static_cast<std::size_t>(graph.opposite[d])] != (order.slot[d] + q / 2) % q)
      return false;
  return true;
}

}  // namespace

std::optional<SymmetricPlacement> bouquet_placement(const EdgeGraph& graph,
                                                    const JunctionOrder& order,
                                                    const TubeShape& shape) {
  if (!is_bouquet(graph, order)) return std::nullopt;
  SymmetricPlacement placement;
  placement.name = "bouquet";
  placement.symmetries = {
      Matrix3d::Identity(),
      Eigen::AngleAxisd(std::numbers::pi, Vector3d::UnitZ()).toRotationMatrix()};
  EmbeddedGraph& embedded = placement.embedded;
  embedded.reach = shape.reach;
  embedded.arm = shape.arm;
  embedded.node_position = {Vector3d::Zero()};
  embedded.node_frame = {Matrix3d::Identity()};
  // The arch of the loop from slot k (and k + q/2) crosses the axis at the k-th height.
  const double lowest = 2 * (shape.reach + shape.arm) + shape.clearance;
  for (std::size_t e = 0; e < graph.edge_count; ++e) {
    const auto [a, b] = order.edge_darts[e];
    const int slot =
        std::min(order.slot[static_cast<std::size_t>(a)], order.slot[static_cast<std::size_t>(b)]);
    embedded.edge_path.push_back({Vector3d(0, 0, lowest + 1.5 * shape.clearance * slot)});
  }
  return placement;
}

}  // namespace tessera::regmap
