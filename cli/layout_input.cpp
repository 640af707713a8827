#include "layout_input.h"

namespace tessera::cli {

std::set<std::string> layout_input_options() {
  return {"--alpha",
          "--rho",
          "--length-factor",
          "--h",
          "--solver",
          "--max-trace-steps",
          "--max-trace-crossings",
          "--max-trace-seconds",
          "--max-solve-nodes",
          "--max-solve-seconds"};
}

const char* const kLayoutInputHelp =
    "  --alpha A            edge weight L_base + A * L_height (default 5; 0 gives the coarsest\n"
    "                       layout, larger values follow the field more closely)\n"
    "  --rho R              spiral test threshold (default 10)\n"
    "  --length-factor F    separatrices grow to L_max = F * diameter / h (default 3, Sec. "
    "6.8);\n"
    "                       doubled while G has no perfect matching\n"
    "  --solver S           P1 solver: exact (default), glpk (the plain model) or glpk-tuned\n"
    "  --h REL              parameter unit as a fraction of the bounding-box diagonal (0.01)\n"
    "  --max-trace-steps N  faces crossed by all separatrices together (default 20000000)\n"
    "  --max-trace-crossings N  crossings they find together (default 20000000)\n"
    "  --max-solve-nodes N  branch-and-bound nodes of program P1, its loop rounds included\n"
    "                       (default 5000; at the limit the best matching found is used,\n"
    "                       matching_stopped_by says node_limit)\n"
    "  --max-trace-seconds S, --max-solve-seconds S\n"
    "                       time guards (default 1800 each), far above what the limits above\n"
    "                       take: the counts make the result the same on every run and\n"
    "                       machine; a result a guard stops depends on the machine's load, and\n"
    "                       says so (tracing: an error; P1: matching_stopped_by time_guard)\n";

layout::LayoutOptions layout_options(const ParsedArgs& parsed) {
  layout::LayoutOptions options;
  options.rho = parsed.number("--rho", options.rho);
  if (!(options.rho > 1)) throw UsageError("--rho expects a number above 1");
  options.length_factor = parsed.number("--length-factor", options.length_factor);
  if (!(options.length_factor > 0) || options.length_factor > 1e3)
    throw UsageError("--length-factor expects a number in (0, 1000]");
  Limits& limits = options.limits;
  limits.max_trace_steps = parsed.count("--max-trace-steps", limits.max_trace_steps);
  limits.max_trace_crossings = parsed.count("--max-trace-crossings", limits.max_trace_crossings);
  limits.max_solve_nodes = parsed.count("--max-solve-nodes", limits.max_solve_nodes);
  limits.max_trace_seconds = parsed.number("--max-trace-seconds", limits.max_trace_seconds);
  limits.max_solve_seconds = parsed.number("--max-solve-seconds", limits.max_solve_seconds);
  if (!(limits.max_trace_seconds > 0) || !(limits.max_solve_seconds > 0))
    throw UsageError("--max-trace-seconds and --max-solve-seconds expect positive numbers");
  return options;
}

double layout_alpha(const ParsedArgs& parsed) {
  const double alpha = parsed.number("--alpha", 5);
  if (!(alpha >= 0)) throw UsageError("--alpha expects a number >= 0");
  return alpha;
}

ParamOptions layout_param_options(const ParsedArgs& parsed) {
  ParamOptions options;
  options.h_relative = parsed.number("--h", options.h_relative);
  if (!(options.h_relative > 0)) throw UsageError("--h expects a positive number");
  return options;
}

matching::SolverKind layout_solver(const ParsedArgs& parsed) {
  return matching::solver_kind_from_name(parsed.value("--solver", "exact"));
}

}  // namespace tessera::cli
