#include "matching/probing.h"

namespace tessera::matching {

namespace {

class Prober {
 public:
  Prober(const MatchingProblem& problem, const Adjacency& incident, const Adjacency& exclusive)
      : problem_(problem),
        incident_(incident),
        exclusive_(exclusive),
        lost_(problem.node_count(), 0) {
    result_.edges.assign(problem.edges.size(), Fixed::free);
  }

  Probing run() {
    bool changed = true;
    while (changed && !result_.infeasible) {
      changed = force_single_edges();
      if (!result_.infeasible) changed = drop_blocking_edges() || changed;
    }
    return result_;
  }

 private:
  struct PortState {
    std::uint32_t usable = 0;  // free edges
    bool matched = false;      // an edge fixed to 1
    std::uint32_t last_free = 0;
  };

  PortState state(std::uint32_t v) const {
    PortState s;
    for (std::uint32_t e : incident_.of(v)) {
      if (result_.edges[e] == Fixed::one) s.matched = true;
      if (result_.edges[e] == Fixed::free) {
        ++s.usable;
        s.last_free = e;
      }
    }
    return s;
  }

  void fail(std::uint32_t port) {
    result_.infeasible = true;
    result_.blocked_port = port;
  }

  void fix_one(std::uint32_t e) {
    result_.edges[e] = Fixed::one;
    for (std::uint32_t f : exclusive_.of(e)) {
      if (result_.edges[f] == Fixed::one) return fail(problem_.edges[e].u);
      result_.edges[f] = Fixed::zero;
    }
  }

  bool force_single_edges() {
    bool changed = false;
    for (std::uint32_t v = 0; v < problem_.node_count() && !result_.infeasible; ++v) {
      if (problem_.is_virtual[v]) continue;
      const PortState s = state(v);
      if (s.matched) continue;
      if (s.usable == 0) {
        fail(v);
      } else if (s.usable == 1) {
        fix_one(s.last_free);
        changed = true;
      }
    }
    return changed;
  }

  // Whether choosing e leaves a port other than e's ends with no usable edge.
  bool blocks_a_port(std::uint32_t e) {
    const MatchingEdge& edge = problem_.edges[e];
    touched_.clear();
    for (std::uint32_t f : exclusive_.of(e)) {
      if (result_.edges[f] != Fixed::free) continue;
      for (std::uint32_t end : {problem_.edges[f].u, problem_.edges[f].v}) {
        if (end == edge.u || end == edge.v || problem_.is_virtual[end]) continue;
        if (lost_[end]++ == 0) touched_.push_back(end);
      }
    }
    bool blocks = false;
    for (std::uint32_t v : touched_) {
      if (!blocks) {
        const PortState s = state(v);
        blocks = !s.matched && lost_[v] == s.usable;
      }
      lost_[v] = 0;
    }
    return blocks;
  }

  bool drop_blocking_edges() {
    bool changed = false;
    for (std::uint32_t e = 0; e < problem_.edges.size(); ++e) {
      if (result_.edges[e] != Fixed::free || !blocks_a_port(e)) continue;
      result_.edges[e] = Fixed::zero;
      changed = true;
    }
    return changed;
  }

  const MatchingProblem& problem_;
  const Adjacency& incident_;
  const Adjacency& exclusive_;
  std::vector<std::uint32_t> lost_;  // per node: free edges at it that the probed edge excludes
  std::vector<std::uint32_t> touched_;
  Probing result_;
};

}  // namespace

Probing probe(const MatchingProblem& problem, const Adjacency& incident,
              const Adjacency& exclusive) {
  return Prober(problem, incident, exclusive).run();
}

}  // namespace tessera::matching
