// A lower bound on P1 that anyone can check, and the edges it rules out below a cost: the dual of
// the linear relaxation (lp_relaxation.h) as a list of valid rows with their multipliers (weak
// LP duality), checked from the problem alone, without trusting the LP solver, then reduced-cost
// fixing.
//
// A matching x that costs at most `cost` has, for multipliers y of valid rows a_r x <= b_r
// (y_r <= 0) and a_r x = b_r (y free), reduced costs d = w - sum_r y_r a_r, bound
// L = sum_r y_r b_r + sum_e min(0, d_e):
//   w x >= sum_r y_r b_r + d x >= L + |d_e| for each edge e with d_e > 0 and x_e = 1, or with
//   d_e < 0 and x_e = 0. x_e = 1 forces, by propagation (propagation.h), the edges O(e) (e among
//   them) to 1 and the edges Z(e) to 0 (those that share a node or form a conflict pair with an
//   edge of O(e), and so on), or ends in a contradiction; then
//   w x >= L + sum_{g in O(e)} max(0, d_g) + sum_{f in Z(e)} max(0, -d_f).
// So no such matching uses an edge with a contradiction or with that sum > cost, nor an edge
// that excludes an edge e with L - d_e > cost. Each edge ruled out is fixed to 0 and propagated
// for the edges after it, in passes until none is ruled out; the edges so fixed (to 0, or to 1
// where a port is left with one edge) add their terms to L for every edge's test. The instance
// without those edges has every matching of cost <= `cost`: the same optimum, if that costs no
// more. Its purpose: second solvers (GLPK, CBC) that cannot solve the whole instance can confirm
// the optimum on what is left.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "matching/adjacency.h"
#include "matching/components.h"
#include "matching/problem.h"

namespace tessera::matching {

// The rows of the relaxation, each valid for every matching without conflicts.
enum class DualRowKind : std::uint8_t {
  degree,   // (5.2): the edges at `node` sum to 1 (at most 1 at a virtual port)
  clique,   // the edges pairwise share a node or form a conflict pair (5.3): they sum to <= 1
  odd_set,  // the edges span an odd number k of nodes: they sum to <= (k - 1) / 2
};

struct DualRow {
  DualRowKind kind = DualRowKind::degree;
  std::uint32_t node = 0;            // degree rows
  std::vector<std::uint32_t> edges;  // clique and odd-set rows, increasing
  double multiplier = 0.0;           // y_r
};

struct CheckedBound {
  bool valid = false;
  std::string error;                  // why not: the first bad row
  double bound = 0.0;                 // L, less a margin for rounding
  std::vector<double> reduced_costs;  // d per edge
};

// Checks every row against the problem (degree rows are taken from the problem itself; multipliers
// of the wrong sign count as 0) and computes L and d in extended precision.
CheckedBound check_dual_bound(const MatchingProblem& problem, const ProblemAdjacency& adjacency,
                              const std::vector<DualRow>& rows);

// The rows of the relaxation at its optimum: degree rows, then the clique rows of the conflict
// pairs (the cover, and the violated cliques of the exclusion graph) and the odd-set rows that the
// cut rounds bring in, until none is violated or `seconds` pass (then the rows so far: a weaker
// bound, still valid).
std::vector<DualRow> relaxation_dual(const MatchingProblem& problem,
                                     const ProblemAdjacency& adjacency, double seconds);

// Per edge, 0 where `bound` shows that no matching of cost <= `cost` uses it.
std::vector<std::uint8_t> edges_below(const MatchingProblem& problem,
                                      const ProblemAdjacency& adjacency, const CheckedBound& bound,
                                      double cost);

// What is left of the problem below `cost`: the same nodes, the edges that no round rules out
// (edge_of: their indices in `problem`), the conflict pairs among them. Each round solves the
// relaxation of what the rounds before left, checks its dual and drops the edges edges_below()
// rules out; every matching of cost <= `cost` keeps clear of them, so it is in what is left, whose
// relaxation is tighter. Where the fixing rules out none, probing: per edge, the relaxation with
// x_e = 1 (where it has x_e < 1) and with x_e = 0 (where it has x_e > 0), its dual checked as
// above (with what x_e = 1 propagates, or with e's own reduced cost for x_e = 0); where that bound
// exceeds `cost`, e is fixed to the other value, with what that propagates. The rounds go on while
// one drops an edge and `seconds` last. `bound` is the last round's: a lower bound on every
// matching of cost <= `cost`.
struct Reduction {
  CheckedBound bound;
  Component part;
  int rounds = 0;
  std::size_t probed = 0;  // edges fixed by probing (to 0, or to 1 with their consequences)
};
Reduction reduce_below(const MatchingProblem& problem, double cost, double seconds);

}  // namespace tessera::matching
