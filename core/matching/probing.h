// Probing (the exact solver's preprocessing). Every free edge e is tried at x_e = 1 and the
// consequences are propagated (propagation.h). If that ends in a contradiction, e is fixed to 0.
// Otherwise every edge f it drove to 0 gives an implied exclusion x_e + x_f <= 1 that no conflict
// pair states: those strengthen the clique rows of the relaxation (lp_relaxation.h). A port with
// one usable edge fixes it to 1. Repeated until nothing changes, or until a deadline.
#pragma once

#include <chrono>
#include <cstdint>
#include <utility>
#include <vector>

#include "matching/adjacency.h"
#include "matching/problem.h"
#include "matching/propagation.h"

namespace tessera::matching {

struct Probing {
  std::vector<Fixed> edges;  // per edge
  bool infeasible = false;
  // The deadline came before every edge was tried: what was found holds, but not all of it.
  bool stopped = false;
  // Pairs of free edges (both orders) that cannot both be 1, beyond the exclusive ones.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> implied;
};

// `incident` is incident_edges(problem), `exclusive` is exclusive_edges(problem). Stops at
// `deadline` (Probing::stopped): on dragon (62,967 edges) probing takes about 4 s.
Probing probe(
    const MatchingProblem& problem, const Adjacency& incident, const Adjacency& exclusive,
    std::chrono::steady_clock::time_point deadline = std::chrono::steady_clock::time_point::max());

}  // namespace tessera::matching
