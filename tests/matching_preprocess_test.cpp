// The exact solver's building blocks on hand-made instances: propagation and probing (fixings and
// implied exclusions), clique separation, independent components, the diving heuristic.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>

#include "matching/adjacency.h"
#include "matching/check.h"
#include "matching/cliques.h"
#include "matching/components.h"
#include "matching/generate.h"
#include "matching/incumbent.h"
#include "matching/probing.h"

namespace tessera::matching {
namespace {

struct Indexed {
  explicit Indexed(MatchingProblem p)
      : problem(std::move(p)),
        incident(incident_edges(problem)),
        conflicts(conflicting_edges(problem)),
        exclusive(exclusive_edges(problem)) {}
  MatchingProblem problem;
  Adjacency incident, conflicts, exclusive;
};

// Ports 0..5. Port 0 has edges 0 (0-1) and 1 (0-2); edge 2 (3-4) conflicts with both, so
// choosing it leaves port 0 unmatched. Edges 3 (1-2), 4 (3-5), 5 (4-5), 6 (1-3), 7 (2-4).
MatchingProblem blocking_instance() {
  MatchingProblem p;
  p.is_virtual.assign(6, 0);
  p.edges = {{0, 1, 1}, {0, 2, 1}, {3, 4, 1}, {1, 2, 1},
             {3, 5, 1}, {4, 5, 1}, {1, 3, 1}, {2, 4, 1}};
  p.conflicts = {{2, 0}, {2, 1}};
  return p;
}

TEST(MatchingProbing, FixesEdgesThatBlockAPort) {
  const Indexed x(blocking_instance());
  const Probing probing = probe(x.problem, x.incident, x.exclusive);
  ASSERT_FALSE(probing.infeasible);
  EXPECT_EQ(probing.edges[2], Fixed::zero);
  // With edge 2 gone, port 5 keeps edges 4 and 5 and nothing is forced.
  EXPECT_EQ(std::count(probing.edges.begin(), probing.edges.end(), Fixed::one), 0);
}

TEST(MatchingProbing, ADeadlinePassedStopsItBeforeTheTries) {
  const Indexed x(blocking_instance());
  const Probing stopped =
      probe(x.problem, x.incident, x.exclusive, std::chrono::steady_clock::now());
  EXPECT_TRUE(stopped.stopped);
  EXPECT_FALSE(stopped.infeasible);
  EXPECT_EQ(stopped.edges[2], Fixed::free);  // the try that fixes it never came
  const Probing whole = probe(x.problem, x.incident, x.exclusive);
  EXPECT_FALSE(whole.stopped);
  EXPECT_EQ(whole.edges[2], Fixed::zero);
}

TEST(MatchingProbing, ASingleEdgeIsForcedAndExcludesItsNeighbours) {
  MatchingProblem p = blocking_instance();
  p.edges[5] = {0, 1, 1};  // port 5 keeps edge 4 only
  const Indexed x(p);
  const Probing probing = probe(x.problem, x.incident, x.exclusive);
  ASSERT_FALSE(probing.infeasible);
  EXPECT_EQ(probing.edges[4], Fixed::one);
  EXPECT_EQ(probing.edges[2], Fixed::zero);  // shares port 3 with edge 4
  EXPECT_EQ(probing.edges[6], Fixed::zero);
}

TEST(MatchingProbing, FindsInfeasibilityAndImpliedExclusions) {
  MatchingProblem p;
  p.is_virtual.assign(4, 0);
  p.edges = {{0, 1, 1}, {2, 3, 1}};
  p.conflicts = {{0, 1}};
  const Indexed infeasible(p);
  EXPECT_TRUE(probe(infeasible.problem, infeasible.incident, infeasible.exclusive).infeasible);

  // Ports 0..5: a = 0-1 forces port 2 onto c = 2-3 (its other edge b = 2-4 conflicts with a),
  // and c conflicts with d = 4-5: a and d cannot both be chosen, though no pair says so (edges
  // 8 = 4-5 and 9 = 0-2 keep a and d feasible).
  MatchingProblem q;
  q.is_virtual.assign(6, 0);
  q.edges = {{0, 1, 1}, {2, 4, 1}, {2, 3, 1}, {4, 5, 1}, {0, 3, 1},
             {1, 5, 1}, {0, 5, 1}, {1, 3, 1}, {4, 5, 1}, {0, 2, 1}};
  q.conflicts = {{0, 1}, {2, 3}};
  const Indexed y(q);
  const Probing probing = probe(y.problem, y.incident, y.exclusive);
  ASSERT_FALSE(probing.infeasible);
  EXPECT_EQ(probing.edges[0], Fixed::free);
  EXPECT_EQ(probing.edges[3], Fixed::free);
  EXPECT_NE(std::find(probing.implied.begin(), probing.implied.end(), std::pair{0u, 3u}),
            probing.implied.end());
  EXPECT_NE(std::find(probing.implied.begin(), probing.implied.end(), std::pair{3u, 0u}),
            probing.implied.end());
}

TEST(MatchingPropagation, TryOneCommitsOnlyOnRequest) {
  const Indexed x(blocking_instance());
  Propagation propagation(x.problem, x.incident, x.exclusive);
  EXPECT_FALSE(propagation.try_one(2));  // port 0 would be left without an edge
  ASSERT_TRUE(propagation.try_one(0));
  EXPECT_EQ(propagation.values()[0], Fixed::free);
  propagation.commit();
  EXPECT_EQ(propagation.values()[0], Fixed::one);
  EXPECT_EQ(propagation.values()[1], Fixed::zero);
  EXPECT_EQ(propagation.values()[3], Fixed::zero);
  EXPECT_FALSE(propagation.infeasible());
}

TEST(MatchingCliques, SeparationFindsOnlyViolatedCliques) {
  // Edges 0, 1, 2 pairwise exclusive (a triangle of the exclusion graph), edge 3 apart.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs = {{0, 1}, {1, 0}, {0, 2},
                                                                {2, 0}, {1, 2}, {2, 1}};
  const Adjacency exclusion = adjacency_from_pairs(4, pairs);
  const std::vector<Clique> violated = violated_cliques(exclusion, {0.5, 0.5, 0.5, 0.5}, 1e-6);
  ASSERT_EQ(violated.size(), 1u);
  EXPECT_EQ(violated[0], (Clique{0, 1, 2}));
  EXPECT_TRUE(violated_cliques(exclusion, {0.4, 0.3, 0.3, 0.5}, 1e-6).empty());
}

TEST(MatchingIncumbent, DivingFollowsTheOrderAndImproves) {
  PlantedSpec spec;
  spec.ports = 40;
  spec.extra_edges = 100;
  spec.conflicts = 150;
  spec.seed = 9;
  const Indexed x(planted_instance(spec));
  const std::vector<Fixed> none(x.problem.edges.size(), Fixed::free);
  const IncumbentSearch search(x.problem, x.incident, x.conflicts, x.exclusive, none);
  std::vector<std::uint32_t> order(x.problem.edges.size());
  for (std::uint32_t e = 0; e < order.size(); ++e) order[e] = e;  // planted edges come first
  const Incumbent found = search.dive(order);
  ASSERT_TRUE(found.found);
  const SolutionCheck check = check_solution(x.problem, found.edges);
  EXPECT_TRUE(check.feasible);
  EXPECT_EQ(check.objective, found.objective);
  std::vector<std::uint32_t> planted(20);
  for (std::uint32_t e = 0; e < 20; ++e) planted[e] = e;
  EXPECT_LE(found.objective, objective_of(x.problem, planted));  // local search only improves
  const auto passed = std::chrono::steady_clock::now() - std::chrono::seconds(1);
  EXPECT_FALSE(search.dive(order, passed).found);  // a dive past its deadline gives nothing
}

}  // namespace
}  // namespace tessera::matching
