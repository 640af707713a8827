// GLPK on P1: the plain model (5.1)-(5.4) and the tuned one (clique rows, cuts, an incumbent) agree
// with each other and with the checker, on feasible and infeasible generated instances.
#include <gtest/gtest.h>

#include <cmath>

#include "matching/check.h"
#include "matching/generate.h"
#include "matching/glpk_solver.h"

namespace tessera::matching {
namespace {

MatchingResult solve(const MatchingProblem& p, const GlpkConfig& config) {
  return solve_with_glpk(p, config, 60.0, Progress());
}

TEST(MatchingGlpk, PlainAndTunedAgreeOnPlantedInstances) {
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    PlantedSpec spec;
    spec.ports = 24;
    spec.virtual_ports = seed % 3;
    spec.extra_edges = 80;
    spec.conflicts = 150;
    spec.seed = seed;
    const MatchingProblem p = planted_instance(spec);
    const MatchingResult plain = solve(p, {});
    const MatchingResult tuned = solve(p, {true, true, plain.edges});
    ASSERT_EQ(plain.status, SolveStatus::optimal) << "seed " << seed;
    ASSERT_EQ(tuned.status, SolveStatus::optimal) << "seed " << seed;
    EXPECT_NEAR(plain.objective, tuned.objective, 1e-9 * std::abs(plain.objective));
    EXPECT_EQ(plain.lower_bound, plain.objective);
    EXPECT_EQ(plain.gap(), 0.0);
    const SolutionCheck check = check_solution(p, tuned.edges);
    EXPECT_TRUE(check.feasible) << check.violations.front();
    EXPECT_EQ(check.objective, tuned.objective);
  }
}

TEST(MatchingGlpk, InfeasibleInstancesAreReportedAsSuch) {
  PlantedSpec spec;
  spec.blocked_squares = 1;
  for (bool tuned : {false, true}) {
    const MatchingResult r = solve(planted_instance(spec), {tuned, tuned, {}});
    EXPECT_EQ(r.status, SolveStatus::infeasible);
    EXPECT_TRUE(r.edges.empty());
    EXPECT_TRUE(std::isinf(r.lower_bound));
  }
  spec.blocked_squares = 0;
  spec.ports = 31;  // odd, no virtual port
  EXPECT_EQ(solve(planted_instance(spec), {}).status, SolveStatus::infeasible);
}

TEST(MatchingGlpk, ATimeLimitReturnsTheBestWithItsBound) {
  SyntheticLayoutSpec spec;
  spec.singularity_pairs = 30;
  spec.alpha = 0.0;
  spec.max_length = 8.0;
  const MatchingProblem p = synthetic_layout_instance(spec);
  const MatchingResult r = solve_with_glpk(p, {}, 0.3, Progress());
  EXPECT_LT(r.seconds, 3.0);
  EXPECT_TRUE(r.status == SolveStatus::feasible || r.status == SolveStatus::time_limit);
  if (r.has_solution()) {
    EXPECT_TRUE(check_solution(p, r.edges).feasible);
    EXPECT_LE(r.lower_bound, r.objective);
    EXPECT_GT(r.gap(), 0.0);
  }
}

}  // namespace
}  // namespace tessera::matching
