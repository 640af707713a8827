#include "regmap/spine_base.h"

#include <algorithm>
#include <cmath>
#include <limits>
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

bool has_loop(const EdgeGraph& graph) {
  for (std::size_t d = 0; d < graph.dart_node.size(); ++d)
    if (graph.dart_node[static_cast<std::size_t>(graph.opposite[d])] == graph.dart_node[d])
      return true;
  return false;
}

// ---- Junctions on the spine -------------------------------------------------------------------

// A junction's level (0 at the top), the side its normal faces (+1 up, -1 down) and the azimuth
// of its first slot; slot k lies at azimuth + side * 2 pi k / q.
struct Junction {
  int level = -1;
  double side = 1.0, azimuth = 0.0;

  double slot_azimuth(int k, int q) const { return azimuth + side * 2 * kPi * k / q; }
};

// Levels in breadth-first order from node 0, so that most tubes span few levels.
void assign_levels(const EdgeGraph& graph, std::vector<Junction>& junctions) {
  std::vector<std::vector<std::int32_t>> neighbours(graph.node_count);
  for (std::size_t d = 0; d < graph.dart_node.size(); ++d)
    neighbours[static_cast<std::size_t>(graph.dart_node[d])].push_back(
        graph.dart_node[static_cast<std::size_t>(graph.opposite[d])]);
  std::vector<std::int32_t> queue = {0};
  junctions[0].level = 0;
  for (std::size_t head = 0; head < queue.size(); ++head) {
    std::vector<std::int32_t>& next = neighbours[static_cast<std::size_t>(queue[head])];
    std::sort(next.begin(), next.end());
    for (std::int32_t w : next) {
      if (junctions[static_cast<std::size_t>(w)].level >= 0) continue;
      junctions[static_cast<std::size_t>(w)].level = static_cast<int>(queue.size());
      queue.push_back(w);
    }
  }
}

// Level by level, the side and turn (q choices each) with the least total turning of the tubes to
// the junctions above.
void turn_junctions(const EdgeGraph& graph, const JunctionOrder& order,
                    std::vector<Junction>& junctions) {
  const int q = order.valence;
  std::vector<std::size_t> by_level(graph.node_count);
  for (std::size_t v = 0; v < graph.node_count; ++v)
    by_level[static_cast<std::size_t>(junctions[v].level)] = v;
  for (std::size_t level = 1; level < by_level.size(); ++level) {
    const std::size_t v = by_level[level];
    double least = std::numeric_limits<double>::infinity();
    Junction best = junctions[v];
    for (double side : {-1.0, 1.0}) {
      for (int i = 0; i < q; ++i) {
        const Junction candidate{static_cast<int>(level), side, 2 * kPi * i / q};
        double total = 0.0;
        for (std::int32_t d : order.node_darts[v]) {
          const auto other = static_cast<std::size_t>(graph.opposite[static_cast<std::size_t>(d)]);
          const Junction& there = junctions[static_cast<std::size_t>(graph.dart_node[other])];
          if (there.level >= static_cast<int>(level)) continue;
          total +=
              std::abs(wrapped(candidate.slot_azimuth(order.slot[static_cast<std::size_t>(d)], q) -
                               there.slot_azimuth(order.slot[other], q)));
        }
        if (total < least - 1e-9) {
          least = total;
          best = candidate;
        }
      }
    }
    junctions[v] = best;
  }
}

// ---- Tubes on cylinders -----------------------------------------------------------------------

// A tube's azimuth along the height: breakpoints (height, azimuth) from its upper end down, the
// azimuth continuous (unwrapped), constant over each end's corner and each gate's band, and eased
// in between (smoothstep), so that the tube runs straight up and down where it meets a corner or a
// gate and its spline does not overshoot there.
using Profile = std::vector<std::array<double, 2>>;

double azimuth_at(const Profile& profile, double height) {
  for (std::size_t i = 0; i + 1 < profile.size(); ++i) {
    const auto [z0, a0] = profile[i];
    const auto [z1, a1] = profile[i + 1];
    if (height > z0 || height < z1) continue;
    if (z0 == z1) return a0;
    const double t = (z0 - height) / (z0 - z1);
    return a0 + (a1 - a0) * t * t * (3 - 2 * t);
  }
  return height > profile.front()[0] ? profile.front()[1] : profile.back()[1];
}

struct SpineTube {
  std::size_t edge = 0;
  bool first_dart_on_top = true;
  Profile profile;
  int layer = 0;
};

struct SpineSizes {
  double corner = 0.0, level_step = 0.0, innermost = 0.0, layer_step = 0.0;

  double height(int level) const { return -level * level_step; }
  double radius(int layer) const { return innermost + layer * layer_step; }
};

SpineSizes spine_sizes(const TubeShape& shape, int valence) {
  const double unit = shape.reach + shape.arm + 1.0;
  SpineSizes s;
  s.corner = 0.3 * unit;
  s.level_step = 2 * s.corner + 0.6 * unit;
  s.layer_step = 1.5 * shape.clearance;
  // The gap between two darts is wide enough for a tube and its clearance on every cylinder.
  s.innermost = std::max(shape.reach + shape.arm + s.corner + 0.2 * unit,
                         2 * s.layer_step * valence / (2 * kPi));
  return s;
}

// From the upper end's dart to the lower end's, through the middle of the gap nearest the straight
// turn at every level in between.
SpineTube spine_tube(std::size_t edge, const EdgeGraph& graph, const JunctionOrder& order,
                     const std::vector<Junction>& junctions, const SpineSizes& sizes) {
  const int q = order.valence;
  auto [top, bottom] = order.edge_darts[edge];
  const auto junction_of = [&](std::int32_t d) -> const Junction& {
    return junctions[static_cast<std::size_t>(graph.dart_node[static_cast<std::size_t>(d)])];
  };
  SpineTube tube;
  tube.edge = edge;
  if (junction_of(top).level > junction_of(bottom).level) {
    std::swap(top, bottom);
    tube.first_dart_on_top = false;
  }
  const Junction& upper = junction_of(top);
  const Junction& lower = junction_of(bottom);
  const double start = upper.slot_azimuth(order.slot[static_cast<std::size_t>(top)], q);
  const double turn =
      wrapped(lower.slot_azimuth(order.slot[static_cast<std::size_t>(bottom)], q) - start);
  const double z_top = sizes.height(upper.level), z_bottom = sizes.height(lower.level);
  tube.profile = {{z_top, start}, {z_top - sizes.corner, start}};
  for (int level = upper.level + 1; level < lower.level; ++level) {
    const Junction& between = *std::find_if(junctions.begin(), junctions.end(),
                                            [&](const Junction& j) { return j.level == level; });
    const double z = sizes.height(level);
    const double straight = start + turn * (z_top - z) / (z_top - z_bottom);
    // The gap centres are at half slots; the one nearest the straight turn.
    const double slots = (straight - between.azimuth) * q / (2 * kPi) * between.side;
    const double gate =
        between.slot_azimuth(0, q) + between.side * 2 * kPi * (std::floor(slots) + 0.5) / q;
    const double previous = tube.profile.back()[1];
    const double at = previous + wrapped(gate - previous);
    tube.profile.push_back({z + sizes.corner, at});
    tube.profile.push_back({z - sizes.corner, at});
  }
  const double previous = tube.profile.back()[1];
  const double end = previous + wrapped(start + turn - previous);
  tube.profile.push_back({z_bottom + sizes.corner, end});
  tube.profile.push_back({z_bottom, end});
  return tube;
}

// The least angular distance (mod 2 pi) of two tubes over the heights they share, sampled finely
// between the breakpoints of both; 0 when they cross, 2 pi when they share no height.
double closest_approach(const SpineTube& e, const SpineTube& f) {
  const double hi = std::min(e.profile.front()[0], f.profile.front()[0]);
  const double lo = std::max(e.profile.back()[0], f.profile.back()[0]);
  if (hi < lo) return 2 * kPi;
  std::vector<double> breaks = {hi, lo};
  for (const SpineTube* t : {&e, &f})
    for (const auto& [z, a] : t->profile)
      if (z < hi && z > lo) breaks.push_back(z);
  std::sort(breaks.begin(), breaks.end());
  constexpr int kSamples = 16;
  double closest = 2 * kPi, previous = 0.0;
  bool first = true;
  for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
    for (int k = 0; k <= kSamples; ++k) {
      const double z = breaks[i] + (breaks[i + 1] - breaks[i]) * k / kSamples;
      const double d = azimuth_at(e.profile, z) - azimuth_at(f.profile, z);
      if (!first && std::floor(d / (2 * kPi)) != std::floor(previous / (2 * kPi))) return 0.0;
      closest = std::min(closest, std::abs(wrapped(d)));
      previous = d;
      first = false;
    }
  }
  return closest;
}

// Each tube, longest span first, on the innermost cylinder where it keeps a clearance and a half
// from the tubes already there.
void assign_layers(std::vector<SpineTube>& tubes, const SpineSizes& sizes) {
  std::vector<std::size_t> by_span(tubes.size());
  for (std::size_t i = 0; i < by_span.size(); ++i) by_span[i] = i;
  const auto span = [&](std::size_t i) {
    return tubes[i].profile.front()[0] - tubes[i].profile.back()[0];
  };
  std::stable_sort(by_span.begin(), by_span.end(),
                   [&](std::size_t a, std::size_t b) { return span(a) > span(b); });
  std::vector<std::vector<std::size_t>> layers;
  for (std::size_t i : by_span) {
    int layer = 0;
    for (;; ++layer) {
      if (layer == static_cast<int>(layers.size())) layers.emplace_back();
      const double gap = sizes.layer_step / sizes.radius(layer);
      const auto& there = layers[static_cast<std::size_t>(layer)];
      if (std::all_of(there.begin(), there.end(),
                      [&](std::size_t j) { return closest_approach(tubes[i], tubes[j]) >= gap; }))
        break;
    }
    tubes[i].layer = layer;
    layers[static_cast<std::size_t>(layer)].push_back(i);
  }
}

// Quarter circle onto the cylinder, the profile sampled densely enough for the tube to follow its
// gates, quarter circle off it; an odd number of waypoints, from the edge's first dart.
std::vector<Vector3d> spine_path(const SpineTube& tube, const SpineSizes& sizes) {
  const double radius = sizes.radius(tube.layer), c = sizes.corner;
  const double z_top = tube.profile.front()[0], z_bottom = tube.profile.back()[0];
  const double start = tube.profile.front()[1], end = tube.profile.back()[1];
  std::vector<Vector3d> path;
  constexpr int kCornerSteps = 3;
  for (int i = 0; i <= kCornerSteps; ++i) {
    const double alpha = kPi / 2 * i / kCornerSteps;
    path.push_back(
        cylindrical(radius - c + c * std::sin(alpha), start, z_top - c + c * std::cos(alpha)));
  }
  // Steps of at most half a corner in height and a twelfth of pi in azimuth, an even number.
  const double run = (z_top - z_bottom) - 2 * c;
  double turning = 0.0;
  for (std::size_t i = 0; i + 1 < tube.profile.size(); ++i)
    turning += std::abs(tube.profile[i + 1][1] - tube.profile[i][1]);
  const double pieces = std::max(run / (c / 2), turning / (kPi / 12));
  const int steps = 2 * std::max(1, static_cast<int>(std::ceil(pieces / 2)));
  for (int i = 1; i < steps; ++i) {
    const double z = z_top - c - run * i / steps;
    path.push_back(cylindrical(radius, azimuth_at(tube.profile, z), z));
  }
  for (int i = kCornerSteps; i >= 0; --i) {
    const double alpha = kPi / 2 * i / kCornerSteps;
    path.push_back(
        cylindrical(radius - c + c * std::sin(alpha), end, z_bottom + c - c * std::cos(alpha)));
  }
  if (!tube.first_dart_on_top) std::reverse(path.begin(), path.end());
  return path;
}

}  // namespace

std::optional<SymmetricPlacement> spine_placement(const EdgeGraph& graph,
                                                  const JunctionOrder& order,
                                                  const TubeShape& shape) {
  if (graph.node_count < 2 || has_loop(graph)) return std::nullopt;
  std::vector<Junction> junctions(graph.node_count);
  assign_levels(graph, junctions);
  turn_junctions(graph, order, junctions);
  const SpineSizes sizes = spine_sizes(shape, order.valence);
  std::vector<SpineTube> tubes;
  for (std::size_t e = 0; e < graph.edge_count; ++e)
    tubes.push_back(spine_tube(e, graph, order, junctions, sizes));
  assign_layers(tubes, sizes);

  SymmetricPlacement placement;
  placement.name = "spine";
  placement.symmetries.push_back(Matrix3d::Identity());
  EmbeddedGraph& embedded = placement.embedded;
  embedded.reach = shape.reach;
  embedded.arm = shape.arm;
  for (const Junction& j : junctions) {
    embedded.node_position.push_back({0.0, 0.0, sizes.height(j.level)});
    const Vector3d e1 = cylindrical(1.0, j.azimuth, 0.0), n(0.0, 0.0, j.side);
    Matrix3d frame;
    frame << e1, n.cross(e1), n;
    embedded.node_frame.push_back(frame);
  }
  for (const SpineTube& tube : tubes) embedded.edge_path.push_back(spine_path(tube, sizes));
  return placement;
}

}  // namespace tessera::regmap
