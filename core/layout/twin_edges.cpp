#include "layout/twin_edges.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace tessera::layout {
namespace {

// Lengths this close (relative to the base) are the same; the same tolerance as case 3 of C1.
constexpr double kSameLength = 1e-6;

bool twins(const GraphEdge& a, const GraphEdge& b) {
  const double tolerance = kSameLength * std::max({1.0, a.base, b.base});
  return a.kind == EdgeKind::crossing && b.kind == EdgeKind::crossing && a.side == b.side &&
         std::abs(a.base - b.base) <= tolerance && std::abs(a.height - b.height) <= tolerance;
}

// Per edge, the edge it is a twin of (itself for the first of its twins).
std::vector<Index> first_twins(const PortGraph& graph) {
  std::map<std::pair<Index, Index>, std::vector<Index>> by_ports;
  std::vector<Index> first(graph.edges.size());
  for (Index e = 0; e < graph.edges.size(); ++e) {
    const GraphEdge& edge = graph.edges[e];
    std::vector<Index>& same_ports = by_ports[{std::min(edge.u, edge.v), std::max(edge.u, edge.v)}];
    const auto twin = std::find_if(same_ports.begin(), same_ports.end(),
                                   [&](Index f) { return twins(graph.edges[f], edge); });
    first[e] = twin == same_ports.end() ? e : *twin;
    if (first[e] == e) same_ports.push_back(e);
  }
  return first;
}

std::vector<EdgePair> renumbered(const std::vector<EdgePair>& pairs,
                                 const std::vector<Index>& number) {
  std::vector<EdgePair> out;
  out.reserve(pairs.size());
  for (const EdgePair& pair : pairs) {
    const Index a = number[pair.first], b = number[pair.second];
    if (a != b) out.push_back({std::min(a, b), std::max(a, b)});
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace

std::size_t merge_twin_edges(PortGraph& graph, std::vector<Arc>& arcs) {
  const std::vector<Index> first = first_twins(graph);
  std::vector<Index> number(graph.edges.size());
  std::vector<GraphEdge> kept;
  std::vector<Arc> kept_arcs;
  for (Index e = 0; e < graph.edges.size(); ++e) {
    if (first[e] != e) {
      number[e] = number[first[e]];
      continue;
    }
    number[e] = static_cast<Index>(kept.size());
    kept.push_back(graph.edges[e]);
    kept_arcs.push_back(std::move(arcs[e]));
    kept_arcs.back().edge = number[e];
  }
  const std::size_t removed = graph.edges.size() - kept.size();
  graph.edges = std::move(kept);
  arcs = std::move(kept_arcs);
  graph.zero_area = renumbered(graph.zero_area, number);
  return removed;
}

}  // namespace tessera::layout
