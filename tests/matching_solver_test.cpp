// The exact solver against brute force on tiny instances and against GLPK's plain model on
// generated ones (planted matchings, random conflicts, infeasible ones): the same status, the same
// optimum, and every matching passes the independent checker.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>

#include "matching/adjacency.h"
#include "matching/blossom.h"
#include "matching/check.h"
#include "matching/cliques.h"
#include "matching/components.h"
#include "matching/dual_bound.h"
#include "matching/exact_solver.h"
#include "matching/generate.h"
#include "matching/lp_relaxation.h"
#include "matching/random.h"
#include "matching/solver.h"

namespace tessera::matching {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

struct Matching {
  std::vector<std::uint32_t> edges;
  double cost = 0.0;
};

// Every matching without conflicts, by enumerating every subset of edges (m <= 20).
std::vector<Matching> feasible_matchings(const MatchingProblem& p) {
  std::vector<Matching> matchings;
  const std::uint32_t m = static_cast<std::uint32_t>(p.edges.size());
  for (std::uint32_t subset = 0; subset < (1u << m); ++subset) {
    std::vector<std::uint32_t> edges;
    for (std::uint32_t e = 0; e < m; ++e)
      if (subset & (1u << e)) edges.push_back(e);
    const SolutionCheck check = check_solution(p, edges);
    if (check.feasible) matchings.push_back({std::move(edges), check.objective});
  }
  return matchings;
}

// The optimum by brute force, or that of the matchings that hold edge `kept`.
double brute_force_optimum(const MatchingProblem& p, std::optional<std::uint32_t> kept = {}) {
  double best = kInfinity;
  for (const Matching& matching : feasible_matchings(p))
    if (!kept || std::count(matching.edges.begin(), matching.edges.end(), *kept))
      best = std::min(best, matching.cost);
  return best;
}

MatchingProblem tiny_instance(std::uint64_t seed) {
  Random random(seed);
  MatchingProblem p;
  const std::uint32_t n = 4 + random.below(5);
  for (std::uint32_t v = 0; v < n; ++v) p.is_virtual.push_back(random.below(4) == 0);
  const std::uint32_t m = 6 + random.below(10);
  for (std::uint32_t e = 0; e < m; ++e) {
    const std::uint32_t u = random.below(n);
    const std::uint32_t v = (u + 1 + random.below(n - 1)) % n;
    p.edges.push_back({u, v, std::round(random.unit() * 20.0 - 4.0)});  // ties and negatives
  }
  const std::uint32_t k = random.below(2 * m);
  for (std::uint32_t c = 0; c < k; ++c) {
    const std::uint32_t e = random.below(m);
    p.conflicts.push_back({e, (e + 1 + random.below(m - 1)) % m});
  }
  return p;
}

void expect_agree(const MatchingProblem& p, const MatchingResult& exact, double optimum,
                  const std::string& what) {
  if (std::isinf(optimum)) {
    EXPECT_EQ(exact.status, SolveStatus::infeasible) << what;
    EXPECT_TRUE(exact.edges.empty()) << what;
    return;
  }
  ASSERT_EQ(exact.status, SolveStatus::optimal) << what;
  EXPECT_NEAR(exact.objective, optimum, 1e-9 * std::max(1.0, std::abs(optimum))) << what;
  EXPECT_EQ(exact.lower_bound, exact.objective) << what;
  EXPECT_EQ(exact.gap(), 0.0) << what;
  const SolutionCheck check = check_solution(p, exact.edges);
  EXPECT_TRUE(check.feasible) << what;
  EXPECT_EQ(check.objective, exact.objective) << what;
}

TEST(MatchingExact, MatchesBruteForceOnTinyInstances) {
  int feasible = 0;
  for (std::uint64_t seed = 1; seed <= 300; ++seed) {
    const MatchingProblem p = tiny_instance(seed);
    const double optimum = brute_force_optimum(p);
    feasible += std::isfinite(optimum);
    expect_agree(p, solve_matching(p, SolverKind::exact, 10.0), optimum,
                 "seed " + std::to_string(seed));
  }
  EXPECT_GT(feasible, 50);  // both kinds are well represented
  EXPECT_LT(feasible, 250);
}

TEST(MatchingExact, AgreesWithGlpkOnPlantedAndRandomInstances) {
  int infeasible = 0;
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    PlantedSpec spec;
    spec.ports = 20 + 2 * static_cast<std::uint32_t>(seed % 11);
    spec.virtual_ports = static_cast<std::uint32_t>(seed % 4);
    spec.keep_planted_feasible = seed % 4 != 0;  // some may lose every feasible matching
    spec.extra_edges = (spec.keep_planted_feasible ? 3 : 1) * spec.ports;
    spec.conflicts = (spec.keep_planted_feasible ? (seed % 2 ? 3 : 8) : 2) * spec.ports;
    spec.seed = seed;
    const MatchingProblem p = planted_instance(spec);
    const MatchingResult glpk = solve_matching(p, SolverKind::glpk, 60.0);
    ASSERT_TRUE(glpk.status == SolveStatus::optimal || glpk.status == SolveStatus::infeasible);
    if (spec.keep_planted_feasible) EXPECT_EQ(glpk.status, SolveStatus::optimal);
    infeasible += glpk.status == SolveStatus::infeasible;
    const double optimum = glpk.status == SolveStatus::optimal ? glpk.objective : kInfinity;
    expect_agree(p, solve_matching(p, SolverKind::exact, 60.0), optimum,
                 "seed " + std::to_string(seed));
  }
  EXPECT_GT(infeasible, 0);
}

SyntheticLayoutSpec layout_spec(std::uint32_t pairs, double max_length, double alpha) {
  SyntheticLayoutSpec spec;
  spec.singularity_pairs = pairs;
  spec.max_length = max_length;
  spec.alpha = alpha;
  spec.seed = 3;
  return spec;
}

TEST(MatchingExact, AgreesWithGlpkOnSyntheticLayoutInstances) {
  for (double alpha : {0.0, 1.0, 5.0}) {
    const MatchingProblem p = synthetic_layout_instance(layout_spec(7, 6.0, alpha));
    const MatchingResult glpk = solve_matching(p, SolverKind::glpk, 60.0);
    ASSERT_EQ(glpk.status, SolveStatus::optimal);
    expect_agree(p, solve_matching(p, SolverKind::exact, 60.0), glpk.objective,
                 "alpha " + std::to_string(alpha));
  }
}

// Instances whose root relaxation leaves a gap, so that the search branches (pseudocosts) and
// re-solves from the root's binding rows with the slack ones pooled: still GLPK's optimum.
TEST(MatchingExact, AgreesWithGlpkWhenItBranches) {
  int branched = 0;
  for (std::uint32_t seed = 1; seed <= 12; ++seed) {
    SyntheticLayoutSpec spec = layout_spec(9, 7.0, 1.0);
    spec.seed = seed;
    const MatchingProblem p = synthetic_layout_instance(spec);
    const MatchingResult glpk = solve_matching(p, SolverKind::glpk_tuned, 120.0);
    ASSERT_EQ(glpk.status, SolveStatus::optimal) << "seed " << seed;
    const MatchingResult exact = solve_matching(p, SolverKind::exact, 60.0);
    expect_agree(p, exact, glpk.objective, "seed " + std::to_string(seed));
    branched += exact.nodes > 0;
  }
  EXPECT_GE(branched, 2);
}

// Larger instances, where GLPK's plain model takes minutes: the tuned model is the reference.
TEST(MatchingExact, AgreesWithTunedGlpkOnLargerSyntheticInstances) {
  for (double alpha : {0.0, 1.0, 5.0, 20.0}) {
    const MatchingProblem p = synthetic_layout_instance(layout_spec(11, 8.0, alpha));
    const MatchingResult tuned = solve_matching(p, SolverKind::glpk_tuned, 120.0);
    ASSERT_EQ(tuned.status, SolveStatus::optimal);
    expect_agree(p, solve_matching(p, SolverKind::exact, 60.0), tuned.objective,
                 "alpha " + std::to_string(alpha));
  }
}

TEST(MatchingExact, ConflictsThatBlockEveryMatchingMeanInfeasible) {
  PlantedSpec spec;
  spec.blocked_squares = 2;  // G has a perfect matching, P1 none
  const MatchingProblem p = planted_instance(spec);
  std::vector<std::uint8_t> all(p.edges.size(), 1);
  EXPECT_TRUE(deficient_ports(p, all).empty());
  const MatchingResult r = solve_matching(p, SolverKind::exact, 10.0);
  EXPECT_EQ(r.status, SolveStatus::infeasible);
  EXPECT_TRUE(r.unmatchable_ports.empty());
  EXPECT_TRUE(std::isinf(r.lower_bound));
}

TEST(MatchingExact, NamesThePortsNoMatchingCovers) {
  // Ports 0-1-2 in a path and 3-4: the star at 1 leaves 0 or 2 uncovered.
  MatchingProblem p;
  p.is_virtual = {0, 0, 0, 0, 0};
  p.edges = {{0, 1, 1.0}, {1, 2, 1.0}, {3, 4, 1.0}};
  const MatchingResult r = solve_matching(p, SolverKind::exact, 10.0);
  EXPECT_EQ(r.status, SolveStatus::infeasible);
  EXPECT_EQ(r.unmatchable_ports, (std::vector<std::uint32_t>{0, 2}));
  p.is_virtual[2] = 1;  // now 2 may stay unmatched
  EXPECT_EQ(solve_matching(p, SolverKind::exact, 10.0).status, SolveStatus::optimal);
}

TEST(MatchingExact, ComponentsAddUp) {
  PlantedSpec a;
  a.ports = 16;
  a.conflicts = 100;
  a.seed = 11;
  PlantedSpec b = a;
  b.virtual_ports = 3;
  b.seed = 12;
  const MatchingProblem pa = planted_instance(a), pb = planted_instance(b);
  MatchingProblem both = pa;
  const auto shift_nodes = static_cast<std::uint32_t>(pa.node_count());
  const auto shift_edges = static_cast<std::uint32_t>(pa.edges.size());
  both.is_virtual.insert(both.is_virtual.end(), pb.is_virtual.begin(), pb.is_virtual.end());
  for (const MatchingEdge& e : pb.edges)
    both.edges.push_back({e.u + shift_nodes, e.v + shift_nodes, e.weight});
  for (const ConflictPair& c : pb.conflicts)
    both.conflicts.push_back({c.first + shift_edges, c.second + shift_edges});
  EXPECT_EQ(split_components(both).size(), 2u);
  const MatchingResult ra = solve_matching(pa, SolverKind::exact, 10.0);
  const MatchingResult rb = solve_matching(pb, SolverKind::exact, 10.0);
  const MatchingResult r = solve_matching(both, SolverKind::exact, 10.0);
  ASSERT_EQ(r.status, SolveStatus::optimal);
  EXPECT_NEAR(r.objective, ra.objective + rb.objective, 1e-9 * r.objective);
}

TEST(MatchingExact, IsDeterministic) {
  SyntheticLayoutSpec spec;
  spec.singularity_pairs = 14;
  spec.max_length = 8.0;
  spec.alpha = 0.0;
  const MatchingProblem p = synthetic_layout_instance(spec);
  const MatchingResult first = solve_matching(p, SolverKind::exact, 60.0);
  const MatchingResult second = solve_matching(p, SolverKind::exact, 60.0);
  EXPECT_EQ(first.edges, second.edges);
  EXPECT_EQ(first.nodes, second.nodes);
  EXPECT_EQ(first.objective, second.objective);
}

// The alpha slider's re-solve: the weight-free preprocessing kept in a cache gives the very
// results of a fresh solve for every new set of weights. Extra conflict pairs (as the layout's
// loop rounds add) are solved through it to the same optimum; a problem whose conflicts do not
// start with the cached ones, or whose extra pair joins two components, is solved without it.
TEST(MatchingExact, ACacheReSolvesNewWeightsAsAFreshSolveDoes) {
  const MatchingProblem base = synthetic_layout_instance(layout_spec(11, 8.0, 5.0));
  ExactSolverCache cache;
  Random random(5);
  for (int round = 0; round < 6; ++round) {
    MatchingProblem p = base;
    if (round > 0)
      for (MatchingEdge& e : p.edges) e.weight *= 0.5 + random.unit();
    const MatchingResult fresh = solve_matching(p, SolverKind::exact, 60.0);
    const MatchingResult cached = solve_matching(p, SolverKind::exact, 60.0, Progress(), &cache);
    const std::string what = "round " + std::to_string(round);
    ASSERT_EQ(fresh.status, SolveStatus::optimal) << what;
    EXPECT_EQ(cached.status, fresh.status) << what;
    EXPECT_EQ(cached.edges, fresh.edges) << what;
    EXPECT_EQ(cached.objective, fresh.objective) << what;
    EXPECT_EQ(cached.nodes, fresh.nodes) << what;
    // The optimum's own edges in conflict: the next round of the layout's loop conflicts.
    for (std::size_t k = 1; k < fresh.edges.size(); k += 2)
      p.conflicts.push_back({fresh.edges[k - 1], fresh.edges[k]});
    ASSERT_NE(cache.structure_for(p), nullptr) << what;
    const MatchingResult fresh_more = solve_matching(p, SolverKind::exact, 60.0);
    const MatchingResult cached_more =
        solve_matching(p, SolverKind::exact, 60.0, Progress(), &cache);
    ASSERT_EQ(cached_more.status, fresh_more.status) << what;
    if (fresh_more.status == SolveStatus::optimal) {
      EXPECT_NEAR(cached_more.objective, fresh_more.objective, 1e-9 * fresh_more.objective) << what;
      EXPECT_GT(cached_more.objective, cached.objective) << what;
    }
  }
  ASSERT_NE(cache.structure_for(base), nullptr);
  MatchingProblem other = base;
  other.conflicts.pop_back();
  EXPECT_EQ(cache.structure_for(other), nullptr);
}

// A cache filled after its deadline keeps its components without roots (probing stopped): the
// first solve with time makes them, and the solves with extra pairs and without give what fresh
// solves give.
TEST(MatchingExact, ACacheFilledOutOfTimeSolvesAsAFreshSolveDoes) {
  const MatchingProblem base = synthetic_layout_instance(layout_spec(11, 8.0, 5.0));
  ExactSolverCache cache;
  const std::vector<ComponentStructure>* parts =
      cache.structure_for(base, std::chrono::steady_clock::now());
  ASSERT_NE(parts, nullptr);
  for (const ComponentStructure& part : *parts) EXPECT_FALSE(part.root.has_value());
  const MatchingResult first = solve_matching(base, SolverKind::exact, 60.0);
  ASSERT_EQ(first.status, SolveStatus::optimal);
  MatchingProblem more = base;
  for (std::size_t k = 1; k < first.edges.size(); k += 2)
    more.conflicts.push_back({first.edges[k - 1], first.edges[k]});
  const auto expect_as_fresh = [&cache](const MatchingProblem& p) {
    const MatchingResult fresh = solve_matching(p, SolverKind::exact, 60.0);
    const MatchingResult cached = solve_matching(p, SolverKind::exact, 60.0, Progress(), &cache);
    ASSERT_EQ(cached.status, fresh.status);
    if (fresh.has_solution())
      EXPECT_NEAR(cached.objective, fresh.objective, 1e-9 * fresh.objective);
  };
  expect_as_fresh(more);
  // The solve with extra pairs made the roots of the cached graph, not only of its copy.
  EXPECT_TRUE(std::all_of(parts->begin(), parts->end(),
                          [](const ComponentStructure& part) { return part.root.has_value(); }));
  expect_as_fresh(base);
}

TEST(MatchingExact, ACacheSkipsExtraPairsAcrossComponents) {
  PlantedSpec spec;
  spec.ports = 12;
  spec.conflicts = 10;
  const MatchingProblem one = planted_instance(spec);
  MatchingProblem two = one;  // a second copy of it, a second component
  const auto nodes = static_cast<std::uint32_t>(one.node_count());
  const auto edges = static_cast<std::uint32_t>(one.edges.size());
  two.is_virtual.insert(two.is_virtual.end(), one.is_virtual.begin(), one.is_virtual.end());
  for (const MatchingEdge& e : one.edges) two.edges.push_back({e.u + nodes, e.v + nodes, e.weight});
  for (const ConflictPair& c : one.conflicts)
    two.conflicts.push_back({c.first + edges, c.second + edges});
  ExactSolverCache cache;
  const MatchingResult r = solve_matching(two, SolverKind::exact, 10.0, Progress(), &cache);
  ASSERT_EQ(r.status, SolveStatus::optimal);
  two.conflicts.push_back({r.edges.front(), r.edges.back()});
  EXPECT_EQ(cache.structure_for(two), nullptr);
  const MatchingResult across = solve_matching(two, SolverKind::exact, 10.0, Progress(), &cache);
  EXPECT_EQ(across.objective, solve_matching(two, SolverKind::exact, 10.0).objective);
}

TEST(MatchingExact, ATimeLimitReturnsTheBestWithAProvenBound) {
  SyntheticLayoutSpec spec;
  spec.singularity_pairs = 40;
  spec.max_length = 10.0;
  spec.alpha = 0.0;
  const MatchingProblem p = synthetic_layout_instance(spec);
  const MatchingResult r = solve_matching(p, SolverKind::exact, 0.05);
  EXPECT_LT(r.seconds, 2.0);
  if (r.status == SolveStatus::optimal) GTEST_SKIP() << "solved within 0.05 s";
  ASSERT_TRUE(r.status == SolveStatus::feasible || r.status == SolveStatus::time_limit);
  EXPECT_EQ(r.stopped_by, StopReason::time_guard);
  EXPECT_TRUE(std::isfinite(r.lower_bound));
  if (r.has_solution()) {
    EXPECT_TRUE(check_solution(p, r.edges).feasible);
    EXPECT_LE(r.lower_bound, r.objective);
    EXPECT_GT(r.gap(), 0.0);
  }
}

// The node limit is work: the same result on every run, and said so; without it, the optimum.
TEST(MatchingExact, ANodeLimitStopsTheSameWayOnEveryRun) {
  SyntheticLayoutSpec spec;
  spec.singularity_pairs = 40;
  spec.max_length = 10.0;
  spec.alpha = 0.0;
  const MatchingProblem p = synthetic_layout_instance(spec);
  const MatchingResult optimum = solve_matching(p, SolverKind::exact, 600.0);
  ASSERT_EQ(optimum.status, SolveStatus::optimal);
  EXPECT_EQ(optimum.stopped_by, StopReason::none);
  ASSERT_GT(optimum.nodes, 2u) << "the instance needs a search";
  for (SolverKind kind : {SolverKind::exact, SolverKind::glpk}) {
    const MatchingResult a = solve_matching(p, kind, {600.0, 2});
    const MatchingResult b = solve_matching(p, kind, {600.0, 2});
    EXPECT_EQ(a.stopped_by, StopReason::node_limit) << to_string(kind);
    EXPECT_TRUE(a.status == SolveStatus::feasible || a.status == SolveStatus::node_limit)
        << to_string(a.status);
    EXPECT_EQ(a.edges, b.edges);
    EXPECT_EQ(a.lower_bound, b.lower_bound);
    EXPECT_EQ(a.nodes, b.nodes);
    if (a.has_solution()) EXPECT_GE(a.objective, optimum.objective - 1e-9);
  }
}

SearchLimits generous_limits() {
  return {std::chrono::steady_clock::now() + std::chrono::seconds(10)};
}

// RENS keeps the edges at 1 and completes them optimally: with one edge at 1 (the rest at 1/2) it
// finds the best matching that holds that edge, or reports none when no matching holds it.
TEST(MatchingNeighbourhood, CompletesTheEdgesAtOneOptimally) {
  int completed = 0, impossible = 0;
  for (std::uint64_t seed = 1; seed <= 150; ++seed) {
    const MatchingProblem p = tiny_instance(seed);
    const Adjacency conflicts = conflicting_edges(p);
    const std::vector<Fixed> fixed(p.edges.size(), Fixed::free);
    for (std::uint32_t kept = 0; kept < p.edges.size(); kept += 3) {
      std::vector<double> x(p.edges.size(), 0.5);
      x[kept] = 1.0;
      const Incumbent found = complete_integral_part(p, conflicts, x, fixed, generous_limits());
      const double optimum = brute_force_optimum(p, kept);
      const std::string what = "seed " + std::to_string(seed) + " edge " + std::to_string(kept);
      if (std::isinf(optimum)) {
        EXPECT_FALSE(found.found) << what;
        ++impossible;
        continue;
      }
      ASSERT_TRUE(found.found) << what;
      EXPECT_TRUE(std::binary_search(found.edges.begin(), found.edges.end(), kept)) << what;
      const SolutionCheck check = check_solution(p, found.edges);
      EXPECT_TRUE(check.feasible) << what;
      EXPECT_NEAR(found.objective, optimum, 1e-9 * std::max(1.0, std::abs(optimum))) << what;
      ++completed;
    }
  }
  EXPECT_GT(completed, 50);
  EXPECT_GT(impossible, 20);
}

// With an optimum's edges all at 1 there is nothing left to match: the completion is that optimum;
// with no edge at 1 there is no neighbourhood.
TEST(MatchingNeighbourhood, AnIntegralPointIsItsOwnCompletion) {
  const MatchingProblem p = synthetic_layout_instance(layout_spec(9, 7.0, 1.0));
  const MatchingResult optimum = solve_matching(p, SolverKind::exact, 60.0);
  ASSERT_EQ(optimum.status, SolveStatus::optimal);
  std::vector<double> x(p.edges.size(), 0.0);
  for (std::uint32_t e : optimum.edges) x[e] = 1.0;
  const Adjacency conflicts = conflicting_edges(p);
  const std::vector<Fixed> fixed(p.edges.size(), Fixed::free);
  const Incumbent found = complete_integral_part(p, conflicts, x, fixed, generous_limits());
  ASSERT_TRUE(found.found);
  EXPECT_EQ(found.edges, optimum.edges);
  EXPECT_EQ(found.objective, optimum.objective);
  EXPECT_FALSE(complete_integral_part(p, conflicts, std::vector<double>(p.edges.size(), 0.5), fixed,
                                      generous_limits())
                   .found);
}

// Below a cutoff at or above the optimum, the part left by reduced-cost fixing holds the optimum
// and proves it; below a cutoff under the optimum it proves nothing, and a complete search of it
// finds nothing that cheap. Against brute force, with the LP of the conflict cliques solved once.
TEST(MatchingNeighbourhood, BelowACutoffTheOptimumIsFoundAndProvenOnlyIfItIsThatCheap) {
  int proven = 0, refuted = 0;
  for (std::uint64_t seed = 1; seed <= 200; ++seed) {
    const MatchingProblem p = tiny_instance(seed);
    const double optimum = brute_force_optimum(p);
    if (std::isinf(optimum)) continue;
    const Adjacency conflicts = conflicting_edges(p);
    LpRelaxation lp(p, incident_edges(p), conflict_cliques(p));
    ASSERT_EQ(lp.solve_with_cuts(exclusive_edges(p), kInfinity, 10.0, 0), LpStatus::optimal);
    const LpOptimum root{lp.values(), lp.reduced_costs(), lp.objective()};
    const std::vector<Fixed> fixed(p.edges.size(), Fixed::free);
    for (const double cutoff : {lp.objective(), optimum - 0.5, optimum, optimum + 3.0}) {
      const NeighbourhoodSearch below =
          solve_below_cutoff(p, conflicts, root, cutoff, fixed, generous_limits());
      const std::string what = "seed " + std::to_string(seed) + " cutoff " + std::to_string(cutoff);
      ASSERT_TRUE(below.complete) << what;
      if (below.best.found) EXPECT_TRUE(check_solution(p, below.best.edges).feasible) << what;
      if (optimum <= cutoff) {
        ASSERT_TRUE(below.proven) << what;
        EXPECT_NEAR(below.best.objective, optimum, 1e-9 * std::max(1.0, std::abs(optimum))) << what;
        ++proven;
      } else {
        EXPECT_FALSE(below.proven) << what;
        if (below.best.found) EXPECT_GT(below.best.objective, cutoff) << what;
        ++refuted;
      }
    }
  }
  EXPECT_GT(proven, 100);
  EXPECT_GT(refuted, 100);
}

// The relaxation's dual, checked, bounds the optimum; every matching of cost <= C keeps clear of
// the edges it rules out below C, and what is left has the same optimum. Against brute force.
TEST(MatchingDualBound, RulesOutOnlyEdgesThatNoMatchingBelowTheCostUses) {
  int ruled_out = 0, bounded = 0, more_rounds = 0;
  for (std::uint64_t seed = 1; seed <= 200; ++seed) {
    const MatchingProblem p = tiny_instance(seed);
    const std::vector<Matching> matchings = feasible_matchings(p);
    const ProblemAdjacency adjacency = adjacency_of(p);
    const CheckedBound checked =
        check_dual_bound(p, adjacency, relaxation_dual(p, adjacency, 10.0));
    const std::string what = "seed " + std::to_string(seed);
    ASSERT_TRUE(checked.valid) << what << ": " << checked.error;
    if (matchings.empty()) continue;
    const double optimum = brute_force_optimum(p);
    EXPECT_LE(checked.bound, optimum) << what;
    bounded += checked.bound > optimum - 1.0;
    for (const double cost : {optimum - 0.5, optimum, optimum + 2.0}) {
      const std::vector<std::uint8_t> allowed = edges_below(p, adjacency, checked, cost);
      ruled_out += static_cast<int>(std::count(allowed.begin(), allowed.end(), 0));
      for (const Matching& matching : matchings)
        if (matching.cost <= cost)
          for (std::uint32_t e : matching.edges) EXPECT_TRUE(allowed[e]) << what << " edge " << e;
    }
    for (const double cost : {optimum, optimum + 2.0}) {
      const Reduction reduction = reduce_below(p, cost, 10.0);
      const Component& part = reduction.part;
      EXPECT_EQ(part.problem.is_virtual, p.is_virtual) << what;
      EXPECT_EQ(brute_force_optimum(part.problem), optimum) << what;
      EXPECT_LE(reduction.bound.bound, optimum) << what;
      std::vector<std::uint8_t> left(p.edges.size(), 0);
      for (std::uint32_t i = 0; i < part.edge_of.size(); ++i) {
        const MatchingEdge &kept = part.problem.edges[i], &edge = p.edges[part.edge_of[i]];
        EXPECT_TRUE(kept.u == edge.u && kept.v == edge.v && kept.weight == edge.weight) << what;
        left[part.edge_of[i]] = 1;
      }
      for (const Matching& matching : matchings)
        if (matching.cost <= cost)
          for (std::uint32_t e : matching.edges) EXPECT_TRUE(left[e]) << what << " edge " << e;
      more_rounds += reduction.rounds > 2;
    }
  }
  EXPECT_GT(ruled_out, 1000);  // the fixing does something
  EXPECT_GT(bounded, 100);     // and the bound is mostly within 1 of the optimum
  EXPECT_GT(more_rounds, 0);   // a round on what is left rules out more
}

// On planted instances dense in conflicts, whose root relaxation leaves a gap (the search
// branches), probing rules out edges that the fixing keeps; what is left keeps an optimal
// matching, and GLPK finds the same optimum on it.
TEST(MatchingDualBound, ProbingRulesOutMoreAndWhatIsLeftKeepsTheOptimum) {
  std::size_t probed = 0;
  for (std::uint32_t seed = 1; seed <= 6; ++seed) {
    PlantedSpec spec;
    spec.ports = 40;
    spec.extra_edges = 120;
    spec.conflicts = 320;
    spec.seed = seed;
    const MatchingProblem p = planted_instance(spec);
    const MatchingResult exact = solve_matching(p, SolverKind::exact, 60.0);
    ASSERT_EQ(exact.status, SolveStatus::optimal) << "seed " << seed;
    const Reduction reduction =
        reduce_below(p, exact.objective + 1e-7 * std::abs(exact.objective), 60.0);
    std::vector<std::uint8_t> left(p.edges.size(), 0);
    for (std::uint32_t e : reduction.part.edge_of) left[e] = 1;
    for (std::uint32_t e : exact.edges) EXPECT_TRUE(left[e]) << "seed " << seed << " edge " << e;
    const MatchingResult glpk = solve_matching(reduction.part.problem, SolverKind::glpk, 60.0);
    EXPECT_EQ(glpk.status, SolveStatus::optimal) << "seed " << seed;
    EXPECT_NEAR(glpk.objective, exact.objective, 1e-9) << "seed " << seed;
    probed += reduction.probed;
  }
  EXPECT_GT(probed, 0u);
}

// A square 0-1-2-3 (edges 0-1, 2-3, 1-2, 0-3, weight 1) and a virtual port 4 joined to 3.
MatchingProblem square_with_a_virtual_port() {
  MatchingProblem p;
  p.is_virtual = {0, 0, 0, 0, 1};
  p.edges = {{0, 1, 1.0}, {2, 3, 1.0}, {1, 2, 1.0}, {0, 3, 1.0}, {3, 4, 5.0}};
  p.conflicts = {{1, 4}};
  return p;
}

std::vector<DualRow> half_on_every_port() {
  std::vector<DualRow> rows;
  for (std::uint32_t v = 0; v < 4; ++v) rows.push_back({DualRowKind::degree, v, {}, 0.5});
  return rows;
}

TEST(MatchingDualBound, RefusesRowsThatAreNotValid) {
  const MatchingProblem p = square_with_a_virtual_port();
  const ProblemAdjacency adjacency = adjacency_of(p);
  const CheckedBound degrees = check_dual_bound(p, adjacency, half_on_every_port());
  ASSERT_TRUE(degrees.valid);
  EXPECT_NEAR(degrees.bound, 2.0, 1e-9);  // the optimum: both perfect matchings cost 2
  const auto check_with = [&](DualRow row) {
    std::vector<DualRow> rows = half_on_every_port();
    rows.push_back(std::move(row));
    return check_dual_bound(p, adjacency, rows);
  };
  EXPECT_TRUE(check_with({DualRowKind::clique, 0, {1, 4}, -1.0}).valid);   // a conflict pair
  EXPECT_TRUE(check_with({DualRowKind::clique, 0, {0, 2}, -1.0}).valid);   // sharing node 1
  EXPECT_TRUE(check_with({DualRowKind::odd_set, 0, {0, 2}, -1.0}).valid);  // nodes 0, 1, 2
  const std::vector<std::pair<DualRow, std::string>> bad = {
      {{DualRowKind::clique, 0, {0, 1}, -1.0}, "edges 0 and 1 share no node"},
      {{DualRowKind::odd_set, 0, {0, 1}, -1.0}, "even number of nodes"},
      {{DualRowKind::clique, 0, {2, 0}, -1.0}, "not increasing"},
      {{DualRowKind::clique, 0, {0, 9}, -1.0}, "not increasing indices of edges"},
      {{DualRowKind::clique, 0, {}, -1.0}, "not increasing"},
      {{DualRowKind::degree, 7, {}, 1.0}, "node 7 is none"},
      {{DualRowKind::degree, 0, {}, std::nan("")}, "not a finite number"}};
  for (const auto& [row, message] : bad) {
    const CheckedBound checked = check_with(row);
    EXPECT_FALSE(checked.valid) << message;
    EXPECT_NE(checked.error.find("row 4: "), std::string::npos) << checked.error;
    EXPECT_NE(checked.error.find(message), std::string::npos) << checked.error;
  }
}

// check_dual_bound() of `rows` on `p`, which should be `bound`, and edges_below() of it at each
// cost.
std::vector<std::vector<std::uint8_t>> edges_below_costs(const MatchingProblem& p,
                                                         const std::vector<DualRow>& rows,
                                                         double bound,
                                                         const std::vector<double>& costs) {
  const ProblemAdjacency adjacency = adjacency_of(p);
  const CheckedBound checked = check_dual_bound(p, adjacency, rows);
  EXPECT_TRUE(checked.valid) << checked.error;
  EXPECT_NEAR(checked.bound, bound, 1e-9);
  std::vector<std::vector<std::uint8_t>> allowed;
  for (const double cost : costs) allowed.push_back(edges_below(p, adjacency, checked, cost));
  return allowed;
}

using Allowed = std::vector<std::vector<std::uint8_t>>;

// A multiplier of the wrong sign would prove too much: the virtual port's row is slack at the
// optimum, and +10 on it would claim a bound of 12. It counts as 0. Below cost 4 the edge to the
// virtual port (3-4) is ruled out (and below any cost: with it in, 0-1 and 1-2 are both forced).
TEST(MatchingDualBound, AMultiplierOfTheWrongSignCountsAsZero) {
  std::vector<DualRow> rows = half_on_every_port();
  rows.push_back({DualRowKind::degree, 4, {}, 10.0});
  rows.push_back({DualRowKind::clique, 0, {1, 4}, 3.0});
  EXPECT_EQ(edges_below_costs(square_with_a_virtual_port(), rows, 2.0, {4.0, 1e9}),
            (Allowed{{1, 1, 1, 1, 0}, {1, 1, 1, 1, 0}}));
}

// Multipliers 1 on the ports give the square's edges reduced cost -1 and a weak bound L = 0. An
// edge in the matching leaves out the two edges at its ends, whose -1 then no longer count: it
// costs at least L + 2. Below 1.5 every edge goes; below 2, the optimum, none of the square's.
TEST(MatchingDualBound, AnEdgeInLeavesOutTheNegativeReducedCostsOfTheEdgesItExcludes) {
  std::vector<DualRow> rows = half_on_every_port();
  for (DualRow& row : rows) row.multiplier = 1.0;
  EXPECT_EQ(edges_below_costs(square_with_a_virtual_port(), rows, 0.0, {1.5, 2.0}),
            (Allowed{{0, 0, 0, 0, 0}, {1, 1, 1, 1, 0}}));
}

// A square 0-1-2-3 whose edge 0-1 costs 0 and forces 2-3, which costs 5: with no multipliers,
// L = 0 and below cost 2 (the other perfect matching's) 0-1 goes too, by propagation.
TEST(MatchingDualBound, AnEdgeInCountsTheReducedCostsOfTheEdgesItForces) {
  MatchingProblem p;
  p.is_virtual = {0, 0, 0, 0};
  p.edges = {{0, 1, 0.0}, {2, 3, 5.0}, {1, 2, 1.0}, {0, 3, 1.0}};
  EXPECT_EQ(edges_below_costs(p, {}, 0.0, {2.0, 5.0}), (Allowed{{0, 0, 1, 1}, {1, 1, 1, 1}}));
}

// A path 0-1-2-3 with a chord 0-2 and a parallel edge 2-3: keeping edge 0-1 leaves nodes 2, 3
// open with the edges between them that are allowed and in no conflict with 0-1.
TEST(MatchingNeighbourhood, TheOpenPartHoldsTheCompatibleEdgesBetweenUncoveredNodes) {
  MatchingProblem p;
  p.is_virtual = {0, 0, 0, 1};
  p.edges = {{0, 1, 1.0}, {1, 2, 2.0}, {2, 3, 3.0}, {0, 2, 4.0}, {2, 3, 5.0}, {3, 2, 6.0}};
  p.conflicts = {{0, 4}, {2, 5}};  // 2-3 (weight 5) conflicts with the kept edge
  const std::vector<std::uint8_t> allowed = {1, 1, 1, 1, 1, 0};  // and 3-2 is not allowed
  const Component open = open_part(p, conflicting_edges(p), {0}, allowed);
  EXPECT_EQ(open.node_of, (std::vector<std::uint32_t>{2, 3}));
  EXPECT_EQ(open.problem.is_virtual, (std::vector<std::uint8_t>{0, 1}));
  EXPECT_EQ(open.edge_of, (std::vector<std::uint32_t>{2}));
  ASSERT_EQ(open.problem.edges.size(), 1u);
  EXPECT_EQ(open.problem.edges[0].u, 0u);
  EXPECT_EQ(open.problem.edges[0].v, 1u);
  EXPECT_EQ(open.problem.edges[0].weight, 3.0);
  EXPECT_TRUE(open.problem.conflicts.empty());  // its partner 3-2 is not in the open part
  // Nothing kept: the whole problem, its allowed edges and the conflict pairs among them.
  const Component all = open_part(p, conflicting_edges(p), {}, allowed);
  EXPECT_EQ(all.edge_of, (std::vector<std::uint32_t>{0, 1, 2, 3, 4}));
  ASSERT_EQ(all.problem.conflicts.size(), 1u);
  EXPECT_EQ(all.problem.conflicts[0].first, 0u);
  EXPECT_EQ(all.problem.conflicts[0].second, 4u);
}

TEST(MatchingBlossom, CoversPortsAtLeastWeightWithVirtualPorts) {
  for (std::uint64_t seed = 1; seed <= 200; ++seed) {
    MatchingProblem p = tiny_instance(seed);
    p.conflicts.clear();
    const double optimum = brute_force_optimum(p);
    std::vector<double> weights;
    for (const MatchingEdge& e : p.edges) weights.push_back(e.weight);
    const PortCover cover =
        min_weight_port_cover(p, weights, std::vector<std::uint8_t>(p.edges.size(), 1));
    ASSERT_EQ(cover.exists, std::isfinite(optimum)) << "seed " << seed;
    if (!cover.exists) continue;
    const SolutionCheck check = check_solution(p, cover.edges);
    EXPECT_TRUE(check.feasible) << "seed " << seed;
    EXPECT_EQ(check.objective, optimum) << "seed " << seed;
  }
}

TEST(MatchingSolver, NamesItsSolvers) {
  EXPECT_EQ(solver_kind_from_name("glpk-tuned"), SolverKind::glpk_tuned);
  EXPECT_STREQ(to_string(SolverKind::exact), "exact");
  EXPECT_THROW(solver_kind_from_name("cplex"), InputError);
}

}  // namespace
}  // namespace tessera::matching
