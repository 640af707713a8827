// The solution checker catches every kind of broken solution, whoever produced it.
#include <gtest/gtest.h>

#include <set>

#include "matching/check.h"
#include "matching/cliques.h"
#include "matching/generate.h"

namespace tessera::matching {
namespace {

// Ports 0..3, virtual port 4: a square 0-1-2-3 with a diagonal pair and an edge to the virtual
// port.
MatchingProblem square() {
  MatchingProblem p;
  p.is_virtual = {0, 0, 0, 0, 1};
  p.edges = {{0, 1, 1.0}, {2, 3, 2.0}, {1, 2, 3.0}, {3, 0, 4.0}, {0, 4, 0.5}, {0, 1, 7.0}};
  p.conflicts = {{0, 1}};
  return p;
}

TEST(MatchingCheck, AcceptsAFeasibleMatchingAndRecomputesItsObjective) {
  const SolutionCheck check = check_solution(square(), {2, 3});
  EXPECT_TRUE(check.feasible);
  EXPECT_EQ(check.objective, 7.0);
  EXPECT_TRUE(check.violations.empty());
  EXPECT_TRUE(check_solution(square(), {1, 5}).feasible);  // the multi-edge 5 joins 0 and 1
}

TEST(MatchingCheck, CatchesUnmatchedAndDoublyMatchedPorts) {
  const SolutionCheck missing = check_solution(square(), {2});
  EXPECT_FALSE(missing.feasible);
  EXPECT_EQ(missing.violation_count, 2u);  // ports 0 and 3
  EXPECT_EQ(missing.violations[0], "port 0 is matched 0 times");
  const SolutionCheck twice = check_solution(square(), {2, 3, 4});
  EXPECT_FALSE(twice.feasible);
  EXPECT_EQ(twice.violations[0], "port 0 is matched 2 times");
  EXPECT_EQ(check_solution(square(), {2, 3, 4}).violation_count, 1u);
}

TEST(MatchingCheck, VirtualPortsAtMostOnce) {
  MatchingProblem p = square();
  p.edges.push_back({3, 4, 1.0});
  EXPECT_TRUE(check_solution(p, {2, 3}).feasible);              // virtual port 4 unmatched
  EXPECT_TRUE(check_solution(p, {2, 4, 1}).feasible == false);  // port 2 twice
  const SolutionCheck both = check_solution(p, {4, 6, 2});
  EXPECT_FALSE(both.feasible);
  EXPECT_NE(both.violations[0].find("virtual port 4 is matched 2 times"), std::string::npos);
}

TEST(MatchingCheck, CatchesConflictsRepeatsAndUnknownEdges) {
  const SolutionCheck conflict = check_solution(square(), {0, 1});
  EXPECT_FALSE(conflict.feasible);
  EXPECT_EQ(conflict.violations[0], "edges 0 and 1 are both chosen but conflict");
  const SolutionCheck repeated = check_solution(square(), {2, 2, 3});
  EXPECT_FALSE(repeated.feasible);
  EXPECT_EQ(repeated.violations[0], "edge 2 is chosen twice");
  const SolutionCheck unknown = check_solution(square(), {2, 3, 99});
  EXPECT_FALSE(unknown.feasible);
  EXPECT_EQ(unknown.violations[0], "edge 99 does not exist");
}

TEST(MatchingCheck, ReportsAFewViolationsAndCountsAll) {
  PlantedSpec spec;
  spec.ports = 200;
  const SolutionCheck check = check_solution(planted_instance(spec), {});
  EXPECT_EQ(check.violation_count, 200u);
  EXPECT_EQ(check.violations.size(), 10u);
}

TEST(MatchingCliques, CoverEveryConflictWithCliquesOfTheExclusionGraph) {
  SyntheticLayoutSpec spec;
  spec.singularity_pairs = 8;
  spec.max_length = 6.0;
  const MatchingProblem p = synthetic_layout_instance(spec);
  ASSERT_GT(p.conflicts.size(), 50u);
  std::set<std::pair<std::uint32_t, std::uint32_t>> conflicts, covered;
  for (const ConflictPair& c : p.conflicts) conflicts.insert(std::minmax(c.first, c.second));
  auto exclusive = [&](std::uint32_t a, std::uint32_t b) {
    const MatchingEdge &e = p.edges[a], &f = p.edges[b];
    return conflicts.count(std::minmax(a, b)) || e.u == f.u || e.u == f.v || e.v == f.u ||
           e.v == f.v;
  };
  for (const Clique& clique : conflict_cliques(p)) {
    bool holds_conflict = false;
    for (std::size_t i = 0; i < clique.size(); ++i)
      for (std::size_t j = i + 1; j < clique.size(); ++j) {
        ASSERT_TRUE(exclusive(clique[i], clique[j])) << clique[i] << " " << clique[j];
        const auto pair = std::minmax(clique[i], clique[j]);
        if (conflicts.count(pair)) {
          covered.insert(pair);
          holds_conflict = true;
        }
      }
    EXPECT_TRUE(holds_conflict);
  }
  EXPECT_EQ(covered, conflicts);
}

}  // namespace
}  // namespace tessera::matching
