#include "matching/cliques.h"

#include <algorithm>
#include <optional>
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

// Keeps the members of the sorted `kept` that are in the sorted `other`. Binary searches when
// `kept` is much shorter (as candidates of a growing clique soon are), a merge otherwise.
void keep_common(std::vector<std::uint32_t>& kept, std::span<const std::uint32_t> other) {
  std::size_t out = 0;
  if (8 * kept.size() < other.size()) {
    for (std::uint32_t x : kept)
      if (std::binary_search(other.begin(), other.end(), x)) kept[out++] = x;
  } else {
    auto it = other.begin();
    for (std::uint32_t x : kept) {
      while (it != other.end() && *it < x) ++it;
      if (it != other.end() && *it == x) kept[out++] = x;
    }
  }
  kept.resize(out);
}

class CliqueCover {
 public:
  CliqueCover(const Adjacency& exclusion, const Adjacency& pairs)
      : exclusion_(exclusion),
        conflicts_(pairs),
        covered_(conflicts_.list.size(), 0),
        links_(conflicts_.size(), 0),
        stamp_(conflicts_.size(), 0),
        member_(conflicts_.size(), 0) {}

  std::vector<Clique> run() {
    std::vector<Clique> cliques;
    const auto m = static_cast<std::uint32_t>(conflicts_.size());
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
  // links_[c] += 1 for every conflict pair (member, c) not covered yet; a count is valid only
  // while stamp_[c] is the current clique's stamp (so that nothing needs clearing).
  void count_links(std::uint32_t member) {
    for (std::uint32_t k = conflicts_.start[member]; k < conflicts_.start[member + 1]; ++k) {
      if (covered_[k]) continue;
      const std::uint32_t c = conflicts_.list[k];
      if (stamp_[c] != clique_count_) {
        stamp_[c] = clique_count_;
        links_[c] = 0;
      }
      ++links_[c];
    }
  }

  std::uint32_t links(std::uint32_t c) const { return stamp_[c] == clique_count_ ? links_[c] : 0; }

  // Extends {a, b} by the common neighbour that covers the most new conflict pairs while one covers
  // any (counted as the clique grows, so that a step costs O(candidates + degree)).
  Clique grow(std::uint32_t a, std::uint32_t b) {
    ++clique_count_;
    Clique clique = {a, b};
    count_links(a);
    count_links(b);
    std::vector<std::uint32_t> candidates = intersect(exclusion_.of(a), exclusion_.of(b));
    while (!candidates.empty()) {
      std::uint32_t best = candidates.front();
      std::uint32_t best_links = links(best);
      for (std::uint32_t c : candidates)
        if (links(c) > best_links) {
          best = c;
          best_links = links(c);
        }
      if (best_links == 0) break;
      clique.push_back(best);
      count_links(best);
      keep_common(candidates, exclusion_.of(best));
    }
    std::sort(clique.begin(), clique.end());
    return clique;
  }

  void mark_covered(const Clique& clique) {
    for (std::uint32_t e : clique) member_[e] = 1;
    for (std::uint32_t e : clique)
      for (std::uint32_t k = conflicts_.start[e]; k < conflicts_.start[e + 1]; ++k)
        if (member_[conflicts_.list[k]]) covered_[k] = 1;
    for (std::uint32_t e : clique) member_[e] = 0;
  }

  const Adjacency& exclusion_;
  const Adjacency& conflicts_;
  std::vector<std::uint8_t> covered_;  // per entry of conflicts_.list
  std::vector<std::uint32_t> links_;   // per edge, during grow()
  std::vector<std::uint32_t> stamp_;   // per edge: the clique its links_ entry counts for
  std::uint32_t clique_count_ = 0;
  std::vector<std::uint8_t> member_;  // per edge, during mark_covered()
};

// The clique grown from `seed` by the candidate of largest x and made maximal, if its weight
// exceeds `weight_above`. The growth stops as soon as the weight cannot get there any more (what
// it still gains is among the candidates): most seeds give cliques that are not violated, and
// making those maximal took most of the separation's time.
std::optional<Clique> violated_clique_from(std::uint32_t seed, const Adjacency& exclusion,
                                           const std::vector<double>& x, double weight_above) {
  constexpr double kMargin = 1e-9;  // far above the rounding of the sums
  Clique clique = {seed};
  double weight = x[seed];
  auto of = exclusion.of(seed);
  std::vector<std::uint32_t> candidates(of.begin(), of.end());
  while (!candidates.empty()) {
    double reachable = weight;
    for (std::uint32_t e : candidates) reachable += std::max(x[e], 0.0);
    if (reachable <= weight_above - kMargin) return std::nullopt;
    const auto best = std::max_element(
        candidates.begin(), candidates.end(),
        [&](std::uint32_t a, std::uint32_t b) { return x[a] < x[b] || (x[a] == x[b] && a > b); });
    const std::uint32_t chosen = *best;
    clique.push_back(chosen);
    weight += x[chosen];
    keep_common(candidates, exclusion.of(chosen));
  }
  std::sort(clique.begin(), clique.end());
  double sorted_weight = 0.0;  // summed in member order, as the rows' activity is
  for (std::uint32_t e : clique) sorted_weight += x[e];
  if (!(sorted_weight > weight_above)) return std::nullopt;
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
    std::optional<Clique> clique = violated_clique_from(seed, exclusion, x, 1.0 + tolerance);
    if (clique && std::find(found.begin(), found.end(), *clique) == found.end())
      found.push_back(std::move(*clique));
  }
  return found;
}

}  // namespace tessera::matching
