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
#pragma once

#include "base/progress.h"
#include "matching/problem.h"
#include "matching/result.h"

namespace tessera::matching {

MatchingResult solve_exact(const MatchingProblem& problem, double time_limit,
                           const Progress& progress);

}  // namespace tessera::matching
