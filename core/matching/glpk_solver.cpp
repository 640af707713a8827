#include "matching/glpk_solver.h"

#include <glpk.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <exception>
#include <limits>
#include <memory>

#include "base/error.h"
#include "matching/adjacency.h"
#include "matching/cliques.h"

namespace tessera::matching {

namespace {

using Clock = std::chrono::steady_clock;

struct ProblemDeleter {
  void operator()(glp_prob* p) const { glp_delete_prob(p); }
};
using GlpkProblem = std::unique_ptr<glp_prob, ProblemDeleter>;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

int milliseconds_left(Clock::time_point start, double limit) {
  const double left = std::max(0.0, limit - seconds_since(start));
  return static_cast<int>(std::min(left * 1000.0, 2.0e9)) + 1;
}

// Adds the row sum_{e in edges} x_e (= or <=) 1; GLPK numbers rows and columns from 1.
void add_row(glp_prob* lp, std::span<const std::uint32_t> edges, bool equality) {
  const int row = glp_add_rows(lp, 1);
  glp_set_row_bnds(lp, row, equality ? GLP_FX : GLP_UP, 1.0, 1.0);
  std::vector<int> index(edges.size() + 1);
  std::vector<double> value(edges.size() + 1, 1.0);
  for (std::size_t k = 0; k < edges.size(); ++k) index[k + 1] = static_cast<int>(edges[k]) + 1;
  glp_set_mat_row(lp, row, static_cast<int>(edges.size()), index.data(), value.data());
}

GlpkProblem build_model(const MatchingProblem& problem, bool clique_rows) {
  GlpkProblem lp(glp_create_prob());
  glp_set_obj_dir(lp.get(), GLP_MIN);
  if (!problem.edges.empty()) glp_add_cols(lp.get(), static_cast<int>(problem.edges.size()));
  for (std::size_t e = 0; e < problem.edges.size(); ++e) {
    glp_set_col_kind(lp.get(), static_cast<int>(e) + 1, GLP_BV);                   // (5.4)
    glp_set_obj_coef(lp.get(), static_cast<int>(e) + 1, problem.edges[e].weight);  // (5.1)
  }
  const Adjacency incident = incident_edges(problem);
  for (std::uint32_t v = 0; v < problem.node_count(); ++v)  // (5.2)
    add_row(lp.get(), incident.of(v), problem.is_virtual[v] == 0);
  if (clique_rows) {
    for (const Clique& clique : conflict_cliques(problem)) add_row(lp.get(), clique, false);
  } else {
    for (const ConflictPair& c : problem.conflicts)  // (5.3)
      add_row(lp.get(), std::array{c.first, c.second}, false);
  }
  return lp;
}

struct Search {
  const Progress* progress = nullptr;
  Clock::time_point start;
  double time_limit = 0.0;
  std::uint64_t max_nodes = UINT64_MAX;
  bool node_limit_hit = false;
  double last_report = -1.0;
  std::vector<double> incumbent;  // 1-based column values, empty when none
  bool incumbent_given = false;
  double bound = -std::numeric_limits<double>::infinity();
  std::uint64_t nodes = 0;
  std::exception_ptr error;
};

void report(Search& s) {
  const double now = seconds_since(s.start);
  if (now - s.last_report < 0.2) return;
  s.last_report = now;
  s.progress->step("glpk", std::min(1.0, now / s.time_limit));
}

void on_tree_event(glp_tree* tree, void* info) {
  Search& s = *static_cast<Search*>(info);
  if (s.error) return;
  try {
    int total = 0;
    glp_ios_tree_size(tree, nullptr, nullptr, &total);
    s.nodes = std::max<std::uint64_t>(s.nodes, static_cast<std::uint64_t>(total));
    if (s.nodes >= s.max_nodes && !s.node_limit_hit) {
      s.node_limit_hit = true;
      glp_ios_terminate(tree);
    }
    if (const int best = glp_ios_best_node(tree); best != 0)
      s.bound = glp_ios_node_bound(tree, best);
    if (glp_ios_reason(tree) == GLP_IHEUR && !s.incumbent_given && !s.incumbent.empty()) {
      glp_ios_heur_sol(tree, s.incumbent.data());
      s.incumbent_given = true;
    }
    report(s);
  } catch (...) {
    s.error = std::current_exception();
    glp_ios_terminate(tree);
  }
}

MatchingResult infeasible_result() {
  MatchingResult r;
  r.status = SolveStatus::infeasible;
  r.objective = r.lower_bound = std::numeric_limits<double>::infinity();
  return r;
}

MatchingResult no_solution_result(double bound, StopReason reason) {
  MatchingResult r;
  r.status = reason == StopReason::node_limit ? SolveStatus::node_limit : SolveStatus::time_limit;
  r.stopped_by = reason;
  r.objective = std::numeric_limits<double>::infinity();
  r.lower_bound = bound;
  return r;
}

MatchingResult read_solution(const MatchingProblem& problem, glp_prob* lp, bool proven,
                             double bound) {
  MatchingResult r;
  for (std::uint32_t e = 0; e < problem.edges.size(); ++e)
    if (glp_mip_col_val(lp, static_cast<int>(e) + 1) > 0.5) r.edges.push_back(e);
  r.objective = objective_of(problem, r.edges);
  r.status = proven ? SolveStatus::optimal : SolveStatus::feasible;
  r.lower_bound = proven ? r.objective : std::min(bound, r.objective);
  return r;
}

// The root LP relaxation; false if it is infeasible (then so is P1).
bool solve_relaxation(glp_prob* lp, Search& s) {
  glp_smcp parameters;
  glp_init_smcp(&parameters);
  parameters.msg_lev = GLP_MSG_OFF;
  parameters.tm_lim = milliseconds_left(s.start, s.time_limit);
  const int code = glp_simplex(lp, &parameters);
  if (code != 0 && code != GLP_ETMLIM)
    throw Error("GLPK's simplex failed (code " + std::to_string(code) + ")");
  if (glp_get_status(lp) == GLP_NOFEAS) return false;
  if (glp_get_status(lp) == GLP_OPT) s.bound = glp_get_obj_val(lp);
  return glp_get_status(lp) == GLP_OPT;
}

}  // namespace

MatchingResult solve_with_glpk(const MatchingProblem& problem, const GlpkConfig& config,
                               const SolveLimits& limits, const Progress& progress) {
  Search s;
  s.progress = &progress;
  s.start = Clock::now();
  s.time_limit = limits.seconds;
  s.max_nodes = limits.nodes;
  const double time_limit = limits.seconds;
  if (!config.incumbent.empty()) {
    s.incumbent.assign(problem.edges.size() + 1, 0.0);
    for (std::uint32_t e : config.incumbent) s.incumbent[e + 1] = 1.0;
  }
  if (problem.edges.empty()) {
    const bool all_virtual = std::all_of(problem.is_virtual.begin(), problem.is_virtual.end(),
                                         [](std::uint8_t v) { return v != 0; });
    if (!all_virtual) return infeasible_result();
    MatchingResult empty;
    empty.status = SolveStatus::optimal;
    return empty;
  }
  const GlpkProblem lp = build_model(problem, config.clique_rows);
  MatchingResult result;
  if (!solve_relaxation(lp.get(), s)) {
    const bool infeasible = glp_get_status(lp.get()) == GLP_NOFEAS;
    result = infeasible ? infeasible_result() : no_solution_result(s.bound, StopReason::time_guard);
  } else {
    glp_iocp parameters;
    glp_init_iocp(&parameters);
    parameters.msg_lev = GLP_MSG_OFF;
    parameters.tm_lim = milliseconds_left(s.start, time_limit);
    parameters.cb_func = on_tree_event;
    parameters.cb_info = &s;
    if (config.cuts) {
      parameters.mir_cuts = parameters.gmi_cuts = parameters.cov_cuts = parameters.clq_cuts =
          GLP_ON;
    }
    const int terminal = glp_term_out(GLP_OFF);  // the clique cut generator talks regardless
    const int code = glp_intopt(lp.get(), &parameters);
    glp_term_out(terminal);
    if (s.error) std::rethrow_exception(s.error);
    if (code != 0 && code != GLP_ETMLIM && code != GLP_ESTOP)
      throw Error("GLPK's branch-and-bound failed (code " + std::to_string(code) + ")");
    const int status = glp_mip_status(lp.get());
    const StopReason stopped = code == GLP_ETMLIM ? StopReason::time_guard
                               : s.node_limit_hit ? StopReason::node_limit
                                                  : StopReason::none;
    if (status == GLP_NOFEAS) {
      result = infeasible_result();
    } else if (status == GLP_OPT || status == GLP_FEAS) {
      result = read_solution(problem, lp.get(), status == GLP_OPT && code == 0, s.bound);
      result.stopped_by = stopped;
    } else {
      result = no_solution_result(s.bound, stopped);
    }
  }
  result.nodes = s.nodes;
  result.seconds = seconds_since(s.start);
  return result;
}

}  // namespace tessera::matching
