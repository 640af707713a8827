// The exact solver of P1 (thesis Ch. 5): proven optimal matchings, or a proven gap at the node
// limit.
//
//  1. Independent components (components.h) are solved one by one.
//  2. Feasibility: the blossom algorithm decides whether any matching covers every port; if not,
//     P1 is infeasible and the Gallai-Edmonds set D names the ports at fault (blossom.h).
//  3. The cheapest matching without conflict constraints bounds P1 from below; when it is
//     conflict-free it is optimal and the search ends here.
//  4. Probing fixes edges that no feasible matching can hold, or that every one must (probing.h).
//  5. The LP relaxation with clique rows and odd-set rows (lp_relaxation.h) gives the root bound
//     and the clique multipliers that price conflicts for the Lagrangian repair (incumbent.h); on
//     a component of 10,000 edges or more, one round of GLPK's Gomory cuts raises the bound.
//  6. The incumbent to start from: the better of a Lagrangian repair (incumbent.h) and the optimum
//     of the smaller P1 left once the LP's edges at 1 are kept (RENS, exact_solver.cpp). Then the
//     part of P1 that holds every matching no dearer than it, or than the LP bound plus 0.02 % if
//     that is less, is solved exactly within a node limit (solve_below_cutoff()): an optimum within
//     that cutoff is P1's, and no search follows; otherwise the part's best may still be a better
//     incumbent. A dive (incumbent.h) only when none of these finds one. On fertility's 41 slider
//     positions the dive was never better than the first two, yet took 5 to 16 ms of every root
//     that went on to a search; without it the same trees, P1 summed 1,383 -> 1,104 ms (bunny 801
//     -> 705, rocker-arm 350 -> 307).
//  7. LP-based branch-and-bound with reduced-cost fixing closes the gap (branch_and_bound.h).
//  8. The components share the node limit (SolveLimits::nodes), in their order.
// Deterministic: the same instance and node limit give the same matching, whatever the machine and
// its load, unless the time guard (SolveLimits::seconds) passes during the solve: then stopped_by
// is time_guard, whatever stopped (probing, a root LP, a search).
//
// Steps 1, 2, 4 and the clique cover of step 5 read no weight: an ExactSolverCache keeps them
// between solves of one graph with its conflicts, so that a new alpha (SPEC "Data flow": only the
// weights change) starts at step 3. The results are the same with or without it.
#pragma once

#include <chrono>
#include <cstdint>
#include <optional>
#include <vector>

#include "base/progress.h"
#include "matching/adjacency.h"
#include "matching/branch_and_bound.h"
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
  // Made with the cache (by its first call whose probing the deadline does not stop), or by a
  // solve without the cache that needs it.
  std::optional<Root> root;
  // Per edge: in a pair added to the cached graph's (ExactSolverCache); the search prefers to
  // branch on these (branch_and_bound.h). Empty when none was added.
  std::vector<std::uint8_t> preferred;
};

// Holds the preprocessing of the first problem solved with it. A problem with the same nodes and
// edges whose conflicts start with the same pairs and add some within components (the layout's
// loop rounds, conflicts.h) gets it with the extra pairs added: probing's fixings and implied
// exclusions still hold under more conflicts, and each extra pair joins the rows as its own
// clique. Any other problem is solved without it (and leaves it as it is).
class ExactSolverCache {
 public:
  // The preprocessing for `problem`, or null if the cache holds another graph. A component whose
  // probing `deadline` stops is kept without its root until a call with time makes it.
  std::vector<ComponentStructure>* structure_for(const MatchingProblem& problem,
                                                 std::chrono::steady_clock::time_point deadline =
                                                     std::chrono::steady_clock::time_point::max());

 private:
  MatchingProblem graph_;  // the nodes, edges and conflicts it was made for (weights unused)
  std::vector<ComponentStructure> components_;
  std::vector<std::uint32_t> component_of_edge_, local_edge_;
  std::vector<ComponentStructure> with_extra_pairs_;  // for the last problem with extra pairs
  bool filled_ = false;
};

// A matching that keeps the edges at 1 in `x` (an LP optimum), a relaxation-induced neighbourhood
// (RENS, Berthold 2014): the ports they leave open are matched by the exact solver, within
// `limits`, on the edges between them that `fixed` allows and that conflict with none of the kept
// ones. Nothing when no edge is at 1 or no such matching exists (or none was found in time).
// The solver's roots start their search from it (exact_solver.cpp) with a node limit: work, not
// time, so that the incumbent and the result are the same on every run. On fertility's slider
// (41 alphas) the roots' incumbents came out at the optimum or much closer to it (alpha 0, third
// loop round: 1,792.50 where the dive and the Lagrangian repair gave 1,999.72, optimum 1,784.18),
// the search trees had 19 % fewer nodes and P1 took 17 % less time.
Incumbent complete_integral_part(const MatchingProblem& problem, const Adjacency& conflicts,
                                 const std::vector<double>& x, const std::vector<Fixed>& fixed,
                                 const SearchLimits& limits);

// An optimum of the LP relaxation (lp_relaxation.h): its values, reduced costs and objective.
struct LpOptimum {
  const std::vector<double>& x;
  const std::vector<double>& d;
  double objective;
};

// The outcome of an exact search of a part of P1.
struct NeighbourhoodSearch {
  Incumbent best;         // the part's optimum if `complete`, else the best found
  bool complete = false;  // the search ended within its limits
  bool proven = false;    // `best` is P1's optimum (solve_below_cutoff())
  std::uint64_t nodes = 0;
};

// The part of P1 that holds every matching of cost at most `cutoff`: reduced-cost fixing against
// the LP optimum `lp` with `cutoff` in place of an incumbent's cost (an edge at 0 with reduced cost
// d > cutoff - bound cannot be in such a matching, nor can one at 1 with -d above that be left
// out), on top of `fixed`; solved exactly within `limits`. If its optimum costs at most `cutoff`,
// that is P1's optimum (`proven`); if its search is complete and finds nothing that cheap, no
// matching costs `cutoff` or less. On dragon at alpha 1 (62,967 edges, 5.3 M conflict pairs) the
// root's bound is 1.06 below the optimum (0.011 %) but its incumbent 38.9 above: the part below
// the cutoff has 12,240 free edges, its search (111 nodes) proves the optimum, and P1 took 22.4 s
// instead of 49.1 s (138 nodes of the search). At alpha 5 the incumbent is within the 0.02 %: the
// part below its cost proved it in 30.4 s instead of 62.6 s; alpha 20, 14.0 s instead of 16.4 s.
NeighbourhoodSearch solve_below_cutoff(const MatchingProblem& problem, const Adjacency& conflicts,
                                       const LpOptimum& lp, double cutoff,
                                       const std::vector<Fixed>& fixed, const SearchLimits& limits);

// `cache` may be null.
MatchingResult solve_exact(const MatchingProblem& problem, const SolveLimits& limits,
                           const Progress& progress, ExactSolverCache* cache = nullptr);

}  // namespace tessera::matching
