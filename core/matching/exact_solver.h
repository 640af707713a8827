// The exact solver of P1 (thesis Ch. 5): proven optimal matchings, or a proven gap at the deadline.
//
//  1. Independent components (components.h) are solved one by one.
//  2. Feasibility: the blossom algorithm decides whether any matching covers every port; if not,
//     P1 is infeasible and the Gallai-Edmonds set D names the ports at fault (blossom.h).
//  3. The cheapest matching without conflict constraints bounds P1 from below; when it is
//     conflict-free it is optimal and the search ends here.
//  4. Probing fixes edges that no feasible matching can hold, or that every one must (probing.h).
//  5. The LP relaxation with clique rows and odd-set rows (lp_relaxation.h) gives the root bound
//     and the clique multipliers that price conflicts for the Lagrangian repair (incumbent.h).
//  6. LP-based branch-and-bound with reduced-cost fixing closes the gap (branch_and_bound.h).
// Deterministic: the same instance gives the same matching, whatever the machine, unless the time
// limit stops it.
//
// Steps 1, 2, 4 and the clique cover of step 5 read no weight: an ExactSolverCache keeps them
// between solves of one graph with its conflicts, so that a new alpha (SPEC "Data flow": only the
// weights change) starts at step 3. The results are the same with or without it.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "base/progress.h"
#include "matching/adjacency.h"
#include "matching/cliques.h"
#include "matching/components.h"
#include "matching/probing.h"
#include "matching/problem.h"
#include "matching/result.h"

namespace tessera::matching {

// The weight-free preprocessing of one component.
struct ComponentStructure {
  Component component;  // its weights are set anew at every solve
  Adjacency incident;
  Adjacency conflicts;
  std::vector<std::uint32_t> unmatchable_ports;  // Gallai-Edmonds D; empty: a cover exists
  struct Root {
    Probing probing;
    Adjacency exclusion;  // exclusive pairs with the implied exclusions of probing
    std::vector<Clique> cliques;
  };
  std::optional<Root> root;  // made by the first solve whose conflict-free cover has conflicts
};

// Holds the preprocessing of the first problem solved with it. A problem with the same nodes and
// edges whose conflicts start with the same pairs and add some within components (the layout's
// loop rounds, conflicts.h) gets it with the extra pairs added: probing's fixings and implied
// exclusions still hold under more conflicts, and each extra pair joins the rows as its own
// clique. Any other problem is solved without it (and leaves it as it is).
class ExactSolverCache {
 public:
  // The preprocessing for `problem`, or null if the cache holds another graph.
  std::vector<ComponentStructure>* structure_for(const MatchingProblem& problem);

 private:
  MatchingProblem graph_;  // the nodes, edges and conflicts it was made for (weights unused)
  std::vector<ComponentStructure> components_;
  std::vector<std::uint32_t> component_of_edge_, local_edge_;
  std::vector<ComponentStructure> with_extra_pairs_;  // for the last problem with extra pairs
  bool filled_ = false;
};

// `cache` may be null.
MatchingResult solve_exact(const MatchingProblem& problem, double time_limit,
                           const Progress& progress, ExactSolverCache* cache = nullptr);

}  // namespace tessera::matching
