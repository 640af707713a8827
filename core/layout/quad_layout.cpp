#include "layout/quad_layout.h"

#include <algorithm>
#include <chrono>

#include "layout/conflicts.h"
#include "layout/growth.h"
#include "layout/metrics.h"
#include "layout/p1.h"
#include "layout/patches.h"
#include "layout/twin_edges.h"
#include "matching/blossom.h"
#include "mesh/geometry.h"

namespace tessera::layout {
namespace {

using Clock = std::chrono::steady_clock;

class StageClock {
 public:
  explicit StageClock(std::vector<StageSeconds>& seconds) : seconds_(seconds) {}
  // Adds to the stage's time when it runs again (another round of solve_layout()).
  void stage_done(const std::string& stage) {
    const Clock::time_point now = Clock::now();
    const double seconds = std::chrono::duration<double>(now - last_).count();
    last_ = now;
    for (StageSeconds& done : seconds_) {
      if (done.stage != stage) continue;
      done.seconds += seconds;
      return;
    }
    seconds_.push_back({stage, seconds});
  }

 private:
  std::vector<StageSeconds>& seconds_;
  Clock::time_point last_ = Clock::now();
};

}  // namespace

namespace {

// The separatrices grown to L_max and, while G has no perfect matching, to L_max doubled (Sec.
// 5.1): the graph, its straight arcs, and what the growth found. The growth's working memory (the
// crossings pending, those seen, the spiral test's last crossings) goes when it returns.
void grow_graph(const Charts& charts, const LayoutOptions& options, const Progress& progress,
                LayoutGraph& result) {
  SeparatrixGrowth growth(charts, find_ports(charts),
                          {options.rho, options.limits.max_trace_steps,
                           options.limits.max_trace_crossings, options.limits.max_trace_seconds});
  double length_limit =
      options.length_factor * bounding_box(charts.mesh).diagonal() / charts.param.h;
  while (true) {
    growth.grow(length_limit, progress);
    result.graph = growth.graph();
    result.trace_steps = growth.steps();
    result.trace_crossings = growth.crossings();
    const std::size_t candidates = result.graph.edges.size();
    result.arcs = keep_edges_with_arcs(charts, result.graph);
    result.curved_edges = candidates - result.graph.edges.size();
    const matching::MatchingProblem problem = matching_problem(result.graph, 0);
    result.unmatchable_ports =
        matching::deficient_ports(problem, std::vector<std::uint8_t>(problem.edges.size(), 1));
    if (result.unmatchable_ports.empty() || result.length_doublings == options.max_length_doublings)
      return;
    length_limit *= 2;
    ++result.length_doublings;
  }
}

}  // namespace

LayoutGraph build_layout_graph(const Charts& charts, const LayoutOptions& options,
                               const Progress& progress) {
  LayoutGraph result;
  StageClock clock(result.seconds);
  grow_graph(charts, options, progress, result);
  result.twin_edges = merge_twin_edges(result.graph, result.arcs);
  clock.stage_done("separatrices");
  result.graph.conflicts = illegal_crossings(charts, result.graph, result.arcs, progress);
  clock.stage_done("conflicts");
  return result;
}

namespace {

// The layout of the chosen edges (LAYOUT_NOTES "The layout itself"), or the one the cache holds for
// them.
void lay_out(const Charts& charts, const LayoutGraph& graph, const ResolveCache& cache,
             StageClock& clock, QuadLayout& layout) {
  if (cache.last && cache.last->matching.edges == layout.matching.edges) {
    layout.arcs = cache.last->arcs;
    layout.refined = cache.last->refined;
    layout.check = cache.last->check;
    layout.angle_rsd = cache.last->angle_rsd;
    ++layout.reused_rounds;
    clock.stage_done("layout");
    clock.stage_done("check");
    return;
  }
  layout.arcs.clear();
  for (std::uint32_t e : layout.matching.edges) layout.arcs.push_back(graph.arcs[e]);
  layout.refined = refine_along_arcs(charts, layout.arcs);
  const Connectivity connectivity = build_connectivity(layout.refined.mesh);
  std::vector<std::int32_t> patch = assign_patches(layout.refined, connectivity);
  clock.stage_done("layout");
  layout.check = check_layout(layout.refined.mesh, connectivity, patch);
  layout.angle_rsd =
      relative_standard_deviation(corner_angles(layout.refined, patch, layout.check));
  layout.refined.mesh.face_attributes["patch"] = std::move(patch);
  clock.stage_done("check");
}

void solve_p1(const matching::MatchingProblem& problem, const matching::SolveLimits& limits,
              const Progress& progress, ResolveCache& cache, StageClock& clock,
              QuadLayout& layout) {
  layout.matching = matching::solve_matching(problem, layout.solver, limits, progress, &cache.p1);
  clock.stage_done("P1");
}

// Rounds of P1 after a failed check (loop_pairs()); all rounds share the solver's node limit and
// time guard.
constexpr int kMaxLoopRounds = 8;

// Ch. 5 in rounds: while the check finds patches that are no disks, the chosen pairs that close
// loops (loop_pairs()) become conflicts and P1 is solved again. A matching whose layout failed
// before goes to the next round without being laid out again. An alpha solved before
// (cache.solved) runs no round: its matching is laid out. The layout returned is laid out unless
// `lay_out_result` is false (presolve_layout(), which keeps only the matching).
QuadLayout solve_in_rounds(const Charts& charts, const LayoutGraph& graph, double alpha,
                           matching::SolverKind solver, const Limits& limits,
                           const Progress& progress, ResolveCache& cache, bool lay_out_result) {
  QuadLayout layout;
  layout.alpha = alpha;
  layout.solver = solver;
  std::vector<StageSeconds> seconds;
  StageClock clock(seconds);
  const std::pair<matching::SolverKind, double> key{solver, alpha};
  if (const auto known = cache.solved.find(key); known != cache.solved.end()) {
    layout.matching = known->second.matching;
    layout.loop_rounds = known->second.loop_rounds;
    layout.reused_rounds = layout.rounds() - 1;  // the failed rounds are in cache.failed
    layout.solved_before = true;
    clock.stage_done("P1");
    if (lay_out_result) lay_out(charts, graph, cache, clock, layout);
    layout.seconds = std::move(seconds);
    return layout;
  }
  matching::MatchingProblem problem = matching_problem(graph.graph, alpha);
  const Clock::time_point deadline =
      Clock::now() + std::chrono::duration_cast<Clock::duration>(
                         std::chrono::duration<double>(std::min(limits.max_solve_seconds, 1e9)));
  const auto seconds_left = [&] {
    return std::chrono::duration<double>(deadline - Clock::now()).count();
  };
  std::uint64_t nodes_used = 0;
  const auto limits_left = [&] {
    return matching::SolveLimits(
        seconds_left(), limits.max_solve_nodes - std::min(nodes_used, limits.max_solve_nodes));
  };
  // Every round ended with a proven optimum or infeasibility and none was left out for a limit:
  // the result goes into cache.solved.
  const auto proven = [](const matching::MatchingResult& m) {
    return (m.status == matching::SolveStatus::optimal ||
            m.status == matching::SolveStatus::infeasible) &&
           m.stopped_by == matching::StopReason::none;
  };
  solve_p1(problem, limits_left(), progress, cache, clock, layout);
  nodes_used += layout.matching.nodes;
  bool repeatable = proven(layout.matching);
  bool laid_out = false;  // the stages ran for this layout's matching (or gave the cache's last)
  for (int round = 0; round < kMaxLoopRounds && layout.matching.has_solution(); ++round) {
    auto failed = cache.failed.find(layout.matching.edges);
    laid_out = failed == cache.failed.end();
    if (laid_out) {
      lay_out(charts, graph, cache, clock, layout);
      if (layout.check.valid()) break;
      failed = cache.failed
                   .emplace(layout.matching.edges,
                            graph.repair_pairs ? graph.repair_pairs(charts, graph.graph, layout)
                                               : loop_pairs(charts, graph.graph, layout.arcs))
                   .first;
    }
    const std::vector<EdgePair>& pairs = failed->second;
    if (pairs.empty()) break;
    // Out of nodes or past the guard, the rounds stop; the layout says which stopped them.
    const matching::StopReason stop = seconds_left() <= 0 ? matching::StopReason::time_guard
                                      : nodes_used >= limits.max_solve_nodes
                                          ? matching::StopReason::node_limit
                                          : matching::StopReason::none;
    if (stop != matching::StopReason::none) {
      layout.matching.stopped_by = std::max(layout.matching.stopped_by, stop);
      repeatable = false;
      break;
    }
    add_loop_conflicts(pairs, problem);
    QuadLayout next;
    next.alpha = alpha;
    next.solver = solver;
    next.reused_rounds = layout.reused_rounds + (laid_out ? 0 : 1);
    next.loop_rounds = layout.loop_rounds;
    next.loop_rounds.push_back(pairs);
    solve_p1(problem, limits_left(), progress, cache, clock, next);
    nodes_used += next.matching.nodes;
    repeatable = repeatable && proven(next.matching);
    if (!next.matching.has_solution()) break;
    layout = std::move(next);
    laid_out = false;
  }
  layout.p1_nodes = nodes_used;
  if (repeatable && layout.matching.status == matching::SolveStatus::optimal)
    cache.solved[key] = {layout.matching, layout.loop_rounds};
  if (!laid_out && lay_out_result) lay_out(charts, graph, cache, clock, layout);
  layout.seconds = std::move(seconds);
  return layout;
}

}  // namespace

QuadLayout solve_layout(const Charts& charts, const LayoutGraph& graph, double alpha,
                        matching::SolverKind solver, const Limits& limits, const Progress& progress,
                        ResolveCache* cache) {
  ResolveCache own_cache;
  if (!cache) cache = &own_cache;
  QuadLayout layout = solve_in_rounds(charts, graph, alpha, solver, limits, progress, *cache, true);
  cache->last = layout;
  return layout;
}

bool presolve_layout(const Charts& charts, const LayoutGraph& graph, double alpha,
                     matching::SolverKind solver, const Limits& limits, const Progress& progress,
                     ResolveCache& cache) {
  const std::pair<matching::SolverKind, double> key{solver, alpha};
  if (!cache.solved.contains(key))
    solve_in_rounds(charts, graph, alpha, solver, limits, progress, cache, false);
  return cache.solved.contains(key);
}

double average_separatrix_length(const PortGraph& graph) {
  if (graph.separatrices.empty()) return 0;
  double total = 0;
  for (const Separatrix& s : graph.separatrices) total += s.length;
  return total / double(graph.separatrices.size());
}

}  // namespace tessera::layout
