#include "matching/exact_solver.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "matching/blossom.h"
#include "matching/branch_and_bound.h"
#include "matching/check.h"
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
constexpr std::uint64_t kNeighbourhoodNodes = 200;  // the searches of the roots' neighbourhoods
// The optimistic cutoff of a root, above its LP bound by this fraction (solve_below_cutoff()).
constexpr double kOptimisticGap = 2e-4;
constexpr double kIntegral = 1e-6;  // an LP value this close to 0 or 1 is integral
// One round of Gomory cuts at the root of a component this large (solve_component()), whatever
// the time: the size decides, so that the result is the same on every run. (They were made only
// when the time left was 8 times what the root LP took, so that the machine's load chose.) On
// dragon at alpha 5 (62,967 edges) P1 is proven optimal with them, 15,011.31 after 148 nodes in
// 47 s; without them it stopped at 60 s with 15,020.06 over 15,008.40 (4,400 nodes). Making them
// takes up to 46 s there (alpha 0), which no limit stops.
constexpr std::size_t kGomoryEdges = 10'000;
constexpr int kGomoryCuts = 2'000;

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

// The edges at 1 when every value is 0 or 1 (within kIntegral), else nothing.
std::optional<std::vector<std::uint32_t>> integral_edges(const std::vector<double>& x) {
  std::vector<std::uint32_t> edges;
  for (std::uint32_t e = 0; e < x.size(); ++e) {
    if (x[e] > 1.0 - kIntegral) {
      edges.push_back(e);
    } else if (x[e] >= kIntegral) {
      return std::nullopt;
    }
  }
  return edges;
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

// A search stopped short stopped at its node limit, unless the time guard did (solve_exact()).
MatchingResult from_search(const SearchResult& search, double proven_bound) {
  MatchingResult r;
  r.nodes = search.nodes;
  if (search.complete) {
    if (!search.best.found) return infeasible();
    r.status = SolveStatus::optimal;
    r.edges = search.best.edges;
    r.objective = r.lower_bound = search.best.objective;
    return r;
  }
  r.lower_bound = std::max(search.lower_bound, proven_bound);
  if (search.best.found) {
    r.status = SolveStatus::feasible;
    r.edges = search.best.edges;
    r.objective = search.best.objective;
    r.lower_bound = std::min(r.lower_bound, r.objective);
  } else {
    r.status = SolveStatus::node_limit;
    r.objective = kInfinity;
  }
  r.stopped_by = StopReason::node_limit;
  return r;
}

// Only the time guard stops a solve before its search.
MatchingResult stopped_at_root(double bound) {
  MatchingResult r;
  r.status = SolveStatus::time_limit;
  r.stopped_by = StopReason::time_guard;
  r.objective = kInfinity;
  r.lower_bound = bound;
  return r;
}

// The weight-free preprocessing of every component (steps 1 and 2).
std::vector<ComponentStructure> prepare(const MatchingProblem& problem) {
  std::vector<ComponentStructure> parts;
  for (Component& component : split_components(problem)) {
    ComponentStructure part;
    part.incident = incident_edges(component.problem);
    part.conflicts = conflicting_edges(component.problem);
    part.unmatchable_ports = deficient_ports(
        component.problem, std::vector<std::uint8_t>(component.problem.edges.size(), 1));
    part.component = std::move(component);
    parts.push_back(std::move(part));
  }
  return parts;
}

void set_weights(Component& component, const MatchingProblem& problem) {
  for (std::size_t e = 0; e < component.edge_of.size(); ++e)
    component.problem.edges[e].weight = problem.edges[component.edge_of[e]].weight;
}

// The same nodes and edges, and a's conflict pairs are the first ones of b's.
bool same_graph_up_to_extra_pairs(const MatchingProblem& a, const MatchingProblem& b) {
  return a.is_virtual == b.is_virtual &&
         std::equal(a.edges.begin(), a.edges.end(), b.edges.begin(), b.edges.end(),
                    [](const MatchingEdge& x, const MatchingEdge& y) {
                      return x.u == y.u && x.v == y.v;
                    }) &&
         a.conflicts.size() <= b.conflicts.size() &&
         std::equal(a.conflicts.begin(), a.conflicts.end(), b.conflicts.begin(),
                    [](const ConflictPair& x, const ConflictPair& y) {
                      return x.first == y.first && x.second == y.second;
                    });
}

// Probing and the clique cover of the exclusion graph with the implied exclusions of probing
// (larger cliques, stronger rows); the cover only if probing leaves P1 feasible.
ComponentStructure::Root make_root(const ComponentStructure& part, const Adjacency& exclusive,
                                   Probing probing) {
  ComponentStructure::Root root;
  root.probing = std::move(probing);
  if (root.probing.infeasible) return root;
  root.exclusion = with_pairs(exclusive, root.probing.implied);
  root.cliques = clique_cover(root.exclusion, part.conflicts);
  return root;
}

// The root of `part`, unless the deadline stops probing (then the next solve with time makes it).
void ensure_root(ComponentStructure& part, Clock::time_point deadline) {
  if (part.root) return;
  const Adjacency exclusive = exclusive_edges(part.component.problem);
  Probing probing = probe(part.component.problem, part.incident, exclusive, deadline);
  if (probing.stopped && !probing.infeasible) return;
  part.root = make_root(part, exclusive, std::move(probing));
}

// Conflict pairs (local edge indices) added to a component with its root.
void add_pairs(ComponentStructure& part, const std::vector<ConflictPair>& extra) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> both_orders;
  part.preferred.resize(part.component.problem.edges.size(), 0);
  for (const ConflictPair& c : extra) {
    part.preferred[c.first] = part.preferred[c.second] = 1;
    part.component.problem.conflicts.push_back(c);
    both_orders.emplace_back(c.first, c.second);
    both_orders.emplace_back(c.second, c.first);
  }
  part.conflicts = with_pairs(part.conflicts, both_orders);
  if (!part.root || part.root->probing.infeasible) return;
  ComponentStructure::Root& root = *part.root;
  root.exclusion = with_pairs(root.exclusion, both_orders);
  for (const ConflictPair& c : extra)
    root.cliques.push_back({std::min(c.first, c.second), std::max(c.first, c.second)});
}

// How a solve searches: its limits, and whether its roots look for an incumbent around the LP
// optimum (complete_integral_part(), whose own solve does not).
struct SolveMode {
  SearchLimits limits;
  bool search_neighbourhood = true;
};

MatchingResult solve_all(const MatchingProblem& problem, std::vector<ComponentStructure>& parts,
                         Clock::time_point start, const SolveMode& mode, const Progress& progress);

// What a root learns below its cutoff (step 6 in exact_solver.h): the incumbent's cost, or the LP
// bound plus kOptimisticGap if that is less. The search of solve_below_cutoff(), and the lower
// bound: the cutoff if that search is complete but not proven.
struct BelowCutoff {
  NeighbourhoodSearch search;
  double bound;
};

BelowCutoff below_root_cutoff(const ComponentStructure& part, const LpRelaxation& lp,
                              const Incumbent& start, double root_bound,
                              Clock::time_point deadline) {
  BelowCutoff below{{}, root_bound};
  double cutoff = lp.objective() + kOptimisticGap * std::max(1.0, std::abs(lp.objective()));
  if (start.found) cutoff = std::min(cutoff, start.objective);
  below.search = solve_below_cutoff(part.component.problem, part.conflicts,
                                    {lp.values(), lp.reduced_costs(), lp.objective()}, cutoff,
                                    part.root->probing.edges, {deadline, kNeighbourhoodNodes});
  if (below.search.complete && !below.search.proven)  // no matching costs `cutoff` or less
    below.bound = std::max(root_bound, cutoff - bound_tolerance(cutoff));
  return below;
}

MatchingResult solve_component(ComponentStructure& part, const SolveMode& mode,
                               const Progress& progress) {
  const Clock::time_point deadline = mode.limits.deadline;
  const MatchingProblem& problem = part.component.problem;
  if (!part.unmatchable_ports.empty()) return infeasible(part.unmatchable_ports);
  // The cheapest matching without conflict constraints (Sec. 5.1): optimal when conflict-free,
  // a lower bound otherwise.
  std::vector<double> weights(problem.edges.size());
  for (std::size_t e = 0; e < weights.size(); ++e) weights[e] = problem.edges[e].weight;
  const PortCover unconstrained =
      min_weight_port_cover(problem, weights, std::vector<std::uint8_t>(weights.size(), 1));
  if (!unconstrained.exists) return infeasible();
  if (conflict_free(part.conflicts, unconstrained.edges, problem.edges.size()))
    return optimal(problem, unconstrained.edges);
  const double cover_bound = objective_of(problem, unconstrained.edges);

  ensure_root(part, deadline);
  if (!part.root) return stopped_at_root(cover_bound);
  const ComponentStructure::Root& root = *part.root;
  if (root.probing.infeasible) return infeasible();
  if (Clock::now() >= deadline) return stopped_at_root(cover_bound);

  LpRelaxation lp(problem, part.incident, root.cliques);
  for (std::uint32_t e = 0; e < problem.edges.size(); ++e)
    if (root.probing.edges[e] != Fixed::free) {
      const int value = root.probing.edges[e] == Fixed::one ? 1 : 0;
      lp.set_bounds(e, value, value);
    }
  const auto seconds_left = [&] {
    return std::chrono::duration<double>(deadline - Clock::now()).count();
  };
  const LpStatus status =
      lp.solve_with_cuts(root.exclusion, kInfinity, seconds_left(), kRootCutRounds);
  if (status == LpStatus::infeasible) return infeasible();
  if (status == LpStatus::time_limit) return stopped_at_root(cover_bound);
  if (mode.search_neighbourhood && problem.edges.size() >= kGomoryEdges &&
      lp.add_gomory_cuts(kGomoryCuts) > 0) {
    // Dragon at alpha 0 (62,967 edges): the root bound went from 7794.07 to 7798.96, and the
    // search proved the optimum, 7803.94, after 1,607 nodes (2,309 s on the 2-core machine);
    // without the cuts no run had closed the gap (the longest, 1,400 s: 7804.60 over 7802.14).
    // Below this size the dense rows cost more than they save: on fertility's slider (1,670 edges)
    // the largest re-solve went from 268 ms to 592 ms. Without them, at the 60 s default limit,
    // dragon at alpha 0 has an incumbent (7829.57 over 7794.07); with them it had none.
    const LpStatus strengthened =
        lp.solve_with_cuts(root.exclusion, kInfinity, seconds_left(), kRootCutRounds);
    if (strengthened == LpStatus::infeasible) return infeasible();
    if (strengthened == LpStatus::time_limit) return stopped_at_root(cover_bound);
  }
  if (const std::optional<std::vector<std::uint32_t>> edges = integral_edges(lp.values()))
    return optimal(problem, *edges);  // every conflict pair is in a row: a matching without any
  const double root_bound = std::max(cover_bound, lp.objective());

  const IncumbentSearch heuristics(problem, part.incident, part.conflicts, root.exclusion,
                                   root.probing.edges);
  Incumbent start = heuristics.lagrangian_repair(lp.edge_prices(), kRepairRounds);
  if (mode.search_neighbourhood) {
    Incumbent completed = complete_integral_part(
        problem, part.conflicts, lp.values(), root.probing.edges, {deadline, kNeighbourhoodNodes});
    if (completed.found) heuristics.improve(completed);
    if (completed.found && (!start.found || completed.objective < start.objective))
      start = std::move(completed);
  }
  BelowCutoff below = mode.search_neighbourhood
                          ? below_root_cutoff(part, lp, start, root_bound, deadline)
                          : BelowCutoff{{}, root_bound};
  if (below.search.proven) {
    MatchingResult r = optimal(problem, below.search.best.edges);
    r.nodes = below.search.nodes;
    return r;
  }
  if (below.search.best.found) {
    heuristics.improve(below.search.best);
    if (!start.found || below.search.best.objective < start.objective)
      start = std::move(below.search.best);
  }
  // The dive last: on dragon at alpha 0 it fails after 8 to 10 s, and the part's search finds its
  // first matching 8 s sooner without it first (tessera solve --time-limit 45: 7833.95, where it
  // had none).
  if (!start.found) start = heuristics.dive(order_by_relaxation(lp), deadline);
  lp.drop_slack_rows();
  const SearchResult search =
      branch_and_bound(problem, lp, root.exclusion, root.probing.edges, part.preferred, heuristics,
                       std::move(start), root_bound, mode.limits, progress);
  MatchingResult r = from_search(search, below.bound);
  r.nodes += below.search.nodes;
  return r;
}

bool stopped_without_solution(SolveStatus status) {
  return status == SolveStatus::time_limit || status == SolveStatus::node_limit;
}

void add_component(const Component& component, const MatchingResult& part, MatchingResult& total) {
  for (std::uint32_t e : part.edges) total.edges.push_back(component.edge_of[e]);
  total.objective += part.objective;
  total.lower_bound += part.lower_bound;
  total.nodes += part.nodes;
  total.stopped_by = std::max(total.stopped_by, part.stopped_by);
  if (part.status == SolveStatus::time_limit || total.status == SolveStatus::time_limit) {
    total.status = SolveStatus::time_limit;
  } else if (stopped_without_solution(part.status) || stopped_without_solution(total.status)) {
    total.status = SolveStatus::node_limit;
  } else if (part.status == SolveStatus::feasible) {
    total.status = SolveStatus::feasible;
  }
}

MatchingResult solve_all(const MatchingProblem& problem, std::vector<ComponentStructure>& parts,
                         Clock::time_point start, const SolveMode& mode, const Progress& progress) {
  MatchingResult total;
  total.status = SolveStatus::optimal;
  for (ComponentStructure& structure : parts) {
    const Component& component = structure.component;
    set_weights(structure.component, problem);
    // The components share the node limit, in their order.
    SolveMode part_mode = mode;
    part_mode.limits.max_nodes -= std::min(total.nodes, mode.limits.max_nodes);
    const MatchingResult part = solve_component(structure, part_mode, progress);
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
  if (stopped_without_solution(total.status)) {
    total.edges.clear();
    total.objective = kInfinity;
  }
  std::sort(total.edges.begin(), total.edges.end());
  if (total.has_solution()) total.objective = objective_of(problem, total.edges);
  if (total.status == SolveStatus::optimal) total.lower_bound = total.objective;
  total.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return total;
}

// The best matching that holds `kept` and otherwise only `allowed` edges, by the exact solver on
// the part of P1 that `kept` leaves open (open_part()).
NeighbourhoodSearch search_neighbourhood(const MatchingProblem& problem, const Adjacency& conflicts,
                                         std::vector<std::uint32_t> kept,
                                         const std::vector<std::uint8_t>& allowed,
                                         const SearchLimits& limits) {
  const Component open = open_part(problem, conflicts, kept, allowed);
  std::vector<ComponentStructure> parts = prepare(open.problem);
  const MatchingResult rest =
      solve_all(open.problem, parts, Clock::now(), SolveMode{limits, false}, Progress());
  NeighbourhoodSearch search;
  search.nodes = rest.nodes;
  search.complete = rest.status == SolveStatus::optimal || rest.status == SolveStatus::infeasible;
  if (!rest.has_solution()) return search;
  search.best.edges = std::move(kept);
  for (std::uint32_t e : rest.edges) search.best.edges.push_back(open.edge_of[e]);
  std::sort(search.best.edges.begin(), search.best.edges.end());
  const SolutionCheck check = check_solution(problem, search.best.edges);
  search.best.found = check.feasible;  // kept edges in conflict: no matching here
  search.best.objective = check.objective;
  return search;
}

}  // namespace

Incumbent complete_integral_part(const MatchingProblem& problem, const Adjacency& conflicts,
                                 const std::vector<double>& x, const std::vector<Fixed>& fixed,
                                 const SearchLimits& limits) {
  std::vector<std::uint32_t> kept;
  for (std::uint32_t e = 0; e < x.size(); ++e)
    if (x[e] > 1.0 - kIntegral) kept.push_back(e);
  if (kept.empty()) return {};
  std::vector<std::uint8_t> allowed(fixed.size());
  for (std::size_t e = 0; e < fixed.size(); ++e) allowed[e] = fixed[e] != Fixed::zero;
  return search_neighbourhood(problem, conflicts, std::move(kept), allowed, limits).best;
}

NeighbourhoodSearch solve_below_cutoff(const MatchingProblem& problem, const Adjacency& conflicts,
                                       const LpOptimum& lp, double cutoff,
                                       const std::vector<Fixed>& fixed,
                                       const SearchLimits& limits) {
  const double slack = cutoff - lp.objective;
  std::vector<std::uint32_t> kept;
  std::vector<std::uint8_t> allowed(fixed.size());
  for (std::uint32_t e = 0; e < fixed.size(); ++e) {
    const bool out = fixed[e] == Fixed::zero || (lp.x[e] < kIntegral && lp.d[e] > slack);
    const bool in = fixed[e] == Fixed::one || (lp.x[e] > 1.0 - kIntegral && -lp.d[e] > slack);
    allowed[e] = !out;
    if (in && !out) kept.push_back(e);
  }
  NeighbourhoodSearch search =
      search_neighbourhood(problem, conflicts, std::move(kept), allowed, limits);
  search.proven = search.complete && search.best.found && search.best.objective <= cutoff;
  return search;
}

std::vector<ComponentStructure>* ExactSolverCache::structure_for(const MatchingProblem& problem,
                                                                 Clock::time_point deadline) {
  if (!filled_) {
    graph_ = problem;
    components_ = prepare(problem);
    component_of_edge_.resize(problem.edges.size());
    local_edge_.resize(problem.edges.size());
    for (std::uint32_t c = 0; c < components_.size(); ++c)
      for (std::uint32_t e = 0; e < components_[c].component.edge_of.size(); ++e) {
        component_of_edge_[components_[c].component.edge_of[e]] = c;
        local_edge_[components_[c].component.edge_of[e]] = e;
      }
    filled_ = true;
  }
  if (!same_graph_up_to_extra_pairs(graph_, problem)) return nullptr;
  // The roots with the rest: they read no weight either, and made lazily they fell to the first
  // solve whose cover has conflicts, often the slider's first move (fandisk: the layout at
  // alpha 5 has a conflict-free cover, and alpha 0 then took 27.7 ms instead of 11.1). Those the
  // deadline left out are made by the next call with time, before any pairs are added, so that
  // every later call keeps them.
  for (ComponentStructure& part : components_) ensure_root(part, deadline);
  if (problem.conflicts.size() == graph_.conflicts.size()) return &components_;
  std::vector<std::vector<ConflictPair>> extra(components_.size());
  for (std::size_t k = graph_.conflicts.size(); k < problem.conflicts.size(); ++k) {
    const ConflictPair& c = problem.conflicts[k];
    const std::uint32_t component = component_of_edge_[c.first];
    if (component_of_edge_[c.second] != component) return nullptr;
    extra[component].push_back({local_edge_[c.first], local_edge_[c.second]});
  }
  with_extra_pairs_ = components_;
  for (std::size_t c = 0; c < extra.size(); ++c)
    if (!extra[c].empty()) add_pairs(with_extra_pairs_[c], extra[c]);
  return &with_extra_pairs_;
}

MatchingResult solve_exact(const MatchingProblem& problem, const SolveLimits& limits,
                           const Progress& progress, ExactSolverCache* cache) {
  const Clock::time_point start = Clock::now();
  const auto deadline = start + std::chrono::duration_cast<Clock::duration>(
                                    std::chrono::duration<double>(std::min(limits.seconds, 1e9)));
  std::vector<ComponentStructure>* cached =
      cache ? cache->structure_for(problem, deadline) : nullptr;
  std::vector<ComponentStructure> fresh;
  if (!cached) fresh = prepare(problem);
  MatchingResult result = solve_all(problem, cached ? *cached : fresh, start,
                                    SolveMode{{deadline, limits.nodes}}, progress);
  // Any step may have been cut short once the guard passed (probing, a root LP, the Gomory
  // cuts, a neighbourhood's search, the dive): the result is the machine's, and says so.
  if (Clock::now() >= deadline) {
    result.stopped_by = StopReason::time_guard;
    if (result.status == SolveStatus::node_limit) result.status = SolveStatus::time_limit;
  }
  return result;
}

}  // namespace tessera::matching
