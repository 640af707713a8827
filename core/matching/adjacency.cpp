#include "matching/adjacency.h"

#include <algorithm>

namespace tessera::matching {

namespace {

std::vector<std::pair<std::uint32_t, std::uint32_t>> conflict_pairs(const MatchingProblem& p) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  pairs.reserve(2 * p.conflicts.size());
  for (const ConflictPair& c : p.conflicts) {
    pairs.emplace_back(c.first, c.second);
    pairs.emplace_back(c.second, c.first);
  }
  return pairs;
}

}  // namespace

bool Adjacency::contains(std::uint32_t i, std::uint32_t j) const {
  const auto list = of(i);
  return std::binary_search(list.begin(), list.end(), j);
}

// Bucketed by the first index (a counting sort), then each list sorted and made unique: linear in
// the pairs but for the short per-index sorts.
Adjacency adjacency_from_pairs(std::size_t n,
                               const std::vector<std::pair<std::uint32_t, std::uint32_t>>& pairs) {
  std::vector<std::uint32_t> start(n + 1, 0);
  for (const auto& [a, b] : pairs) ++start[a + 1];
  for (std::size_t i = 0; i < n; ++i) start[i + 1] += start[i];
  std::vector<std::uint32_t> list(pairs.size());
  std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
  for (const auto& [a, b] : pairs) list[fill[a]++] = b;
  Adjacency adj;
  adj.start.assign(n + 1, 0);
  adj.list.reserve(list.size());
  for (std::size_t i = 0; i < n; ++i) {
    const auto first = list.begin() + start[i], last = list.begin() + start[i + 1];
    std::sort(first, last);
    adj.list.insert(adj.list.end(), first, std::unique(first, last));
    adj.start[i + 1] = static_cast<std::uint32_t>(adj.list.size());
  }
  return adj;
}

Adjacency incident_edges(const MatchingProblem& problem) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  pairs.reserve(2 * problem.edges.size());
  for (std::uint32_t e = 0; e < problem.edges.size(); ++e) {
    pairs.emplace_back(problem.edges[e].u, e);
    pairs.emplace_back(problem.edges[e].v, e);
  }
  return adjacency_from_pairs(problem.node_count(), pairs);
}

Adjacency conflicting_edges(const MatchingProblem& problem) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs = conflict_pairs(problem);
  return adjacency_from_pairs(problem.edges.size(), pairs);
}

Adjacency exclusive_edges(const MatchingProblem& problem) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs = conflict_pairs(problem);
  const Adjacency incident = incident_edges(problem);
  for (std::uint32_t v = 0; v < incident.size(); ++v)
    for (std::uint32_t a : incident.of(v))
      for (std::uint32_t b : incident.of(v))
        if (a != b) pairs.emplace_back(a, b);
  return adjacency_from_pairs(problem.edges.size(), pairs);
}

ProblemAdjacency adjacency_of(const MatchingProblem& problem) {
  return {incident_edges(problem), conflicting_edges(problem), exclusive_edges(problem)};
}

}  // namespace tessera::matching
