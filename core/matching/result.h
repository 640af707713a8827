// What every P1 solver returns (thesis Ch. 5): the chosen edges with the objective (5.1) and a
// proven lower bound, so that the gap certifies how far from optimal the answer can be.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace tessera::matching {

enum class SolveStatus {
  optimal,     // edges are optimal: objective == lower_bound (gap 0 within the solver's tolerance)
  feasible,    // stopped at a limit (stopped_by) with a feasible matching; gap > 0 is proven
  infeasible,  // proven: no matching covers every port without a conflict pair
  time_limit,  // stopped at the time guard before any feasible matching was found
  node_limit,  // stopped at the node limit before any feasible matching was found
};

const char* to_string(SolveStatus status);

// What stopped a solve short. The node limit is work: the same result on every run and machine.
// The time guard is the machine's speed and load: a result it touched may differ from run to run.
enum class StopReason { none, node_limit, time_guard };

const char* to_string(StopReason reason);

// What a solver may spend: branch-and-bound nodes, and wall-clock seconds as a last-resort guard.
struct SolveLimits {
  SolveLimits(double guard_seconds, std::uint64_t max_nodes = UINT64_MAX)
      : seconds(guard_seconds), nodes(max_nodes) {}
  double seconds;
  std::uint64_t nodes;
};

struct MatchingResult {
  SolveStatus status = SolveStatus::time_limit;
  std::vector<std::uint32_t> edges;  // indices into problem.edges, increasing
  double objective = 0.0;            // (5.1) of edges; +infinity without a solution
  double lower_bound = 0.0;          // no matching is cheaper; +infinity when infeasible
  double seconds = 0.0;              // wall time of the solve
  std::uint64_t nodes = 0;           // branch-and-bound nodes explored
  StopReason stopped_by = StopReason::none;
  // When infeasible because no matching of G covers every port, conflicts aside: the ports that
  // some maximum matching misses (Gallai-Edmonds set D, blossom.h). The layout stage grows its
  // separatrices around them (thesis Sec. 5.1). Empty otherwise, and from the GLPK solvers.
  std::vector<std::uint32_t> unmatchable_ports;
  bool has_solution() const {
    return status == SolveStatus::optimal || status == SolveStatus::feasible;
  }
  // (objective - lower_bound) / max(|objective|, 1e-9); 0 when optimal, +infinity without solution.
  double gap() const;
};

}  // namespace tessera::matching
