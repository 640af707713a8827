// Compressed adjacency lists of a P1 instance, shared by the clique cover, the preprocessing and
// the search: the edges at each node, and the edges each edge conflicts with or excludes.
#pragma once

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "matching/problem.h"

namespace tessera::matching {

// Sorted lists, one per index.
struct Adjacency {
  std::vector<std::uint32_t> start;  // size n + 1
  std::vector<std::uint32_t> list;

  std::size_t size() const { return start.empty() ? 0 : start.size() - 1; }
  std::span<const std::uint32_t> of(std::uint32_t i) const {
    return {list.data() + start[i], list.data() + start[i + 1]};
  }
  bool contains(std::uint32_t i, std::uint32_t j) const;
};

// From (i, j) pairs over n indices; duplicates are dropped.
Adjacency adjacency_from_pairs(std::size_t n,
                               const std::vector<std::pair<std::uint32_t, std::uint32_t>>& pairs);

// Per node, the edges at it.
Adjacency incident_edges(const MatchingProblem& problem);

// Per edge, the edges it forms a conflict pair (5.3) with.
Adjacency conflicting_edges(const MatchingProblem& problem);

// Per edge, the edges that cannot be chosen with it: its conflicts and the edges sharing a node.
Adjacency exclusive_edges(const MatchingProblem& problem);

// The three of a problem, for the stages that need them all.
struct ProblemAdjacency {
  Adjacency incident, conflicts, exclusive;
};
ProblemAdjacency adjacency_of(const MatchingProblem& problem);

}  // namespace tessera::matching
