// Feasible matchings for the exact solver's upper bound.
//
// Lagrangian repair: the conflict pairs are priced into the weights (w_e plus the multipliers of
// the cliques that hold e, e.g. the clique rows' duals of the LP relaxation), and the cheapest
// matching covering every port for those weights is computed by the blossom algorithm. While it
// holds conflict pairs, the dearer edge of each pair is dropped and the uncovered ports are
// covered again with edges compatible with the rest; when that fails, the edges in conflict are
// priced up and the whole matching is recomputed.
//
// Diving: edges are visited in a given order (e.g. by decreasing LP value); each is set to 1 if
// propagation (propagation.h) allows it, else to 0. When setting 0 fails too, the last edge set
// to 1 is set to 0 instead (depth-first backtracking, a bounded number of times). Cheap: no LP
// is solved.
//
// Local search: exchanges that keep the matching feasible and make it cheaper, to a local optimum:
// two matched edges a-b, c-d replaced by a-c, b-d or a-d, b-c, and one matched edge replaced by
// a cheaper parallel edge or, at a virtual port, by an edge to an unmatched virtual port.
#pragma once

#include <chrono>
#include <cstdint>
#include <vector>

#include "matching/adjacency.h"
#include "matching/problem.h"
#include "matching/propagation.h"

namespace tessera::matching {

struct Incumbent {
  bool found = false;
  std::vector<std::uint32_t> edges;  // increasing
  double objective = 0.0;
};

class IncumbentSearch {
 public:
  // The adjacency lists are those of `problem` (adjacency.h; `exclusive` may hold implied
  // exclusions too). Edges fixed to 0 are never used, edges fixed to 1 always in a dive.
  IncumbentSearch(const MatchingProblem& problem, const Adjacency& incident,
                  const Adjacency& conflicts, const Adjacency& exclusive,
                  const std::vector<Fixed>& fixed);

  // Nothing if it passes `deadline` (on dragon at alpha 0 a failed dive took 7.3 s).
  Incumbent dive(const std::vector<std::uint32_t>& order,
                 std::chrono::steady_clock::time_point deadline =
                     std::chrono::steady_clock::time_point::max()) const;

  // `prices[e]` is added to w_e in the first round (the clique multipliers summed over e's
  // cliques).
  Incumbent lagrangian_repair(const std::vector<double>& prices, int rounds) const;

  // Improves a feasible matching in place to a local optimum of the exchanges above.
  void improve(Incumbent& incumbent) const;

 private:
  bool covers_every_port(const std::vector<Fixed>& values) const;
  bool conflict_free_with(std::uint32_t e, const std::vector<std::uint8_t>& chosen) const;
  std::vector<std::uint32_t> conflicting_members(const std::vector<std::uint32_t>& edges) const;
  bool fill(std::vector<std::uint32_t>& kept, const std::vector<double>& weights) const;
  bool try_swap(std::uint32_t e, std::uint32_t f, std::vector<std::uint8_t>& chosen,
                std::vector<std::int64_t>& edge_at) const;
  bool try_replace(std::uint32_t e, std::vector<std::uint8_t>& chosen,
                   std::vector<std::int64_t>& edge_at) const;
  std::int64_t cheapest_between(std::uint32_t a, std::uint32_t b,
                                const std::vector<std::uint8_t>& chosen) const;

  const MatchingProblem& problem_;
  const Adjacency& incident_;
  const Adjacency& conflicts_;
  const Adjacency& exclusive_;
  std::vector<Fixed> fixed_;
  std::vector<std::uint8_t> allowed_;
  double tolerance_;  // an exchange must gain more than this (relative to the largest weight)
};

}  // namespace tessera::matching
