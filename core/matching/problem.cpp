#include "matching/problem.h"

#include <cmath>

#include "base/error.h"

namespace tessera::matching {

namespace {

[[noreturn]] void fail(const std::string& source, const std::string& message) {
  throw InputError(source + ": " + message);
}

void validate_edges(const MatchingProblem& problem, const std::string& source) {
  const std::size_t n = problem.node_count();
  for (std::size_t e = 0; e < problem.edges.size(); ++e) {
    const MatchingEdge& edge = problem.edges[e];
    const std::string name = "edge " + std::to_string(e);
    if (edge.u >= n || edge.v >= n)
      fail(source, name + " joins node " + std::to_string(edge.u >= n ? edge.u : edge.v) +
                       " but there are only " + std::to_string(n) + " nodes");
    if (edge.u == edge.v)
      fail(source, name + " is a loop at node " + std::to_string(edge.u) +
                       "; an edge of the port graph joins two different ports");
    if (!(std::abs(edge.weight) <= kMaxWeight))
      fail(source, name + " has the weight " + std::to_string(edge.weight) +
                       "; weights are lengths and must be finite, at most 1e9 in magnitude");
  }
}

void validate_conflicts(const MatchingProblem& problem, const std::string& source) {
  const std::size_t m = problem.edges.size();
  for (std::size_t k = 0; k < problem.conflicts.size(); ++k) {
    const ConflictPair& c = problem.conflicts[k];
    const std::string name = "conflict " + std::to_string(k);
    if (c.first >= m || c.second >= m)
      fail(source, name + " names edge " + std::to_string(c.first >= m ? c.first : c.second) +
                       " but there are only " + std::to_string(m) + " edges");
    if (c.first == c.second)
      fail(source, name + " pairs edge " + std::to_string(c.first) + " with itself");
  }
}

}  // namespace

void validate_problem(const MatchingProblem& problem, const Limits& limits,
                      const std::string& source) {
  check_limit(problem.node_count(), limits.max_matching_nodes, source + " (nodes)", "--max-nodes");
  check_limit(problem.edges.size(), limits.max_matching_edges, source + " (edges)", "--max-edges");
  check_limit(problem.conflicts.size(), limits.max_matching_conflicts, source + " (conflicts)",
              "--max-conflicts");
  validate_edges(problem, source);
  validate_conflicts(problem, source);
}

double objective_of(const MatchingProblem& problem, const std::vector<std::uint32_t>& edges) {
  double sum = 0.0;
  for (std::uint32_t e : edges) sum += problem.edges[e].weight;
  return sum;
}

}  // namespace tessera::matching
