// The exact solver's search: LP-based branch-and-bound on P1 (thesis (5.1)-(5.4)).
//
// Each node solves the relaxation (lp_relaxation.h) with the dual simplex method from its parent's
// basis and is pruned when its bound reaches the incumbent. Edges whose reduced cost alone lifts
// the bound to the incumbent are fixed to 0 (or to 1) in the node's subtree (reduced-cost fixing).
// A fractional edge e is branched on, the one whose pseudocosts (the mean bound gains per unit of
// change seen so far when branching on it, down and up) have the largest product, counted twice
// for a preferred edge. The layout's loop rounds prefer the edges of the pairs they added
// (exact_solver.h): the relaxation without those pairs was integral or nearly so, and with them
// it spreads over many edges at a half or a quarter; early in a search, when no pseudocost is
// known yet and many scores tie, the branchings then go to those pairs first. On fertility's 41
// slider positions the trees had 340 nodes in all instead of 640 (alpha 6 to 9, second round: 11
// to 37 instead of 44 to 79; eight: 28 instead of 40), with the same optima (a weight of 1.5 gave
// 342 nodes, 3 gave 417, branching on them before any other edge 518, alpha 0 alone 268). The child
// x_e = 1 comes first (it settles the edge's two ports and every conflict pair it is in), explored
// depth-first until that dive ends, then x_e = 0; the next dive starts at the open node of least
// bound. New incumbents are improved by local search. The search ends when no open node can beat
// the incumbent (optimal; the gap is closed) or at the deadline or node limit, with the least open
// bound as the proven lower bound.
#pragma once

#include <chrono>
#include <cstdint>
#include <vector>

#include "base/progress.h"
#include "matching/incumbent.h"
#include "matching/lp_relaxation.h"
#include "matching/problem.h"

namespace tessera::matching {

struct SearchResult {
  Incumbent best;
  double lower_bound = 0.0;  // proven; equals best.objective when complete and found
  bool complete = false;     // every node was settled
  std::uint64_t nodes = 0;
};

struct SearchLimits {
  std::chrono::steady_clock::time_point deadline;
  // A node limit bounds the search by its work, not by the machine's speed: the same result on
  // every run and machine (used for the search inside a heuristic, exact_solver.cpp).
  std::uint64_t max_nodes = UINT64_MAX;
};

// `lp` holds the root relaxation with the preprocessing's fixings `root` applied; `preferred`
// marks edges the branching prefers (per edge, or empty for none); `exclusion` is the exclusion
// graph whose violated cliques are separated at every node; `start` is the best
// matching known so far (or none); `root_bound` a proven lower bound of P1 (e.g. the cheapest
// matching without conflicts, which may exceed the relaxation's), the least bound of every node.
SearchResult branch_and_bound(const MatchingProblem& problem, LpRelaxation& lp,
                              const Adjacency& exclusion, const std::vector<Fixed>& root,
                              const std::vector<std::uint8_t>& preferred,
                              const IncumbentSearch& heuristics, Incumbent start, double root_bound,
                              const SearchLimits& limits, const Progress& progress);

// Pruning tolerance: a node whose bound is within this of the incumbent cannot improve it.
double bound_tolerance(double incumbent);

}  // namespace tessera::matching
