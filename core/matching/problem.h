// Program P1 of the thesis (Ch. 5, (5.1)-(5.4)): the minimum-weight perfect matching with conflict
// pairs (MWPMPC, Sec. 3.2) on the graph of the ports G.
//
//   minimize    sum_e w_e x_e                                           (5.1)
//   subject to  sum_{e in Adj(v)} x_e = 1   for every port v              (5.2)
//               sum_{e in Adj(v)} x_e <= 1  for every virtual port v (Sec. 4.4)
//               x_e1 + x_e2 <= 1            for every conflict pair (e1, e2) in I   (5.3)
//               x_e in {0, 1}                                           (5.4)
//
// The layout stage fills a MatchingProblem from its port graph (nodes = ports, edges = closed
// separatrices, conflicts = illegal crossings I and zero-area pairs Z, Sec. 4.6); the solvers
// (solver.h) return a MatchingResult whose chosen edges index problem.edges.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "base/limits.h"

namespace tessera::matching {

struct MatchingEdge {
  std::uint32_t u = 0;  // node indices, u != v; several edges may join the same two nodes
  std::uint32_t v = 0;
  double weight = 0.0;  // w_e, finite
};

struct ConflictPair {
  std::uint32_t first = 0;  // edge indices, first != second
  std::uint32_t second = 0;
};

struct MatchingProblem {
  // Node i is a port (matched exactly once) unless is_virtual[i] (matched at most once).
  std::vector<std::uint8_t> is_virtual;
  std::vector<MatchingEdge> edges;
  std::vector<ConflictPair> conflicts;

  std::size_t node_count() const { return is_virtual.size(); }
};

// Weights beyond this magnitude are refused: no layout makes them, and LP solvers (GLPK's simplex
// with its relative tolerances of 1e-7) lose the small weights beside them.
constexpr double kMaxWeight = 1e9;

// Throws InputError naming the first bad node, edge or conflict (index out of range, self-loop,
// a weight that is not finite or above kMaxWeight in magnitude, a conflict of an edge with itself)
// and LimitError when the sizes exceed limits.max_matching_nodes, max_matching_edges or
// max_matching_conflicts. `source` (a file name) prefixes the messages.
void validate_problem(const MatchingProblem& problem, const Limits& limits,
                      const std::string& source);

// The objective (5.1) of a set of edges.
double objective_of(const MatchingProblem& problem, const std::vector<std::uint32_t>& edges);

}  // namespace tessera::matching
