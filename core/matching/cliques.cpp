#include "matching/cliques.h"

#include <algorithm>
#include <span>

#include "matching/adjacency.h"

namespace tessera::matching {

namespace {

std::vector<std::uint32_t> intersect(std::span<const std::uint32_t> a,
                                     std::span<const std::uint32_t> b) {
  std::vector<std::uint32_t> out;
  std::set_intersection(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(out));
  return out;
}

class CliqueCover {
 public:
  CliqueCover(const Adjacency& exclusion, const Adjacency& pairs)
      : exclusion_(exclusion), conflicts_(pairs), covered_(conflicts_.list.size(), 0) {}

  std::vector<Clique> run() {
    std::vector<Clique> cliques;
    const auto m = static_cast<std::uint32_t>(conflicts_.start.size() - 1);
    for (std::uint32_t e = 0; e < m; ++e) {
      for (std::uint32_t k = conflicts_.start[e]; k < conflicts_.start[e + 1]; ++k) {
        if (covered_[k]) continue;
        Clique clique = grow(e, conflicts_.list[k]);
        mark_covered(clique);
        cliques.push_back(std::move(clique));
      }
    }
    return cliques;
  }

 private:
  // Position of the conflict (a, b) in conflicts_.list, or npos.
  std::size_t conflict_slot(std::uint32_t a, std::uint32_t b) const {
    const auto list = conflicts_.of(a);
    const auto it = std::lower_bound(list.begin(), list.end(), b);
    if (it == list.end() || *it != b) return npos;
    return conflicts_.start[a] + static_cast<std::size_t>(it - list.begin());
  }

  std::size_t uncovered_links(std::uint32_t c, const Clique& clique) const {
    std::size_t links = 0;
    for (std::uint32_t member : clique) {
      const std::size_t slot = conflict_slot(c, member);
      links += slot != npos && !covered_[slot];
    }
    return links;
  }

  // Extends {a, b} by common neighbours, preferring those that cover the most new conflict pairs.
  Clique grow(std::uint32_t a, std::uint32_t b) const {
    Clique clique = {a, b};
    std::vector<std::uint32_t> candidates = intersect(exclusion_.of(a), exclusion_.of(b));
    while (!candidates.empty()) {
      std::uint32_t best = candidates.front();
      std::size_t best_links = 0;
      for (std::uint32_t c : candidates) {
        const std::size_t links = uncovered_links(c, clique);
        if (links > best_links) {
          best = c;
          best_links = links;
        }
      }
      clique.push_back(best);
      candidates = intersect(candidates, exclusion_.of(best));
    }
    std::sort(clique.begin(), clique.end());
    return clique;
  }

  void mark_covered(const Clique& clique) {
    for (std::uint32_t a : clique)
      for (std::uint32_t b : clique) {
        const std::size_t slot = a == b ? npos : conflict_slot(a, b);
        if (slot != npos) covered_[slot] = 1;
      }
  }

  static constexpr std::size_t npos = static_cast<std::size_t>(-1);
  const Adjacency& exclusion_;
  const Adjacency& conflicts_;
  std::vector<std::uint8_t> covered_;  // per entry of conflicts_.list
};

// Grows a clique from `seed` by the candidate of largest x, then makes it maximal.
Clique heaviest_clique_from(std::uint32_t seed, const Adjacency& exclusion,
                            const std::vector<double>& x) {
  Clique clique = {seed};
  auto of = exclusion.of(seed);
  std::vector<std::uint32_t> candidates(of.begin(), of.end());
  while (!candidates.empty()) {
    const auto best = std::max_element(
        candidates.begin(), candidates.end(),
        [&](std::uint32_t a, std::uint32_t b) { return x[a] < x[b] || (x[a] == x[b] && a > b); });
    const std::uint32_t chosen = *best;
    clique.push_back(chosen);
    candidates = intersect(candidates, exclusion.of(chosen));
  }
  std::sort(clique.begin(), clique.end());
  return clique;
}

}  // namespace

std::vector<Clique> clique_cover(const Adjacency& exclusion, const Adjacency& pairs) {
  return CliqueCover(exclusion, pairs).run();
}

std::vector<Clique> conflict_cliques(const MatchingProblem& problem) {
  return clique_cover(exclusive_edges(problem), conflicting_edges(problem));
}

std::vector<Clique> violated_cliques(const Adjacency& exclusion, const std::vector<double>& x,
                                     double tolerance) {
  std::vector<std::uint32_t> seeds;
  for (std::uint32_t e = 0; e < x.size(); ++e)
    if (x[e] > tolerance && x[e] < 1.0 - tolerance) seeds.push_back(e);
  std::stable_sort(seeds.begin(), seeds.end(),
                   [&](std::uint32_t a, std::uint32_t b) { return x[a] > x[b]; });
  std::vector<Clique> found;
  for (std::uint32_t seed : seeds) {
    Clique clique = heaviest_clique_from(seed, exclusion, x);
    double weight = 0.0;
    for (std::uint32_t e : clique) weight += x[e];
    if (weight > 1.0 + tolerance && std::find(found.begin(), found.end(), clique) == found.end())
      found.push_back(std::move(clique));
  }
  return found;
}

}  // namespace tessera::matching
