#include "matching/result_json.h"

#include <algorithm>
#include <cmath>

namespace tessera::matching {

namespace {

nlohmann::ordered_json finite_or_null(double x) {
  return std::isfinite(x) ? nlohmann::ordered_json(x) : nlohmann::ordered_json(nullptr);
}

}  // namespace

nlohmann::ordered_json result_json(const MatchingProblem& problem, SolverKind solver,
                                   const MatchingResult& result) {
  nlohmann::ordered_json out;
  out["solver"] = to_string(solver);
  out["status"] = to_string(result.status);
  out["objective"] = finite_or_null(result.objective);
  out["lower_bound"] = finite_or_null(result.lower_bound);
  out["gap"] = finite_or_null(result.gap());
  out["seconds"] = result.seconds;
  out["nodes"] = result.nodes;
  out["stopped_by"] = result.stopped_by == StopReason::none
                          ? nlohmann::ordered_json(nullptr)
                          : nlohmann::ordered_json(to_string(result.stopped_by));
  out["edges"] = result.edges;
  out["unmatchable_ports"] = result.unmatchable_ports;
  const auto virtual_ports = static_cast<std::size_t>(std::count_if(
      problem.is_virtual.begin(), problem.is_virtual.end(), [](std::uint8_t v) { return v != 0; }));
  out["instance"] = {{"ports", problem.node_count() - virtual_ports},
                     {"virtual_ports", virtual_ports},
                     {"edges", problem.edges.size()},
                     {"conflicts", problem.conflicts.size()}};
  return out;
}

}  // namespace tessera::matching
