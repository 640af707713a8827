// tessera solve <instance> [--solver exact|glpk|glpk-tuned] [--time-limit S] [--json]: program P1
// (thesis Ch. 5) from an instance file, by one of the solvers. tessera reduce <instance> --below C
// --output F: the same instance without the edges that no matching of cost <= C can use, by a
// checked LP bound (matching/dual_bound.h), for second solvers to confirm an optimum on.
#include <unistd.h>

#include <cmath>
#include <cstdio>

#include "base/limits.h"
#include "commands.h"
#include "export/write_mesh.h"
#include "matching/dual_bound.h"
#include "matching/instance_file.h"
#include "matching/instance_json.h"
#include "matching/instance_lp.h"
#include "matching/result_json.h"
#include "matching/solver.h"
#include "usage.h"

namespace tessera::cli {
namespace {

constexpr double kDefaultTimeLimit = 60.0;

void print_solve_help() {
  std::printf(
      "usage: tessera solve <instance.json|instance.lp> [--solver S] [--time-limit S] [--json]\n\n"
      "Solves program P1 of a quad layout (thesis Ch. 5): a minimum-weight matching that covers\n"
      "every port exactly once (virtual ports at most once) with no conflict pair, from the\n"
      "compact JSON form or the CPLEX LP form of an instance (the LP is readable by glpsol and\n"
      "cbc too).\n\n"
      "  --solver S        exact (default): preprocessing, clique LP bound, Lagrangian repair and\n"
      "                    branch-and-bound, proven optimal; glpk: GLPK on the plain model\n"
      "                    (5.1)-(5.4); glpk-tuned: GLPK on clique rows with cuts and an "
      "incumbent\n"
      "  --time-limit S    stop after S seconds (default 60) with the best matching and its gap\n"
      "  --json            one JSON object on stdout: solver, status (optimal, feasible,\n"
      "                    infeasible, time_limit), stopped_by (null or time_guard: the time\n"
      "                    limit stopped it, and another run may differ), objective,\n"
      "                    lower_bound, gap, seconds, nodes,\n"
      "                    edges (chosen edge indices), unmatchable_ports, instance\n"
      "  --max-file-bytes N, --max-nodes N, --max-edges N, --max-conflicts N\n"
      "                    the largest instance read (defaults 1500000000, 1000000, 4000000,\n"
      "                    40000000)\n\n"
      "An infeasible instance is an answer (exit code 0). Exit codes: 0 ok, 1 internal error,\n"
      "2 bad input (the message says what and where).\n");
}

void print_reduce_help() {
  std::printf(
      "usage: tessera reduce <instance.json|instance.lp> --below COST --output OUT.lp|OUT.json\n"
      "                      [--time-limit S]\n\n"
      "Writes program P1 without the edges that no matching of cost COST or less can use: the\n"
      "dual of its LP relaxation (degree, clique and odd-set rows), checked row by row against\n"
      "the instance, bounds every matching's cost by its reduced costs (reduced-cost fixing,\n"
      "with what propagation forces per edge), and per edge with it fixed in and fixed out\n"
      "(probing); rounds on what is left, whose relaxation is tighter, while one rules out an\n"
      "edge.\n"
      "The instance written has every matching of cost <= COST, so its optimum is the\n"
      "instance's whenever that costs no more than COST: a solver too slow for the whole\n"
      "instance can confirm an optimum on it.\n\n"
      "  --below COST      the cost (e.g. a claimed optimum, a little above it for rounding)\n"
      "  --output F        the instance left, as CPLEX LP (.lp) or compact JSON (.json)\n"
      "  --time-limit S    seconds for all rounds (default 600); stopped early, what is left is\n"
      "                    larger and still checked\n"
      "  --max-file-bytes N, --max-nodes N, --max-edges N, --max-conflicts N\n"
      "                    as for 'tessera solve'\n");
}

Limits limits_from(const ParsedArgs& parsed) {
  Limits limits;
  limits.max_file_bytes = parsed.count("--max-file-bytes", limits.max_file_bytes);
  limits.max_matching_nodes = parsed.count("--max-nodes", limits.max_matching_nodes);
  limits.max_matching_edges = parsed.count("--max-edges", limits.max_matching_edges);
  limits.max_matching_conflicts = parsed.count("--max-conflicts", limits.max_matching_conflicts);
  return limits;
}

std::string number_text(double x) {
  if (!std::isfinite(x)) return "none";
  char text[32];
  std::snprintf(text, sizeof text, "%.10g", x);
  return text;
}

void print_text(const std::string& path, const matching::MatchingProblem& problem,
                matching::SolverKind solver, const matching::MatchingResult& r) {
  std::printf("%s: %zu nodes, %zu edges, %zu conflict pairs\n", path.c_str(), problem.node_count(),
              problem.edges.size(), problem.conflicts.size());
  std::printf("%s: %s, objective %s, lower bound %s, gap %s, %.3f s, %llu nodes\n",
              matching::to_string(solver), matching::to_string(r.status),
              number_text(r.objective).c_str(), number_text(r.lower_bound).c_str(),
              number_text(r.gap()).c_str(), r.seconds, static_cast<unsigned long long>(r.nodes));
  if (!r.unmatchable_ports.empty())
    std::printf(
        "no matching covers every port; %zu ports are left uncovered by some maximum "
        "matching, the first %u\n",
        r.unmatchable_ports.size(), r.unmatchable_ports.front());
}

Progress stderr_progress() {
  if (!isatty(STDERR_FILENO)) return Progress();
  return Progress([](const std::string& stage, double fraction) {
    std::fprintf(stderr, "\r%s %3.0f%% ", stage.c_str(), 100.0 * fraction);
  });
}

}  // namespace

int solve_command(const Args& args) {
  const ParsedArgs parsed = parse_args(args,
                                       {"--solver", "--time-limit", "--max-file-bytes",
                                        "--max-nodes", "--max-edges", "--max-conflicts"},
                                       {"--json", "--help", "-h"}, "solve");
  if (parsed.has("--help") || parsed.has("-h")) {
    print_solve_help();
    return 0;
  }
  if (parsed.positional.size() != 1)
    throw UsageError("'tessera solve' takes one instance file; run 'tessera solve --help'");
  const matching::SolverKind solver =
      matching::solver_kind_from_name(parsed.value("--solver", "exact"));
  const double time_limit = parsed.number("--time-limit", kDefaultTimeLimit);
  if (time_limit <= 0) throw UsageError("--time-limit expects a positive number of seconds");
  const std::string& path = parsed.positional[0];
  const matching::MatchingProblem problem = matching::read_instance_file(path, limits_from(parsed));
  const matching::MatchingResult result =
      matching::solve_matching(problem, solver, time_limit, stderr_progress());
  if (isatty(STDERR_FILENO)) std::fprintf(stderr, "\r");
  if (parsed.has("--json")) {
    std::printf("%s\n", matching::result_json(problem, solver, result).dump(2).c_str());
  } else {
    print_text(path, problem, solver, result);
  }
  return 0;
}

int reduce_command(const Args& args) {
  const ParsedArgs parsed = parse_args(args,
                                       {"--below", "--output", "--time-limit", "--max-file-bytes",
                                        "--max-nodes", "--max-edges", "--max-conflicts"},
                                       {"--help", "-h"}, "reduce");
  if (parsed.has("--help") || parsed.has("-h")) {
    print_reduce_help();
    return 0;
  }
  if (parsed.positional.size() != 1 || !parsed.has("--below") || !parsed.has("--output"))
    throw UsageError(
        "'tessera reduce' takes one instance file, --below COST and --output FILE; run "
        "'tessera reduce --help'");
  const std::string output = parsed.value("--output");
  const bool as_lp = output.ends_with(".lp");
  if (!as_lp && !output.ends_with(".json"))
    throw UsageError("--output names a .lp or a .json file, got '" + output + "'");
  const double cost = parsed.number("--below", 0.0);
  const double time_limit = parsed.number("--time-limit", 600.0);
  if (time_limit <= 0) throw UsageError("--time-limit expects a positive number of seconds");
  const std::string& path = parsed.positional[0];
  const matching::MatchingProblem problem = matching::read_instance_file(path, limits_from(parsed));
  const matching::Reduction reduction = matching::reduce_below(problem, cost, time_limit);
  const matching::MatchingProblem& left = reduction.part.problem;
  write_file_bytes(output,
                   as_lp ? matching::write_instance_lp(left) : matching::write_instance_json(left));
  std::printf(
      "%s: below %s, %zu of %zu edges and %zu of %zu conflict pairs are left after %d rounds "
      "(%zu edges fixed by probing), in %s; their checked lower bound %s\n",
      path.c_str(), number_text(cost).c_str(), left.edges.size(), problem.edges.size(),
      left.conflicts.size(), problem.conflicts.size(), reduction.rounds, reduction.probed,
      output.c_str(), number_text(reduction.bound.bound).c_str());
  return 0;
}

}  // namespace tessera::cli
