#include "matching/blossom.h"

#include <lemon/matching.h>
#include <lemon/smart_graph.h>

#include <algorithm>
#include <cmath>

namespace tessera::matching {

namespace {

using Graph = lemon::SmartGraph;

// G with the virtual-port completion; `edge_of[k]` is the problem edge of LEMON edge k, or -1 for
// a dummy edge.
struct CompletedGraph {
  Graph graph;
  std::vector<Graph::Node> nodes;
  std::vector<std::int64_t> edge_of;
};

void add_virtual_completion(const MatchingProblem& problem, CompletedGraph& g) {
  std::vector<Graph::Node> virtual_nodes;
  for (std::size_t v = 0; v < problem.node_count(); ++v)
    if (problem.is_virtual[v]) virtual_nodes.push_back(g.nodes[v]);
  for (std::size_t i = 0; i < virtual_nodes.size(); ++i)
    for (std::size_t j = i + 1; j < virtual_nodes.size(); ++j) {
      g.graph.addEdge(virtual_nodes[i], virtual_nodes[j]);
      g.edge_of.push_back(-1);
    }
  if (problem.node_count() % 2 == 1 && !virtual_nodes.empty()) {
    const Graph::Node extra = g.graph.addNode();
    for (const Graph::Node& v : virtual_nodes) {
      g.graph.addEdge(extra, v);
      g.edge_of.push_back(-1);
    }
  }
}

// The allowed edges, the cheapest of each parallel class only (by `weights`, lowest index on ties):
// the edges bucketed by their smaller end (a counting sort, stable), then per bucket the cheapest
// edge to each larger end. Linear, as the dive calls it at every decision.
std::vector<std::uint32_t> offered_edges(const MatchingProblem& problem,
                                         const std::vector<double>& weights,
                                         const std::vector<std::uint8_t>& allowed) {
  const std::size_t n = problem.node_count();
  std::vector<std::uint32_t> start(n + 1, 0);
  for (std::uint32_t e = 0; e < problem.edges.size(); ++e)
    if (allowed[e]) ++start[std::min(problem.edges[e].u, problem.edges[e].v) + 1];
  for (std::size_t v = 0; v < n; ++v) start[v + 1] += start[v];
  std::vector<std::uint32_t> bucketed(start[n]);
  std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
  for (std::uint32_t e = 0; e < problem.edges.size(); ++e)
    if (allowed[e]) bucketed[fill[std::min(problem.edges[e].u, problem.edges[e].v)]++] = e;
  constexpr std::uint32_t kNone = static_cast<std::uint32_t>(-1);
  std::vector<std::uint32_t> seen_from(n, kNone), slot_of(n, 0);
  std::vector<std::uint32_t> offered;
  for (std::uint32_t u = 0; u < n; ++u)
    for (std::uint32_t k = start[u]; k < start[u + 1]; ++k) {
      const std::uint32_t e = bucketed[k];
      const std::uint32_t v = std::max(problem.edges[e].u, problem.edges[e].v);
      if (seen_from[v] != u) {
        seen_from[v] = u;
        slot_of[v] = static_cast<std::uint32_t>(offered.size());
        offered.push_back(e);
      } else if (weights[e] < weights[offered[slot_of[v]]]) {
        offered[slot_of[v]] = e;
      }
    }
  std::sort(offered.begin(), offered.end());
  return offered;
}

void build(const MatchingProblem& problem, const std::vector<std::uint32_t>& offered,
           CompletedGraph& g) {
  g.graph.reserveNode(static_cast<int>(problem.node_count()) + 1);
  for (std::size_t v = 0; v < problem.node_count(); ++v) g.nodes.push_back(g.graph.addNode());
  for (std::uint32_t e : offered) {
    g.graph.addEdge(g.nodes[problem.edges[e].u], g.nodes[problem.edges[e].v]);
    g.edge_of.push_back(e);
  }
  add_virtual_completion(problem, g);
}

}  // namespace

PortCover min_weight_port_cover(const MatchingProblem& problem, const std::vector<double>& weights,
                                const std::vector<std::uint8_t>& allowed) {
  CompletedGraph g;
  build(problem, offered_edges(problem, weights, allowed), g);
  double largest = 1.0;
  for (std::int64_t e : g.edge_of)
    if (e >= 0) largest = std::max(largest, std::abs(weights[static_cast<std::size_t>(e)]));
  // Integer weights keep the blossom algorithm exact; it maximizes, so they are negated.
  const double scale = std::ldexp(1.0, 36) / largest;
  Graph::EdgeMap<std::int64_t> gain(g.graph, 0);
  for (Graph::EdgeIt it(g.graph); it != lemon::INVALID; ++it) {
    const std::int64_t e = g.edge_of[static_cast<std::size_t>(g.graph.id(it))];
    if (e >= 0) gain[it] = -std::llround(weights[static_cast<std::size_t>(e)] * scale);
  }
  lemon::MaxWeightedPerfectMatching<Graph, Graph::EdgeMap<std::int64_t>> blossom(g.graph, gain);
  PortCover cover;
  cover.exists = blossom.run();
  if (!cover.exists) return cover;
  for (Graph::EdgeIt it(g.graph); it != lemon::INVALID; ++it) {
    const std::int64_t e = g.edge_of[static_cast<std::size_t>(g.graph.id(it))];
    if (e >= 0 && blossom.matching(it)) cover.edges.push_back(static_cast<std::uint32_t>(e));
  }
  std::sort(cover.edges.begin(), cover.edges.end());
  return cover;
}

std::vector<std::uint32_t> deficient_ports(const MatchingProblem& problem,
                                           const std::vector<std::uint8_t>& allowed) {
  CompletedGraph g;
  const std::vector<double> zero(problem.edges.size(), 0.0);
  build(problem, offered_edges(problem, zero, allowed), g);
  lemon::MaxMatching<Graph> matching(g.graph);
  matching.run();
  std::vector<std::uint32_t> deficient;
  if (2 * matching.matchingSize() == lemon::countNodes(g.graph)) return deficient;
  for (std::size_t v = 0; v < problem.node_count(); ++v)
    if (!problem.is_virtual[v] && matching.status(g.nodes[v]) == lemon::MaxMatching<Graph>::EVEN)
      deficient.push_back(static_cast<std::uint32_t>(v));
  return deficient;
}

}  // namespace tessera::matching
