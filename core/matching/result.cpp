#include "matching/result.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tessera::matching {

const char* to_string(SolveStatus status) {
  switch (status) {
    case SolveStatus::optimal:
      return "optimal";
    case SolveStatus::feasible:
      return "feasible";
    case SolveStatus::infeasible:
      return "infeasible";
    case SolveStatus::time_limit:
      return "time_limit";
    case SolveStatus::node_limit:
      return "node_limit";
  }
  return "unknown";
}

const char* to_string(StopReason reason) {
  switch (reason) {
    case StopReason::none:
      return "none";
    case StopReason::node_limit:
      return "node_limit";
    case StopReason::time_guard:
      return "time_guard";
  }
  return "unknown";
}

double MatchingResult::gap() const {
  if (!has_solution()) return std::numeric_limits<double>::infinity();
  if (status == SolveStatus::optimal) return 0.0;
  return std::max(0.0, objective - lower_bound) / std::max(std::abs(objective), 1e-9);
}

}  // namespace tessera::matching
