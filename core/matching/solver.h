// One entry point for every P1 solver (thesis Ch. 5, Appendix B), with a node limit, a time guard
// and an independent check of what the solver returns.
//   exact       the exact solver (exact_solver.h), the default
//   glpk        GLPK's branch-and-bound on the plain model (5.1)-(5.4), the reference
//   glpk-tuned  GLPK on clique rows with cuts, started from the Lagrangian repair's matching
#pragma once

#include <string>

#include "base/progress.h"
#include "matching/exact_solver.h"
#include "matching/problem.h"
#include "matching/result.h"

namespace tessera::matching {

enum class SolverKind { exact, glpk, glpk_tuned };

// "exact", "glpk", "glpk-tuned"; throws InputError naming the choices otherwise.
SolverKind solver_kind_from_name(const std::string& name);
const char* to_string(SolverKind kind);

// Solves within `limits`: its branch-and-bound nodes (the same result on every run), and its
// seconds as a guard (a result it stops says so: stopped_by). The returned matching is verified by
// check_solution(); a solver that returns an infeasible one is a bug and throws Error. `cache` (may
// be null) keeps the exact solver's weight-free preprocessing for the next solve of the same graph
// (exact_solver.h); the GLPK solvers do not use it.
MatchingResult solve_matching(const MatchingProblem& problem, SolverKind kind,
                              const SolveLimits& limits, const Progress& progress = Progress(),
                              ExactSolverCache* cache = nullptr);

}  // namespace tessera::matching
