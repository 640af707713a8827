// tessera solve <instance> [--solver exact|glpk|glpk-tuned] [--time-limit S] [--json]: program P1
// (thesis Ch. 5) from an instance file, by one of the solvers.
#include <unistd.h>

#include <cmath>
#include <cstdio>

#include "base/limits.h"
#include "commands.h"
#include "matching/instance_file.h"
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
      "                    infeasible, time_limit), objective, lower_bound, gap, seconds, nodes,\n"
      "                    edges (chosen edge indices), unmatchable_ports, instance\n"
      "  --max-file-bytes N, --max-nodes N, --max-edges N, --max-conflicts N\n"
      "                    the largest instance read (defaults 1500000000, 1000000, 4000000,\n"
      "                    40000000)\n\n"
      "An infeasible instance is an answer (exit code 0). Exit codes: 0 ok, 1 internal error,\n"
      "2 bad input (the message says what and where).\n");
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

}  // namespace tessera::cli
