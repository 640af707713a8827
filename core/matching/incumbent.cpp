#include "matching/incumbent.h"

#include <algorithm>
#include <cmath>

#include "matching/blossom.h"
#include "matching/check.h"
#include "matching/components.h"

namespace tessera::matching {

namespace {

constexpr int kRepairSteps = 8;
constexpr int kImprovePasses = 100;
constexpr int kDiveBacktracks = 1000;

std::vector<std::uint8_t> mask_of(const std::vector<std::uint32_t>& edges, std::size_t m) {
  std::vector<std::uint8_t> mask(m, 0);
  for (std::uint32_t e : edges) mask[e] = 1;
  return mask;
}

double improvement_tolerance(const MatchingProblem& problem) {
  double largest = 0.0;
  for (const MatchingEdge& e : problem.edges) largest = std::max(largest, std::abs(e.weight));
  return 1e-12 * std::max(1.0, largest);
}

}  // namespace

IncumbentSearch::IncumbentSearch(const MatchingProblem& problem, const Adjacency& incident,
                                 const Adjacency& conflicts, const Adjacency& exclusive,
                                 const std::vector<Fixed>& fixed)
    : problem_(problem),
      incident_(incident),
      conflicts_(conflicts),
      exclusive_(exclusive),
      fixed_(fixed),
      allowed_(problem.edges.size(), 1),
      tolerance_(improvement_tolerance(problem)) {
  for (std::size_t e = 0; e < fixed.size(); ++e)
    if (fixed[e] == Fixed::zero) allowed_[e] = 0;
}

// Whether the edges not fixed to 0 still hold a matching that covers every port.
bool IncumbentSearch::covers_every_port(const std::vector<Fixed>& values) const {
  std::vector<std::uint8_t> usable(values.size());
  for (std::size_t e = 0; e < values.size(); ++e) usable[e] = values[e] != Fixed::zero;
  return deficient_ports(problem_, usable).empty();
}

Incumbent IncumbentSearch::dive(const std::vector<std::uint32_t>& order,
                                std::chrono::steady_clock::time_point deadline) const {
  struct Decision {
    std::size_t position;  // in `order`, of the edge set to 1
    Propagation::State before;
  };
  Propagation propagation(problem_, incident_, exclusive_, fixed_);
  std::vector<Decision> decisions;
  int backtracks = 0;
  std::size_t position = 0;
  for (;;) {
    if (std::chrono::steady_clock::now() >= deadline) return {};
    if (propagation.infeasible()) {
      // Both values of some edge fail: undo the last decision and take its other value.
      if (decisions.empty() || backtracks++ == kDiveBacktracks) return {};
      const Decision last = std::move(decisions.back());
      decisions.pop_back();
      propagation.restore(last.before);
      propagation.fix_zero(order[last.position]);
      position = last.position + 1;
      continue;
    }
    while (position < order.size() && propagation.values()[order[position]] != Fixed::free)
      ++position;
    if (position == order.size()) break;
    const std::uint32_t e = order[position];
    if (propagation.try_one(e)) {
      Propagation::State before = propagation.save();
      propagation.commit();
      if (covers_every_port(propagation.values())) {
        decisions.push_back({position, std::move(before)});
      } else {  // conflict-free so far, but the rest cannot cover the ports any more
        propagation.restore(before);
        propagation.fix_zero(e);
      }
    } else {
      propagation.fix_zero(e);
    }
    ++position;
  }
  Incumbent found;
  for (std::uint32_t e = 0; e < problem_.edges.size(); ++e)
    if (propagation.values()[e] == Fixed::one) found.edges.push_back(e);
  const SolutionCheck check = check_solution(problem_, found.edges);
  if (!check.feasible) return {};
  found.found = true;
  found.objective = check.objective;
  improve(found);
  return found;
}

bool IncumbentSearch::conflict_free_with(std::uint32_t e,
                                         const std::vector<std::uint8_t>& chosen) const {
  for (std::uint32_t f : conflicts_.of(e))
    if (chosen[f]) return false;
  return true;
}

// The members of conflict pairs inside `edges`.
std::vector<std::uint32_t> IncumbentSearch::conflicting_members(
    const std::vector<std::uint32_t>& edges) const {
  const std::vector<std::uint8_t> chosen = mask_of(edges, problem_.edges.size());
  std::vector<std::uint32_t> members;
  for (std::uint32_t e : edges)
    if (!conflict_free_with(e, chosen)) members.push_back(e);
  return members;
}

// Covers the ports that `kept` leaves uncovered with allowed edges that neither touch `kept`'s
// nodes nor conflict with `kept`, at least weight; false if impossible.
bool IncumbentSearch::fill(std::vector<std::uint32_t>& kept,
                           const std::vector<double>& weights) const {
  const Component open = open_part(problem_, conflicts_, kept, allowed_);
  std::vector<double> open_weights;
  for (std::uint32_t e : open.edge_of) open_weights.push_back(weights[e]);
  const PortCover cover = min_weight_port_cover(open.problem, open_weights,
                                                std::vector<std::uint8_t>(open.edge_of.size(), 1));
  if (!cover.exists) return false;
  for (std::uint32_t e : cover.edges) kept.push_back(open.edge_of[e]);
  std::sort(kept.begin(), kept.end());
  return true;
}

Incumbent IncumbentSearch::lagrangian_repair(const std::vector<double>& prices, int rounds) const {
  std::vector<double> weights(problem_.edges.size());
  double mean = 0.0;
  for (std::size_t e = 0; e < weights.size(); ++e) {
    weights[e] = problem_.edges[e].weight + prices[e];
    mean += std::abs(problem_.edges[e].weight) / static_cast<double>(weights.size());
  }
  double raise = std::max(mean, 1e-9) / 4.0;
  for (int round = 0; round < rounds; ++round) {
    const PortCover cover = min_weight_port_cover(problem_, weights, allowed_);
    if (!cover.exists) return {};
    std::vector<std::uint32_t> chosen = cover.edges;
    for (int step = 0; step < kRepairSteps; ++step) {
      const std::vector<std::uint32_t> members = conflicting_members(chosen);
      if (members.empty()) {
        Incumbent found{true, chosen, objective_of(problem_, chosen)};
        improve(found);
        return found;
      }
      // Drop the dearer edge of each conflict pair (members are visited dearest first).
      std::vector<std::uint32_t> order = members;
      std::stable_sort(order.begin(), order.end(),
                       [&](std::uint32_t a, std::uint32_t b) { return weights[a] > weights[b]; });
      std::vector<std::uint8_t> kept_mask = mask_of(chosen, problem_.edges.size());
      for (std::uint32_t e : order)
        if (!conflict_free_with(e, kept_mask)) kept_mask[e] = 0;
      std::vector<std::uint32_t> kept;
      for (std::uint32_t e : chosen)
        if (kept_mask[e]) kept.push_back(e);
      if (!fill(kept, weights)) break;
      chosen = std::move(kept);
    }
    for (std::uint32_t e : conflicting_members(cover.edges)) weights[e] += raise;
    raise *= 2.0;
  }
  return {};
}

std::int64_t IncumbentSearch::cheapest_between(std::uint32_t a, std::uint32_t b,
                                               const std::vector<std::uint8_t>& chosen) const {
  std::int64_t best = -1;
  for (std::uint32_t e : incident_.of(a)) {
    const MatchingEdge& edge = problem_.edges[e];
    if (!allowed_[e] || (edge.u == a ? edge.v : edge.u) != b) continue;
    if (best >= 0 && edge.weight >= problem_.edges[static_cast<std::size_t>(best)].weight) continue;
    if (conflict_free_with(e, chosen)) best = e;
  }
  return best;
}

// Replaces matched a-b, c-d by a-c, b-d or a-d, b-c if cheaper and conflict-free.
bool IncumbentSearch::try_swap(std::uint32_t e, std::uint32_t f, std::vector<std::uint8_t>& chosen,
                               std::vector<std::int64_t>& edge_at) const {
  const MatchingEdge& x = problem_.edges[e];
  const MatchingEdge& y = problem_.edges[f];
  const double before = x.weight + y.weight - tolerance_;
  chosen[e] = chosen[f] = 0;
  const std::uint32_t options[2][4] = {{x.u, y.u, x.v, y.v}, {x.u, y.v, x.v, y.u}};
  for (const auto& o : options) {
    const std::int64_t g = cheapest_between(o[0], o[1], chosen);
    if (g < 0 || problem_.edges[static_cast<std::size_t>(g)].weight >= before) continue;
    chosen[static_cast<std::size_t>(g)] = 1;
    const std::int64_t h = cheapest_between(o[2], o[3], chosen);
    if (h >= 0 && problem_.edges[static_cast<std::size_t>(g)].weight +
                          problem_.edges[static_cast<std::size_t>(h)].weight <
                      before) {
      chosen[static_cast<std::size_t>(h)] = 1;
      edge_at[o[0]] = edge_at[o[1]] = g;
      edge_at[o[2]] = edge_at[o[3]] = h;
      return true;
    }
    chosen[static_cast<std::size_t>(g)] = 0;
  }
  chosen[e] = chosen[f] = 1;
  return false;
}

// Replaces matched a-b by a cheaper edge a-b, or, when b is virtual, by a cheaper edge from a to an
// unmatched virtual port (or drops it when both ends are virtual and its weight is positive).
bool IncumbentSearch::try_replace(std::uint32_t e, std::vector<std::uint8_t>& chosen,
                                  std::vector<std::int64_t>& edge_at) const {
  const MatchingEdge& x = problem_.edges[e];
  chosen[e] = 0;
  if (problem_.is_virtual[x.u] && problem_.is_virtual[x.v] && x.weight > tolerance_) {
    edge_at[x.u] = edge_at[x.v] = -1;
    return true;
  }
  std::int64_t best = -1;
  double best_weight = x.weight - tolerance_;
  for (const auto& [keep, release] : {std::pair{x.u, x.v}, std::pair{x.v, x.u}}) {
    for (std::uint32_t f : incident_.of(keep)) {
      const MatchingEdge& y = problem_.edges[f];
      const std::uint32_t other = y.u == keep ? y.v : y.u;
      const bool same_ends = other == release;
      const bool to_free_virtual =
          problem_.is_virtual[release] && problem_.is_virtual[other] && edge_at[other] < 0;
      if (f == e || !allowed_[f] || y.weight >= best_weight || !(same_ends || to_free_virtual) ||
          !conflict_free_with(f, chosen))
        continue;
      best = f;
      best_weight = y.weight;
    }
  }
  if (best < 0) {
    chosen[e] = 1;
    return false;
  }
  const MatchingEdge& y = problem_.edges[static_cast<std::size_t>(best)];
  edge_at[x.u] = edge_at[x.v] = -1;
  edge_at[y.u] = edge_at[y.v] = best;
  chosen[static_cast<std::size_t>(best)] = 1;
  return true;
}

void IncumbentSearch::improve(Incumbent& incumbent) const {
  std::vector<std::uint8_t> chosen = mask_of(incumbent.edges, problem_.edges.size());
  std::vector<std::int64_t> edge_at(problem_.node_count(), -1);
  for (std::uint32_t e : incumbent.edges)
    edge_at[problem_.edges[e].u] = edge_at[problem_.edges[e].v] = e;
  for (int pass = 0; pass < kImprovePasses; ++pass) {
    bool improved = false;
    std::vector<std::uint32_t> edges;
    for (std::uint32_t e = 0; e < chosen.size(); ++e)
      if (chosen[e]) edges.push_back(e);
    for (std::size_t i = 0; i < edges.size(); ++i) {
      if (!chosen[edges[i]]) continue;
      if (try_replace(edges[i], chosen, edge_at)) {
        improved = true;
        continue;
      }
      for (std::size_t j = i + 1; j < edges.size(); ++j) {
        if (chosen[edges[j]] && try_swap(edges[i], edges[j], chosen, edge_at)) {
          improved = true;
          break;
        }
      }
    }
    if (!improved) break;
  }
  incumbent.edges.clear();
  for (std::uint32_t e = 0; e < chosen.size(); ++e)
    if (chosen[e]) incumbent.edges.push_back(e);
  incumbent.objective = objective_of(problem_, incumbent.edges);
}

}  // namespace tessera::matching
