// An independent check of a P1 solution (thesis (5.2)-(5.4)): it trusts nothing the solver says and
// recomputes the degrees, the conflicts and the objective (5.1) from the problem alone.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "matching/problem.h"

namespace tessera::matching {

struct SolutionCheck {
  bool feasible = false;
  double objective = 0.0;               // (5.1) of the given edges, recomputed
  std::vector<std::string> violations;  // the first few, e.g. "port 7 is matched 2 times"
  std::size_t violation_count = 0;      // all of them
};

// In: a problem and the indices of the chosen edges. Out: feasible iff every index is an edge, no
// edge is chosen twice, every port has exactly one chosen edge, every virtual port at most one, and
// no conflict pair has both edges chosen.
SolutionCheck check_solution(const MatchingProblem& problem,
                             const std::vector<std::uint32_t>& chosen);

}  // namespace tessera::matching
