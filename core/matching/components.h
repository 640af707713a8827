// Independent components of P1: nodes joined by an edge, and the ends of two edges in a conflict
// pair, belong to one component; the components are solved one by one and their optima add up.
#pragma once

#include <cstdint>
#include <vector>

#include "matching/adjacency.h"
#include "matching/problem.h"

namespace tessera::matching {

struct Component {
  MatchingProblem problem;             // nodes, edges and conflicts renumbered from 0
  std::vector<std::uint32_t> node_of;  // its node i is node node_of[i] of the whole problem
  std::vector<std::uint32_t> edge_of;  // its edge i is edge edge_of[i] of the whole problem
};

// In increasing order of their smallest node; a single component keeps the original numbering.
std::vector<Component> split_components(const MatchingProblem& problem);

// The P1 that the matching `kept` leaves open: the nodes it does not cover, the edges between them
// that `allowed` admits and that conflict with none of kept's (`conflicts`: conflicting_edges() of
// the problem), and the conflict pairs among those edges.
Component open_part(const MatchingProblem& problem, const Adjacency& conflicts,
                    const std::vector<std::uint32_t>& kept,
                    const std::vector<std::uint8_t>& allowed);

}  // namespace tessera::matching
