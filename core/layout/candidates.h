// The edges of G found while the separatrices grow (thesis Sec. 4.1-4.4, 6.8), decided event by
// event in time order (growth.h):
//  - at an intersection m of gamma_a and gamma_b: condition C1 (cases 1-3, the ratio
//    L_b(m) / L_a(m)) with the window reduction of Prop. 4.1 (per line and side, the hypotenuse's
//    angle atan(height / base) must be below the current window, which then shrinks to it); case 3
//    adds both edges as a zero-area pair (Remark 4.2); then the spiral test (6.7), (6.8) with
//    threshold rho, the first intersection of two neighbouring ports of one singularity being the
//    singularity itself;
//  - a separatrix that runs into a singularity is a closed separatrix: an edge of height 0 to the
//    port it arrives along; one that leaves the surface gets a virtual port and an edge to it.
#pragma once

#include <array>
#include <map>
#include <set>
#include <utility>
#include <vector>

#include "layout/port_graph.h"

namespace tessera::layout {

class EdgeCollector {
 public:
  EdgeCollector(std::size_t line_count, double rho);

  // Counts m in graph.crossing_count and adds its C1 edges to graph.edges. Returns the lines the
  // spiral test stops at m.
  std::vector<Index> on_crossing(PortGraph& graph, const Crossing& m);
  // Separatrix `line` reached the singularity of port `port_hit` after `length`, passing it at the
  // signed distance `offset` (left > 0): the edge's base and height.
  void on_singularity(PortGraph& graph, Index line, Index port_hit, double length, double offset);
  // Separatrix `line` left the surface after `length` at `point` of `face`.
  void on_boundary(PortGraph& graph, Index line, double length, Index face,
                   const Eigen::Vector2d& point);

 private:
  Index try_edge(PortGraph& graph, Index base, double base_length, const Eigen::Vector2d& d_base,
                 Index height, double height_length, const Eigen::Vector2d& d_height);
  void add_c1_edges(PortGraph& graph, const Crossing& m);
  std::vector<Index> spiral_test(const PortGraph& graph, const Crossing& m);

  double rho_;
  std::vector<std::array<double, 2>> window_;  // per line: right side, left side (radians)
  std::map<std::pair<Index, Index>, std::pair<double, double>> last_crossing_;
  std::set<std::pair<Index, Index>> closed_pairs_;
};

}  // namespace tessera::layout
