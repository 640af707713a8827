// The edge graph placed in space: the input of the tubification (thesis Sec. 9.4).
//
// Every node is a junction with a frame: a position, an in-plane direction e1 and a unit normal n
// (e2 = n x e1). Its q darts, in the order of the rotation system (next_around, i.e. S), leave the
// node in the tangent plane at the angles 2 pi k / q from e1, counterclockwise about n: the
// "well-defined plane at v" on which L, LT, LS, LST, ... appear in the group's order (Sec. 9.4,
// Fig. 9.13b). A junction reaches `reach` along each dart; there the dart's tube begins, leaving
// along the dart for an `arm` (its first Bezier control arm) before it bends on. Every edge has a
// path of waypoints its tube passes through, from its first dart's end to its second's; the path
// has an odd number of points and its middle one is the edge's midpoint, the O end in Line(G),
// where the two half tubes of the edge meet.
//
// The initial placement is the Jemisphere of Sec. 9.3 (Fig. 9.9) as build_line_graph() gives it,
// scaled so that a dart's tube is about one unit long, with each frame fitted to the directions of
// its darts' midpoints and to the outward normal of the sphere.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "regmap/line_graph.h"

namespace tessera::regmap {

// The cyclic order of the darts at each node: node_darts[v][k] is dart k of node v, slot[d] is the
// k of dart d, and prev_around inverts next_around.
// edge_darts[e] holds the two darts of edge e, the smaller first: the first dart's end is where the
// edge's path starts.
struct JunctionOrder {
  int valence = 0;
  std::vector<std::vector<std::int32_t>> node_darts;
  std::vector<int> slot;
  std::vector<std::int32_t> prev_around;
  std::vector<std::array<std::int32_t, 2>> edge_darts;
};

JunctionOrder junction_order(const EdgeGraph& graph);

struct EmbeddedGraph {
  std::vector<Eigen::Vector3d> node_position;
  std::vector<Eigen::Matrix3d> node_frame;              // columns e1, e2, n (a rotation)
  std::vector<std::vector<Eigen::Vector3d>> edge_path;  // per edge, an odd number of waypoints
  double reach = 0.0;  // from a node to the start of its darts' tubes
  double arm = 0.0;    // a tube leaves its junction straight for at least this long

  const Eigen::Vector3d& midpoint(std::size_t edge) const {
    return edge_path[edge][edge_path[edge].size() / 2];
  }
};

// The unit direction in which dart d leaves its node.
Eigen::Vector3d dart_direction(const EmbeddedGraph& embedded, const EdgeGraph& graph,
                               const JunctionOrder& order, std::int32_t dart);

// The waypoint of dart d's edge nearest to d's junction along the path.
const Eigen::Vector3d& first_waypoint(const EmbeddedGraph& embedded, const EdgeGraph& graph,
                                      const JunctionOrder& order, std::int32_t dart);

// The rotation F (det +1) minimizing sum_i w_i |F a_i - b_i|^2 (Kabsch).
Eigen::Matrix3d fit_rotation(const std::vector<Eigen::Vector3d>& a,
                             const std::vector<Eigen::Vector3d>& b,
                             const std::vector<double>& weights);

// Sets every node frame to the rotation that best carries the slot directions of its darts to
// the directions of their first waypoints, with `normal_weight` pulling n towards `normal[v]`.
void fit_junction_frames(EmbeddedGraph& embedded, const EdgeGraph& graph,
                         const JunctionOrder& order, const std::vector<Eigen::Vector3d>& normal,
                         double normal_weight);

// The Jemisphere placement of Sec. 9.3 with frames fitted to it.
EmbeddedGraph jemisphere_embedding(const EdgeGraph& graph, const JunctionOrder& order,
                                   Geometry geometry, double reach, double arm);

}  // namespace tessera::regmap
