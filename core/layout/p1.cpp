#include "layout/p1.h"

namespace tessera::layout {

matching::MatchingProblem matching_problem(const PortGraph& graph, double alpha) {
  matching::MatchingProblem problem;
  problem.is_virtual.assign(graph.node_count(), 1);
  for (std::size_t v = 0; v < graph.port_count(); ++v)
    problem.is_virtual[v] = graph.ports.ports[v].folded;
  problem.edges.reserve(graph.edges.size());
  for (const GraphEdge& e : graph.edges) problem.edges.push_back({e.u, e.v, edge_weight(e, alpha)});
  problem.conflicts.reserve(graph.conflicts.size());
  for (const EdgePair& pair : graph.conflicts)
    problem.conflicts.push_back({pair.first, pair.second});
  return problem;
}

void add_loop_conflicts(const std::vector<EdgePair>& loop_pairs,
                        matching::MatchingProblem& problem) {
  for (const EdgePair& pair : loop_pairs) problem.conflicts.push_back({pair.first, pair.second});
}

}  // namespace tessera::layout
