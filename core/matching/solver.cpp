#include "matching/solver.h"

#include <chrono>

#include "base/error.h"
#include "matching/adjacency.h"
#include "matching/check.h"
#include "matching/glpk_solver.h"
#include "matching/incumbent.h"

namespace tessera::matching {

namespace {

constexpr int kRepairRounds = 6;

// The tuned GLPK configuration: clique rows, cuts, and the Lagrangian repair's matching (priced by
// the plain weights) as the first incumbent.
MatchingResult solve_glpk_tuned(const MatchingProblem& problem, const SolveLimits& limits,
                                const Progress& progress) {
  const auto start = std::chrono::steady_clock::now();
  GlpkConfig config;
  config.clique_rows = true;
  config.cuts = true;
  const ProblemAdjacency adjacency = adjacency_of(problem);
  const std::vector<Fixed> none(problem.edges.size(), Fixed::free);
  const IncumbentSearch heuristics(problem, adjacency.incident, adjacency.conflicts,
                                   adjacency.exclusive, none);
  const Incumbent incumbent =
      heuristics.lagrangian_repair(std::vector<double>(problem.edges.size(), 0.0), kRepairRounds);
  if (incumbent.found) config.incumbent = incumbent.edges;
  const double spent =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  MatchingResult result =
      solve_with_glpk(problem, config, {limits.seconds - spent, limits.nodes}, progress);
  result.seconds += spent;
  return result;
}

void verify(const MatchingProblem& problem, const MatchingResult& result, SolverKind kind) {
  if (!result.has_solution()) return;
  const SolutionCheck check = check_solution(problem, result.edges);
  if (!check.feasible)
    throw Error(std::string("the ") + to_string(kind) +
                " solver returned an infeasible matching: " + check.violations.front());
}

}  // namespace

SolverKind solver_kind_from_name(const std::string& name) {
  if (name == "exact") return SolverKind::exact;
  if (name == "glpk") return SolverKind::glpk;
  if (name == "glpk-tuned") return SolverKind::glpk_tuned;
  throw InputError("unknown solver '" + name + "'; choose exact, glpk or glpk-tuned");
}

const char* to_string(SolverKind kind) {
  switch (kind) {
    case SolverKind::exact:
      return "exact";
    case SolverKind::glpk:
      return "glpk";
    case SolverKind::glpk_tuned:
      return "glpk-tuned";
  }
  return "unknown";
}

MatchingResult solve_matching(const MatchingProblem& problem, SolverKind kind,
                              const SolveLimits& limits, const Progress& progress,
                              ExactSolverCache* cache) {
  MatchingResult result;
  switch (kind) {
    case SolverKind::exact:
      result = solve_exact(problem, limits, progress, cache);
      break;
    case SolverKind::glpk:
      result = solve_with_glpk(problem, GlpkConfig{}, limits, progress);
      break;
    case SolverKind::glpk_tuned:
      result = solve_glpk_tuned(problem, limits, progress);
      break;
  }
  verify(problem, result, kind);
  return result;
}

}  // namespace tessera::matching
