#include "matching/components.h"

#include "base/disjoint_sets.h"

namespace tessera::matching {

std::vector<Component> split_components(const MatchingProblem& problem) {
  DisjointSets sets(problem.node_count());
  for (const MatchingEdge& e : problem.edges) sets.join(e.u, e.v);
  for (const ConflictPair& c : problem.conflicts)
    sets.join(problem.edges[c.first].u, problem.edges[c.second].u);
  std::vector<std::int64_t> component_of_root(problem.node_count(), -1);
  std::vector<std::uint32_t> local_node(problem.node_count());
  std::vector<Component> components;
  for (std::uint32_t v = 0; v < problem.node_count(); ++v) {
    const std::size_t root = sets.find(v);
    if (component_of_root[root] < 0) {
      component_of_root[root] = static_cast<std::int64_t>(components.size());
      components.emplace_back();
    }
    Component& part = components[static_cast<std::size_t>(component_of_root[root])];
    local_node[v] = static_cast<std::uint32_t>(part.problem.node_count());
    part.problem.is_virtual.push_back(problem.is_virtual[v]);
    part.node_of.push_back(v);
  }
  std::vector<std::uint32_t> local_edge(problem.edges.size());
  for (std::uint32_t e = 0; e < problem.edges.size(); ++e) {
    const MatchingEdge& edge = problem.edges[e];
    Component& c = components[static_cast<std::size_t>(component_of_root[sets.find(edge.u)])];
    local_edge[e] = static_cast<std::uint32_t>(c.problem.edges.size());
    c.problem.edges.push_back({local_node[edge.u], local_node[edge.v], edge.weight});
    c.edge_of.push_back(e);
  }
  for (const ConflictPair& pair : problem.conflicts) {
    const std::uint32_t root = sets.find(problem.edges[pair.first].u);
    components[static_cast<std::size_t>(component_of_root[root])].problem.conflicts.push_back(
        {local_edge[pair.first], local_edge[pair.second]});
  }
  return components;
}

Component open_part(const MatchingProblem& problem, const Adjacency& conflicts,
                    const std::vector<std::uint32_t>& kept,
                    const std::vector<std::uint8_t>& allowed) {
  const std::size_t m = problem.edges.size();
  std::vector<std::int64_t> local(problem.node_count(), 0);
  std::vector<std::uint8_t> blocked(m, 0);
  for (std::uint32_t e : kept) {
    local[problem.edges[e].u] = local[problem.edges[e].v] = -1;
    for (std::uint32_t f : conflicts.of(e)) blocked[f] = 1;
  }
  Component open;
  for (std::uint32_t v = 0; v < problem.node_count(); ++v) {
    if (local[v] < 0) continue;
    local[v] = static_cast<std::int64_t>(open.node_of.size());
    open.node_of.push_back(v);
    open.problem.is_virtual.push_back(problem.is_virtual[v]);
  }
  std::vector<std::int64_t> open_edge(m, -1);
  for (std::uint32_t e = 0; e < m; ++e) {
    const MatchingEdge& edge = problem.edges[e];
    if (!allowed[e] || blocked[e] || local[edge.u] < 0 || local[edge.v] < 0) continue;
    open_edge[e] = static_cast<std::int64_t>(open.edge_of.size());
    open.problem.edges.push_back({static_cast<std::uint32_t>(local[edge.u]),
                                  static_cast<std::uint32_t>(local[edge.v]), edge.weight});
    open.edge_of.push_back(e);
  }
  for (std::uint32_t i = 0; i < open.edge_of.size(); ++i)
    for (std::uint32_t f : conflicts.of(open.edge_of[i]))
      if (f > open.edge_of[i] && open_edge[f] >= 0)
        open.problem.conflicts.push_back({i, static_cast<std::uint32_t>(open_edge[f])});
  return open;
}

}  // namespace tessera::matching
