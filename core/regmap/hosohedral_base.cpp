#include "regmap/hosohedral_base.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <Eigen/Geometry>

namespace tessera::regmap {

namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;
constexpr double kPi = std::numbers::pi;

// The point at cylinder coordinates (radius, azimuth, height).
Vector3d cylindrical(double radius, double azimuth, double height) {
  return {radius * std::cos(azimuth), radius * std::sin(azimuth), height};
}

// The angle in (-pi, pi] congruent to x.
double wrapped(double x) {
  x = std::remainder(x, 2 * kPi);
  return x <= -kPi ? x + 2 * kPi : x;
}

// The length unit of the placements: a dart's junction, arm and one unit of tube.
double unit_of(const TubeShape& shape) {
  return shape.reach + shape.arm + 1.0;
}

SymmetricPlacement start_placement(const char* name, const TubeShape& shape) {
  SymmetricPlacement placement;
  placement.name = name;
  placement.embedded.reach = shape.reach;
  placement.embedded.arm = shape.arm;
  placement.symmetries.push_back(Matrix3d::Identity());
  return placement;
}

// ---- One junction -----------------------------------------------------------------------------

bool is_bouquet(const EdgeGraph& graph, const JunctionOrder& order) {
  if (graph.node_count != 1) return false;
  const int q = order.valence;
  for (std::size_t d = 0; d < graph.dart_node.size(); ++d)
    if (order.slot[static_cast<std::size_t>(graph.opposite[d])] != (order.slot[d] + q / 2) % q)
      return false;
  return true;
}

SymmetricPlacement bouquet(const EdgeGraph& graph, const JunctionOrder& order,
                           const TubeShape& shape) {
  SymmetricPlacement placement = start_placement("bouquet", shape);
  EmbeddedGraph& embedded = placement.embedded;
  embedded.node_position = {Vector3d::Zero()};
  embedded.node_frame = {Matrix3d::Identity()};
  const double lowest = 2 * (shape.reach + shape.arm) + shape.clearance;
  embedded.edge_path.resize(graph.edge_count);
  for (std::size_t e = 0; e < graph.edge_count; ++e) {
    const auto [a, b] = order.edge_darts[e];
    const int slot =
        std::min(order.slot[static_cast<std::size_t>(a)], order.slot[static_cast<std::size_t>(b)]);
    embedded.edge_path[e] = {Vector3d(0, 0, lowest + 1.5 * shape.clearance * slot)};
  }
  placement.symmetries.push_back(Eigen::AngleAxisd(kPi, Vector3d::UnitZ()).toRotationMatrix());
  return placement;
}

// ---- Two junctions ----------------------------------------------------------------------------

// One edge of a dipole: its directions at the top junction (theta) and the bottom one (psi,
// azimuths about the axis) and the turn between them.
struct DipoleEdge {
  double theta = 0.0, turn = 0.0;
  int layer = 0;
};

// The bottom junction: its normal up (+1) or down (-1) and the azimuth of its first slot.
struct BottomJunction {
  double side = -1.0, azimuth = 0.0;
};

// The azimuth of slot j at the bottom junction.
double bottom_azimuth(const BottomJunction& b, int j, int q) {
  return b.azimuth + b.side * 2 * kPi * j / q;
}

bool is_dipole(const EdgeGraph& graph) {
  if (graph.node_count != 2) return false;
  for (std::size_t d = 0; d < graph.dart_node.size(); ++d)
    if (graph.dart_node[static_cast<std::size_t>(graph.opposite[d])] == graph.dart_node[d])
      return false;
  return true;
}

// The slots (top, bottom) of every edge.
std::vector<std::array<int, 2>> dipole_slots(const EdgeGraph& graph, const JunctionOrder& order) {
  std::vector<std::array<int, 2>> slots;
  for (std::size_t e = 0; e < graph.edge_count; ++e) {
    auto [a, b] = order.edge_darts[e];
    if (graph.dart_node[static_cast<std::size_t>(a)] != 0) std::swap(a, b);
    slots.push_back(
        {order.slot[static_cast<std::size_t>(a)], order.slot[static_cast<std::size_t>(b)]});
  }
  return slots;
}

BottomJunction least_turning(const std::vector<std::array<int, 2>>& slots, int q) {
  BottomJunction best;
  double least = std::numeric_limits<double>::infinity();
  for (double side : {-1.0, 1.0}) {
    for (int i = 0; i < q; ++i) {
      const BottomJunction b{side, 2 * kPi * i / q};
      double total = 0.0;
      for (const auto& [top, bottom] : slots)
        total += std::abs(wrapped(bottom_azimuth(b, bottom, q) - 2 * kPi * top / q));
      if (total < least - 1e-9) {
        least = total;
        best = b;
      }
    }
  }
  return best;
}

// The smallest angular distance of two edges on one cylinder along the height: their azimuth
// difference moves linearly from the top to the bottom.
double closest_approach(const DipoleEdge& e, const DipoleEdge& f) {
  const double top = e.theta - f.theta, bottom = top + e.turn - f.turn;
  const double lo = std::min(top, bottom), hi = std::max(top, bottom);
  if (std::floor(hi / (2 * kPi)) > std::floor(lo / (2 * kPi)) || std::fmod(lo, 2 * kPi) == 0)
    return 0.0;
  return std::min(std::abs(wrapped(top)), std::abs(wrapped(bottom)));
}

double layer_radius(int layer, double innermost, const TubeShape& shape) {
  return innermost + 1.5 * shape.clearance * layer;
}

// Each edge, in the order of the top slots, on the innermost cylinder where it keeps a clearance
// and a half from the edges already there.
void assign_layers(std::vector<DipoleEdge>& edges, double innermost, const TubeShape& shape) {
  std::vector<std::size_t> by_top(edges.size());
  for (std::size_t i = 0; i < by_top.size(); ++i) by_top[i] = i;
  std::sort(by_top.begin(), by_top.end(),
            [&](std::size_t a, std::size_t b) { return edges[a].theta < edges[b].theta; });
  std::vector<std::vector<std::size_t>> layers;
  for (std::size_t i : by_top) {
    int layer = 0;
    for (;; ++layer) {
      if (layer == static_cast<int>(layers.size())) layers.emplace_back();
      const double gap = 1.5 * shape.clearance / layer_radius(layer, innermost, shape);
      const auto& there = layers[static_cast<std::size_t>(layer)];
      if (std::all_of(there.begin(), there.end(),
                      [&](std::size_t j) { return closest_approach(edges[i], edges[j]) >= gap; }))
        break;
    }
    edges[i].layer = layer;
    layers[static_cast<std::size_t>(layer)].push_back(i);
  }
}

// Out from the top junction, round a quarter circle of radius `corner` onto the cylinder, down it
// with the turn spread over the height, round again and in to the bottom junction; an odd number
// of waypoints, dense enough on the corners for the tube to follow them, the middle one at
// height 0.
std::vector<Vector3d> dipole_path(const DipoleEdge& e, double radius, double height,
                                  double corner) {
  std::vector<Vector3d> path;
  constexpr int kCornerSteps = 3;
  for (int i = 0; i <= kCornerSteps; ++i) {
    const double alpha = kPi / 2 * i / kCornerSteps;
    path.push_back(cylindrical(radius - corner + corner * std::sin(alpha), e.theta,
                               height - corner + corner * std::cos(alpha)));
  }
  const int halves = 2 + static_cast<int>(std::ceil(4 * std::abs(e.turn) / kPi));
  for (int i = 1; i < 2 * halves; ++i) {
    const double t = static_cast<double>(i) / (2 * halves);
    path.push_back(cylindrical(radius, e.theta + t * e.turn, (height - corner) * (1 - 2 * t)));
  }
  for (int i = kCornerSteps; i >= 0; --i) {
    const double alpha = kPi / 2 * i / kCornerSteps;
    path.push_back(cylindrical(radius - corner + corner * std::sin(alpha), e.theta + e.turn,
                               corner - height - corner * std::cos(alpha)));
  }
  return path;
}

SymmetricPlacement dipole(const EdgeGraph& graph, const JunctionOrder& order,
                          const TubeShape& shape) {
  const int q = order.valence;
  const std::vector<std::array<int, 2>> slots = dipole_slots(graph, order);
  const BottomJunction bottom = least_turning(slots, q);
  std::vector<DipoleEdge> edges;
  for (const auto& [top, low] : slots) {
    const double theta = 2 * kPi * top / q;
    edges.push_back({theta, wrapped(bottom_azimuth(bottom, low, q) - theta), 0});
  }
  const double unit = unit_of(shape), corner = 0.3 * unit;
  const double innermost = shape.reach + shape.arm + corner + 0.2 * unit;
  assign_layers(edges, innermost, shape);
  int outermost = 0;
  for (const DipoleEdge& e : edges) outermost = std::max(outermost, e.layer);
  const double height = std::max(unit, 0.5 * layer_radius(outermost, innermost, shape)) + corner;

  SymmetricPlacement placement = start_placement("dipole", shape);
  EmbeddedGraph& embedded = placement.embedded;
  embedded.node_position = {Vector3d(0, 0, height), Vector3d(0, 0, -height)};
  Matrix3d low_frame;
  const Vector3d e1 = cylindrical(1.0, bottom.azimuth, 0.0), n(0, 0, bottom.side);
  low_frame << e1, n.cross(e1), n;
  embedded.node_frame = {Matrix3d::Identity(), low_frame};
  for (std::size_t e = 0; e < graph.edge_count; ++e) {
    std::vector<Vector3d> path =
        dipole_path(edges[e], layer_radius(edges[e].layer, innermost, shape), height, corner);
    // The path runs from the edge's first dart; the one at the bottom junction reverses it.
    if (graph.dart_node[static_cast<std::size_t>(order.edge_darts[e][0])] != 0)
      std::reverse(path.begin(), path.end());
    embedded.edge_path.push_back(std::move(path));
  }
  return placement;
}

}  // namespace

std::optional<SymmetricPlacement> hosohedral_placement(const EdgeGraph& graph,
                                                       const JunctionOrder& order,
                                                       const TubeShape& shape) {
  if (is_bouquet(graph, order)) return bouquet(graph, order, shape);
  if (is_dipole(graph)) return dipole(graph, order, shape);
  return std::nullopt;
}

}  // namespace tessera::regmap
