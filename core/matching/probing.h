// Probing (the exact solver's preprocessing): edges that cannot be in any feasible matching are
// fixed to 0, edges that must be are fixed to 1, by propagation to a fixpoint:
//  - a port with no usable edge left: P1 is infeasible;
//  - a port with one usable edge left: that edge is fixed to 1, and every edge exclusive with it
//    (sharing a node, or in a conflict pair with it) to 0;
//  - an edge whose choice would leave some other port without any usable edge is fixed to 0.
#pragma once

#include <cstdint>
#include <vector>

#include "matching/adjacency.h"
#include "matching/problem.h"

namespace tessera::matching {

enum class Fixed : std::int8_t { free = -1, zero = 0, one = 1 };

struct Probing {
  std::vector<Fixed> edges;  // per edge
  bool infeasible = false;
  std::uint32_t blocked_port = 0;  // when infeasible: a port that cannot be matched
};

// `exclusive` is exclusive_edges(problem), `incident` is incident_edges(problem).
Probing probe(const MatchingProblem& problem, const Adjacency& incident,
              const Adjacency& exclusive);

}  // namespace tessera::matching
