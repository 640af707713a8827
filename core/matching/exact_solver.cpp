#include "matching/exact_solver.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "matching/adjacency.h"
#include "matching/blossom.h"
#include "matching/branch_and_bound.h"
#include "matching/cliques.h"
#include "matching/components.h"
#include "matching/incumbent.h"
#include "matching/lp_relaxation.h"
#include "matching/probing.h"

namespace tessera::matching {

namespace {

using Clock = std::chrono::steady_clock;

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr int kRootCutRounds = 30;
constexpr int kRepairRounds = 6;

MatchingResult infeasible(std::vector<std::uint32_t> unmatchable = {}) {
  MatchingResult r;
  r.status = SolveStatus::infeasible;
  r.objective = r.lower_bound = kInfinity;
  r.unmatchable_ports = std::move(unmatchable);
  return r;
}

MatchingResult optimal(const MatchingProblem& problem, std::vector<std::uint32_t> edges) {
  MatchingResult r;
  r.status = SolveStatus::optimal;
  r.edges = std::move(edges);
  r.objective = r.lower_bound = objective_of(problem, r.edges);
  return r;
}

// `graph` with the pairs added.
Adjacency with_pairs(const Adjacency& graph,
                     const std::vector<std::pair<std::uint32_t, std::uint32_t>>& extra) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs = extra;
  for (std::uint32_t i = 0; i < graph.size(); ++i)
    for (std::uint32_t j : graph.of(i)) pairs.emplace_back(i, j);
  return adjacency_from_pairs(graph.size(), pairs);
}

bool conflict_free(const Adjacency& conflicts, const std::vector<std::uint32_t>& edges,
                   std::size_t edge_count) {
  std::vector<std::uint8_t> chosen(edge_count, 0);
  for (std::uint32_t e : edges) chosen[e] = 1;
  for (std::uint32_t e : edges)
    for (std::uint32_t f : conflicts.of(e))
      if (chosen[f]) return false;
  return true;
}

// Edges by decreasing LP value, then increasing reduced cost: the order the dive tries them in.
std::vector<std::uint32_t> order_by_relaxation(const LpRelaxation& lp) {
  std::vector<std::uint32_t> order(lp.values().size());
  for (std::uint32_t e = 0; e < order.size(); ++e) order[e] = e;
  const std::vector<double>& x = lp.values();
  const std::vector<double>& d = lp.reduced_costs();
  std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    return x[a] != x[b] ? x[a] > x[b] : d[a] < d[b];
  });
  return order;
}

MatchingResult from_search(const SearchResult& search, double root_bound) {
  MatchingResult r;
  r.nodes = search.nodes;
  if (search.complete) {
    if (!search.best.found) return infeasible();
    r.status = SolveStatus::optimal;
    r.edges = search.best.edges;
    r.objective = r.lower_bound = search.best.objective;
    return r;
  }
  r.lower_bound = std::max(search.lower_bound, root_bound);
  if (search.best.found) {
    r.status = SolveStatus::feasible;
    r.edges = search.best.edges;
    r.objective = search.best.objective;
    r.lower_bound = std::min(r.lower_bound, r.objective);
  } else {
    r.status = SolveStatus::time_limit;
    r.objective = kInfinity;
  }
  return r;
}

MatchingResult stopped_at_root(double bound) {
  MatchingResult r;
  r.status = SolveStatus::time_limit;
  r.objective = kInfinity;
  r.lower_bound = bound;
  return r;
}

MatchingResult solve_component(const MatchingProblem& problem, Clock::time_point deadline,
                               const Progress& progress) {
  const Adjacency incident = incident_edges(problem);
  const std::vector<std::uint8_t> all(problem.edges.size(), 1);
  std::vector<std::uint32_t> unmatchable = deficient_ports(problem, all);
  if (!unmatchable.empty()) return infeasible(std::move(unmatchable));
  const Adjacency conflicts = conflicting_edges(problem);
  // The cheapest matching without conflict constraints (Sec. 5.1): optimal when conflict-free,
  // a lower bound otherwise.
  std::vector<double> weights(problem.edges.size());
  for (std::size_t e = 0; e < weights.size(); ++e) weights[e] = problem.edges[e].weight;
  const PortCover unconstrained = min_weight_port_cover(problem, weights, all);
  if (!unconstrained.exists) return infeasible();
  if (conflict_free(conflicts, unconstrained.edges, problem.edges.size()))
    return optimal(problem, unconstrained.edges);
  const double cover_bound = objective_of(problem, unconstrained.edges);

  const Adjacency exclusive = exclusive_edges(problem);
  const Probing probing = probe(problem, incident, exclusive);
  if (probing.infeasible) return infeasible();
  if (Clock::now() >= deadline) return stopped_at_root(cover_bound);

  // The exclusion graph with the implied exclusions of probing: larger cliques, stronger rows.
  const Adjacency exclusion = with_pairs(exclusive, probing.implied);
  LpRelaxation lp(problem, incident, clique_cover(exclusion, conflicts));
  for (std::uint32_t e = 0; e < problem.edges.size(); ++e)
    if (probing.edges[e] != Fixed::free) {
      const int value = probing.edges[e] == Fixed::one ? 1 : 0;
      lp.set_bounds(e, value, value);
    }
  const auto seconds_left = [&] {
    return std::chrono::duration<double>(deadline - Clock::now()).count();
  };
  const LpStatus status = lp.solve_with_cuts(exclusion, kInfinity, seconds_left(), kRootCutRounds);
  if (status == LpStatus::infeasible) return infeasible();
  if (status == LpStatus::time_limit) return stopped_at_root(cover_bound);
  const double root_bound = std::max(cover_bound, lp.objective());

  const IncumbentSearch heuristics(problem, incident, conflicts, exclusion, probing.edges);
  Incumbent start = heuristics.dive(order_by_relaxation(lp));
  Incumbent repaired = heuristics.lagrangian_repair(lp.edge_prices(), kRepairRounds);
  if (repaired.found && (!start.found || repaired.objective < start.objective))
    start = std::move(repaired);
  const SearchResult search = branch_and_bound(problem, lp, exclusion, probing.edges, heuristics,
                                               std::move(start), deadline, progress);
  return from_search(search, root_bound);
}

void add_component(const Component& component, const MatchingResult& part, MatchingResult& total) {
  for (std::uint32_t e : part.edges) total.edges.push_back(component.edge_of[e]);
  total.objective += part.objective;
  total.lower_bound += part.lower_bound;
  total.nodes += part.nodes;
  if (part.status == SolveStatus::time_limit || total.status == SolveStatus::time_limit) {
    total.status = SolveStatus::time_limit;
  } else if (part.status == SolveStatus::feasible) {
    total.status = SolveStatus::feasible;
  }
}

}  // namespace

MatchingResult solve_exact(const MatchingProblem& problem, double time_limit,
                           const Progress& progress) {
  const Clock::time_point start = Clock::now();
  const auto deadline = start + std::chrono::duration_cast<Clock::duration>(
                                    std::chrono::duration<double>(std::min(time_limit, 1e9)));
  const std::vector<Component> components = split_components(problem);
  MatchingResult total;
  total.status = SolveStatus::optimal;
  for (const Component& component : components) {
    const MatchingResult part = solve_component(component.problem, deadline, progress);
    if (part.status == SolveStatus::infeasible) {
      MatchingResult r = infeasible();
      for (std::uint32_t v : part.unmatchable_ports)
        r.unmatchable_ports.push_back(component.node_of[v]);
      r.nodes = total.nodes + part.nodes;
      r.seconds = std::chrono::duration<double>(Clock::now() - start).count();
      return r;
    }
    add_component(component, part, total);
  }
  if (total.status == SolveStatus::time_limit) {
    total.edges.clear();
    total.objective = kInfinity;
  }
  std::sort(total.edges.begin(), total.edges.end());
  if (total.has_solution()) total.objective = objective_of(problem, total.edges);
  if (total.status == SolveStatus::optimal) total.lower_bound = total.objective;
  total.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return total;
}

}  // namespace tessera::matching
