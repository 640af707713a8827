#include "layout/p1.h"

#include <numeric>
#include <queue>

namespace tessera::layout {
namespace {

// Edmonds' blossom algorithm for a maximum-cardinality matching of a general graph: augmenting
// paths are searched breadth-first from each free node; an odd cycle (blossom) met on the way is
// contracted to its base, so that paths through it are found as in a bipartite graph.
class Blossom {
 public:
  explicit Blossom(std::size_t n)
      : adjacent_(n), mate_(n, kNone), parent_(n), base_(n), queued_(n), in_blossom_(n) {}
  void add_edge(std::size_t a, std::size_t b) {
    adjacent_[a].push_back(b);
    adjacent_[b].push_back(a);
  }
  std::size_t maximum_matching() {
    std::size_t size = 0;
    for (std::size_t root = 0; root < adjacent_.size(); ++root)
      if (mate_[root] == kNone && augment_from(root)) ++size;
    return size;
  }

 private:
  static constexpr std::size_t kNone = std::size_t(-1);

  std::size_t common_base(std::size_t a, std::size_t b) const {
    std::vector<bool> on_path(adjacent_.size(), false);
    while (true) {
      a = base_[a];
      on_path[a] = true;
      if (mate_[a] == kNone) break;
      a = parent_[mate_[a]];
    }
    while (true) {
      b = base_[b];
      if (on_path[b]) return b;
      b = parent_[mate_[b]];
    }
  }

  void mark_path(std::size_t v, std::size_t base, std::size_t child) {
    while (base_[v] != base) {
      in_blossom_[base_[v]] = in_blossom_[base_[mate_[v]]] = true;
      parent_[v] = child;
      child = mate_[v];
      v = parent_[mate_[v]];
    }
  }

  void contract(std::size_t v, std::size_t to, std::queue<std::size_t>& queue) {
    const std::size_t base = common_base(v, to);
    std::fill(in_blossom_.begin(), in_blossom_.end(), false);
    mark_path(v, base, to);
    mark_path(to, base, v);
    for (std::size_t i = 0; i < adjacent_.size(); ++i) {
      if (!in_blossom_[base_[i]]) continue;
      base_[i] = base;
      if (!queued_[i]) {
        queued_[i] = true;
        queue.push(i);
      }
    }
  }

  bool augment_from(std::size_t root) {
    std::fill(parent_.begin(), parent_.end(), kNone);
    std::fill(queued_.begin(), queued_.end(), false);
    std::iota(base_.begin(), base_.end(), 0);
    std::queue<std::size_t> queue;
    queue.push(root);
    queued_[root] = true;
    while (!queue.empty()) {
      const std::size_t v = queue.front();
      queue.pop();
      for (std::size_t to : adjacent_[v]) {
        if (base_[v] == base_[to] || mate_[v] == to) continue;
        if (to == root || (mate_[to] != kNone && parent_[mate_[to]] != kNone)) {
          contract(v, to, queue);
        } else if (parent_[to] == kNone) {
          parent_[to] = v;
          if (mate_[to] == kNone) {
            flip_path(to);
            return true;
          }
          queued_[mate_[to]] = true;
          queue.push(mate_[to]);
        }
      }
    }
    return false;
  }

  void flip_path(std::size_t v) {
    while (v != kNone) {
      const std::size_t before = parent_[v], next = mate_[before];
      mate_[v] = before;
      mate_[before] = v;
      v = next;
    }
  }

  std::vector<std::vector<std::size_t>> adjacent_;
  std::vector<std::size_t> mate_, parent_, base_;
  std::vector<bool> queued_, in_blossom_;
};

}  // namespace

matching::MatchingProblem matching_problem(const PortGraph& graph, double alpha) {
  matching::MatchingProblem problem;
  problem.is_virtual.assign(graph.node_count(), 0);
  for (std::size_t v = graph.port_count(); v < graph.node_count(); ++v) problem.is_virtual[v] = 1;
  problem.edges.reserve(graph.edges.size());
  for (const GraphEdge& e : graph.edges) problem.edges.push_back({e.u, e.v, edge_weight(e, alpha)});
  problem.conflicts.reserve(graph.conflicts.size());
  for (const EdgePair& pair : graph.conflicts)
    problem.conflicts.push_back({pair.first, pair.second});
  return problem;
}

// The virtual ports are joined pairwise (and to one extra node when their number is odd), so that
// those a matching leaves free pair up among themselves: a perfect matching of that graph exists
// iff G has a matching covering every port.
bool has_perfect_matching(const matching::MatchingProblem& problem) {
  const std::size_t n = problem.node_count();
  std::vector<std::size_t> virtual_nodes;
  for (std::size_t v = 0; v < n; ++v)
    if (problem.is_virtual[v]) virtual_nodes.push_back(v);
  const bool extra = n % 2 == 1;
  Blossom blossom(n + extra);
  for (const matching::MatchingEdge& e : problem.edges) blossom.add_edge(e.u, e.v);
  for (std::size_t i = 0; i < virtual_nodes.size(); ++i) {
    for (std::size_t j = i + 1; j < virtual_nodes.size(); ++j)
      blossom.add_edge(virtual_nodes[i], virtual_nodes[j]);
    if (extra) blossom.add_edge(virtual_nodes[i], n);
  }
  return 2 * blossom.maximum_matching() == n + extra;
}

}  // namespace tessera::layout
