// The P1 instance fuzz targets share this check: an instance that parses and is small enough is
// solved by the exact solver and by plain GLPK (solver.h), and both must agree on the status and,
// when optimal, on the objective. A disagreement, or any exception from a solver, is a finding.
#pragma once

#include <cmath>
#include <cstdlib>
#include <span>

#include "fuzz_target.h"
#include "matching/solver.h"

namespace tessera::fuzz {

inline void solve_both_and_compare(const matching::MatchingProblem& problem) {
  constexpr std::size_t kMaxEdges = 40;  // GLPK's branch-and-bound stays in milliseconds
  constexpr double kMaxCompared = 1e6;   // GLPK's simplex tolerances are relative (1e-7)
  if (problem.edges.size() > kMaxEdges || problem.is_virtual.size() > 2 * kMaxEdges) return;
  for (const matching::MatchingEdge& edge : problem.edges)
    if (std::abs(edge.weight) > kMaxCompared) return;
  const auto exact = matching::solve_matching(problem, matching::SolverKind::exact, 0.5);
  const auto glpk = matching::solve_matching(problem, matching::SolverKind::glpk, 0.5);
  if (exact.status == matching::SolveStatus::time_limit ||
      glpk.status == matching::SolveStatus::time_limit)
    return;
  if (exact.status != glpk.status) std::abort();
  if (exact.status == matching::SolveStatus::optimal &&
      std::abs(exact.objective - glpk.objective) > 1e-6 * std::max(1.0, std::abs(glpk.objective)))
    std::abort();
}

// The body of a P1 fuzz target: a reader's refusal (tessera::Error) is fine, then the comparison.
template <class Reader>
int fuzz_p1_reader(Reader read, const std::uint8_t* data, std::size_t size, const char* name) {
  matching::MatchingProblem problem;
  try {
    problem = read(std::span<const std::uint8_t>(data, size), name, fuzz_limits());
  } catch (const Error&) {
    return 0;
  }
  solve_both_and_compare(problem);
  return 0;
}

}  // namespace tessera::fuzz
