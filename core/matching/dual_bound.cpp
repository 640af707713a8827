#include "matching/dual_bound.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <numeric>
#include <span>

#include "base/error.h"
#include "matching/cliques.h"
#include "matching/lp_relaxation.h"
#include "matching/propagation.h"

namespace tessera::matching {

namespace {

// L is lowered by this much of the magnitude of the terms it sums (in long double, whose rounding
// is far below it), so that it stays a bound whatever the order of the sums.
constexpr double kRelativeMargin = 1e-12;
// Cut rounds of relaxation_dual(): until no row is violated, or the time is up.
constexpr int kCutRounds = 1000;

bool increasing_edges(std::span<const std::uint32_t> edges, std::size_t edge_count) {
  for (std::size_t k = 0; k < edges.size(); ++k)
    if (edges[k] >= edge_count || (k > 0 && edges[k] <= edges[k - 1])) return false;
  return !edges.empty();
}

bool share_a_node(const MatchingEdge& a, const MatchingEdge& b) {
  return a.u == b.u || a.u == b.v || a.v == b.u || a.v == b.v;
}

// Empty if `row` is valid for every matching without conflicts, else why not.
std::string row_error(const MatchingProblem& problem, const Adjacency& conflicts,
                      const DualRow& row) {
  if (!std::isfinite(row.multiplier)) return "its multiplier is not a finite number";
  if (row.kind == DualRowKind::degree)
    return row.node < problem.node_count() ? "" : "node " + std::to_string(row.node) + " is none";
  if (!increasing_edges(row.edges, problem.edges.size()))
    return "its edges are not increasing indices of edges";
  if (row.kind == DualRowKind::clique) {
    for (std::size_t i = 0; i < row.edges.size(); ++i)
      for (std::size_t j = i + 1; j < row.edges.size(); ++j) {
        const std::uint32_t e = row.edges[i], f = row.edges[j];
        if (!share_a_node(problem.edges[e], problem.edges[f]) && !conflicts.contains(e, f))
          return "edges " + std::to_string(e) + " and " + std::to_string(f) +
                 " share no node and form no conflict pair";
      }
  }
  return "";
}

// The nodes the edges span.
std::size_t spanned_nodes(const MatchingProblem& problem, std::span<const std::uint32_t> edges) {
  std::vector<std::uint32_t> nodes;
  for (std::uint32_t e : edges) {
    nodes.push_back(problem.edges[e].u);
    nodes.push_back(problem.edges[e].v);
  }
  std::sort(nodes.begin(), nodes.end());
  return static_cast<std::size_t>(std::unique(nodes.begin(), nodes.end()) - nodes.begin());
}

// What x_g = 1 for g in `ones` and x_f = 0 for f in `zeros` add to L: each term of
// sum_e min(0, d_e) becomes d_g or 0.
double surplus(std::span<const std::uint32_t> ones, std::span<const std::uint32_t> zeros,
               const std::vector<double>& d) {
  double sum = 0.0;
  for (std::uint32_t g : ones) sum += std::max(d[g], 0.0);
  for (std::uint32_t f : zeros) sum += std::max(-d[f], 0.0);
  return sum;
}

// The same for the edges that `values` fixes.
double surplus(const std::vector<Fixed>& values, const std::vector<double>& d) {
  double sum = 0.0;
  for (std::size_t e = 0; e < values.size(); ++e) {
    if (values[e] == Fixed::one) sum += std::max(d[e], 0.0);
    if (values[e] == Fixed::zero) sum += std::max(-d[e], 0.0);
  }
  return sum;
}

using Clock = std::chrono::steady_clock;

double seconds_until(Clock::time_point deadline) {
  return std::chrono::duration<double>(deadline - Clock::now()).count();
}

// The relaxation at its optimum after the cut rounds, or after `seconds`.
std::unique_ptr<LpRelaxation> solved_relaxation(const MatchingProblem& problem,
                                                const ProblemAdjacency& adjacency, double seconds) {
  auto lp = std::make_unique<LpRelaxation>(problem, adjacency.incident,
                                           clique_cover(adjacency.exclusive, adjacency.conflicts));
  lp->solve_with_cuts(adjacency.exclusive, std::numeric_limits<double>::infinity(), seconds,
                      kCutRounds);
  return lp;
}

// What x_e = 1 adds to L by propagation: the surplus of the edges it forces and drops, or
// infinity if it ends in a contradiction.
double using_edge(Propagation& propagation, std::uint32_t e, const std::vector<double>& d) {
  if (!propagation.try_one(e)) return std::numeric_limits<double>::infinity();
  return surplus(propagation.forced(), propagation.dropped(), d);
}

// Per edge, 0 where `propagation` fixed it to 0; all 0 where it ended in a contradiction (no
// matching below the cost exists).
std::vector<std::uint8_t> edges_not_fixed_to_zero(const Propagation& propagation) {
  const std::vector<Fixed>& values = propagation.values();
  std::vector<std::uint8_t> allowed(values.size(), 0);
  if (propagation.infeasible()) return allowed;
  for (std::size_t e = 0; e < values.size(); ++e) allowed[e] = values[e] != Fixed::zero;
  return allowed;
}

// One probe of the relaxation: the edge, the value it is fixed to, and the sign it has in the
// reduced costs' test (the larger |d_e| on the side probed, the likelier it goes).
struct Probe {
  std::uint32_t edge = 0;
  int value = 0;
  double promise = 0.0;
};

// The probes of the free edges: x_e = 1 where the relaxation has x_e < 1, x_e = 0 where it has
// x_e > 0; the most promising first.
std::vector<Probe> probes_of(const LpRelaxation& lp, const std::vector<double>& d,
                             const Propagation& propagation) {
  constexpr double kAtBound = 1e-9;
  std::vector<Probe> probes;
  for (std::uint32_t e = 0; e < d.size(); ++e) {
    if (propagation.values()[e] != Fixed::free) continue;
    const double x = lp.values()[e];
    if (x < 1.0 - kAtBound) probes.push_back({e, 1, d[e]});
    if (x > kAtBound) probes.push_back({e, 0, -d[e]});
  }
  std::stable_sort(probes.begin(), probes.end(),
                   [](const Probe& a, const Probe& b) { return a.promise > b.promise; });
  return probes;
}

// Probing by the relaxation: per probe, the relaxation `lp` (at its optimum) with x_e fixed,
// stopped once its bound passes `cost`. Where that LP's dual, checked, with what the fixing
// propagates (x_e = 1) or its own reduced cost (x_e = 0), bounds every matching with that value
// above `cost`, every matching of cost <= `cost` has the other: e is fixed to it in
// `propagation`, with its consequences. Until `deadline`; returns how many edges were fixed.
std::size_t probe_by_relaxation(const MatchingProblem& problem, const ProblemAdjacency& adjacency,
                                LpRelaxation& lp, const std::vector<double>& reduced, double cost,
                                Clock::time_point deadline, Propagation& propagation) {
  const LpBasis optimum = lp.basis();
  std::size_t fixed = 0;
  for (const Probe& probe : probes_of(lp, reduced, propagation)) {
    const std::uint32_t e = probe.edge;
    const double seconds = seconds_until(deadline);
    if (seconds <= 0 || propagation.infeasible()) break;
    if (propagation.values()[e] != Fixed::free) continue;
    lp.set_bounds(e, probe.value, probe.value);
    lp.solve_with_cuts(adjacency.exclusive, cost, seconds, 0);
    const CheckedBound probed = check_dual_bound(problem, adjacency, lp.dual_rows());
    lp.set_bounds(e, 0, 1);
    lp.restore(optimum);
    if (!probed.valid) continue;
    const std::vector<double>& d = probed.reduced_costs;
    if (probe.value == 1 && probed.bound + using_edge(propagation, e, d) > cost) {
      propagation.fix_zero(e);
      ++fixed;
    }
    if (probe.value == 0 && probed.bound + std::max(-d[e], 0.0) > cost) {
      if (propagation.try_one(e)) {
        propagation.commit();
      } else {
        propagation.fix_zero(e);  // e is in every such matching and cannot be: there is none
      }
      ++fixed;
    }
  }
  return fixed;
}

// The problem as a part of itself.
Component whole(const MatchingProblem& problem) {
  Component part;
  part.problem = problem;
  part.node_of.resize(problem.node_count());
  std::iota(part.node_of.begin(), part.node_of.end(), 0U);
  part.edge_of.resize(problem.edges.size());
  std::iota(part.edge_of.begin(), part.edge_of.end(), 0U);
  return part;
}

}  // namespace

CheckedBound check_dual_bound(const MatchingProblem& problem, const ProblemAdjacency& adjacency,
                              const std::vector<DualRow>& rows) {
  CheckedBound checked;
  std::vector<long double> reduced(problem.edges.size());
  long double magnitude = 0.0L;
  for (std::size_t e = 0; e < reduced.size(); ++e) {
    reduced[e] = problem.edges[e].weight;
    magnitude += std::abs(reduced[e]);
  }
  long double dual_objective = 0.0L;
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const DualRow& row = rows[r];
    if (std::string why = row_error(problem, adjacency.conflicts, row); !why.empty()) {
      checked.error = "row " + std::to_string(r) + ": " + why;
      return checked;
    }
    const bool equality = row.kind == DualRowKind::degree && !problem.is_virtual[row.node];
    const long double y = equality ? row.multiplier : std::min(row.multiplier, 0.0);
    std::span<const std::uint32_t> edges = row.edges;
    long double right_side = 1.0L;
    if (row.kind == DualRowKind::degree) edges = adjacency.incident.of(row.node);
    if (row.kind == DualRowKind::odd_set) {
      const std::size_t nodes = spanned_nodes(problem, edges);
      if (nodes % 2 == 0) {
        checked.error = "row " + std::to_string(r) + ": its edges span an even number of nodes";
        return checked;
      }
      right_side = static_cast<long double>(nodes - 1) / 2.0L;
    }
    dual_objective += y * right_side;
    magnitude += std::abs(y) * (right_side + static_cast<long double>(edges.size()));
    for (std::uint32_t e : edges) reduced[e] -= y;
  }
  long double bound = dual_objective;
  for (long double d : reduced) bound += std::min(d, 0.0L);
  checked.valid = true;
  checked.bound = static_cast<double>(bound - kRelativeMargin * magnitude);
  checked.reduced_costs.assign(reduced.begin(), reduced.end());
  return checked;
}

std::vector<DualRow> relaxation_dual(const MatchingProblem& problem,
                                     const ProblemAdjacency& adjacency, double seconds) {
  return solved_relaxation(problem, adjacency, seconds)->dual_rows();
}

std::vector<std::uint8_t> edges_below(const MatchingProblem& problem,
                                      const ProblemAdjacency& adjacency, const CheckedBound& bound,
                                      double cost) {
  const double gap = cost - bound.bound;
  const std::vector<double>& d = bound.reduced_costs;
  Propagation propagation(problem, adjacency.incident, adjacency.exclusive);
  for (std::uint32_t e = 0; e < d.size() && !propagation.infeasible(); ++e) {
    if (-d[e] <= gap || propagation.values()[e] != Fixed::free) continue;
    if (propagation.try_one(e)) {  // leaving e out costs at least L - d_e: e is in
      propagation.commit();
    } else {
      propagation.fix_zero(e);  // which makes it infeasible
    }
  }
  for (bool changed = true; changed && !propagation.infeasible();) {
    changed = false;
    const double fixed = surplus(propagation.values(), d);
    if (fixed > gap) break;
    for (std::uint32_t e = 0; e < d.size() && !propagation.infeasible(); ++e) {
      if (propagation.values()[e] != Fixed::free) continue;
      if (fixed + using_edge(propagation, e, d) > gap) {
        propagation.fix_zero(e);
        changed = true;
      }
    }
  }
  if (surplus(propagation.values(), d) > gap) return std::vector<std::uint8_t>(d.size(), 0);
  return edges_not_fixed_to_zero(propagation);
}

Reduction reduce_below(const MatchingProblem& problem, double cost, double seconds) {
  constexpr double kLongest = 1e7;  // seconds: a deadline the clock can hold
  const Clock::time_point deadline =
      Clock::now() + std::chrono::duration_cast<Clock::duration>(
                         std::chrono::duration<double>(std::min(seconds, kLongest)));
  Reduction reduction;
  reduction.part = whole(problem);
  for (;;) {
    const MatchingProblem& left = reduction.part.problem;
    const ProblemAdjacency adjacency = adjacency_of(left);
    const std::unique_ptr<LpRelaxation> lp =
        solved_relaxation(left, adjacency, seconds_until(deadline));
    reduction.bound = check_dual_bound(left, adjacency, lp->dual_rows());
    ++reduction.rounds;
    if (!reduction.bound.valid)
      throw Error("the relaxation's dual rows failed their check: " + reduction.bound.error);
    std::vector<std::uint8_t> allowed = edges_below(left, adjacency, reduction.bound, cost);
    if (std::find(allowed.begin(), allowed.end(), 0) == allowed.end()) {
      Propagation propagation(left, adjacency.incident, adjacency.exclusive);
      reduction.probed += probe_by_relaxation(left, adjacency, *lp, reduction.bound.reduced_costs,
                                              cost, deadline, propagation);
      allowed = edges_not_fixed_to_zero(propagation);
    }
    if (std::find(allowed.begin(), allowed.end(), 0) == allowed.end()) break;
    Component next = open_part(left, adjacency.conflicts, {}, allowed);
    for (std::uint32_t& e : next.edge_of) e = reduction.part.edge_of[e];
    reduction.part = std::move(next);
    if (Clock::now() >= deadline) break;
  }
  return reduction;
}

}  // namespace tessera::matching
