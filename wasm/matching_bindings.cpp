// Program P1 bindings (thesis Ch. 5, issue 5): an instance as text, in its compact JSON form
// (matching/instance_json.h) or its CPLEX LP form, solved by one of core/matching's solvers. The
// result is the object `tessera solve --json` prints (matching/result_json.h), so that the wasm
// build and the native command line can be compared field by field.
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <cstdint>
#include <span>
#include <string>

#include "guard.h"
#include "matching/instance_file.h"
#include "matching/result_json.h"
#include "matching/solver.h"
#include "typed_arrays.h"

namespace tessera::wasm {
namespace {

using emscripten::val;

// `solver` is "exact", "glpk" or "glpk-tuned"; `time_limit` in seconds.
val solve_p1(const std::string& instance, const std::string& solver, double time_limit) {
  return guard([&] {
    if (!(time_limit > 0)) throw InputError("the time limit must be a positive number of seconds");
    const matching::SolverKind kind = matching::solver_kind_from_name(solver);
    const std::span<const std::uint8_t> bytes(
        reinterpret_cast<const std::uint8_t*>(instance.data()), instance.size());
    const matching::MatchingProblem problem = matching::read_instance(bytes, "instance", Limits{});
    const matching::MatchingResult result = matching::solve_matching(problem, kind, time_limit);
    return json_to_val(matching::result_json(problem, kind, result));
  });
}

}  // namespace

EMSCRIPTEN_BINDINGS(tessera_matching) {
  emscripten::function("matchingSolve", &solve_p1);
}

}  // namespace tessera::wasm
