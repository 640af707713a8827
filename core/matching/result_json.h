// The machine-readable form of a P1 solve, one definition shared by `tessera solve --json` and the
// wasm module: status, objective, lower_bound, gap, seconds, nodes (null where not finite), the
// chosen edges, the unmatchable ports of an infeasible instance, and the instance's size.
#pragma once

#include <nlohmann/json.hpp>

#include "matching/problem.h"
#include "matching/result.h"
#include "matching/solver.h"

namespace tessera::matching {

nlohmann::ordered_json result_json(const MatchingProblem& problem, SolverKind solver,
                                   const MatchingResult& result);

}  // namespace tessera::matching
