// GLPK's branch-and-bound on program P1 (thesis (5.1)-(5.4), Appendix B): the reference solver and
// the fallback. Plain: the model as the thesis states it, solved as `glpsol` does (LP relaxation by
// the simplex method, then glp_intopt with its defaults). Tuned: the conflict rows aggregated into
// clique rows (cliques.h), a known matching handed in as the first incumbent, and GLPK's cut
// generators on.
#pragma once

#include <cstdint>
#include <vector>

#include "base/progress.h"
#include "matching/problem.h"
#include "matching/result.h"

namespace tessera::matching {

struct GlpkConfig {
  bool clique_rows = false;              // (5.3) as clique rows instead of one row per pair
  bool cuts = false;                     // GLPK's MIR, Gomory, cover and clique cuts
  std::vector<std::uint32_t> incumbent;  // a feasible matching (edge indices), or empty
};

// Solves within limits.nodes nodes of GLPK's search tree (counted in its callback, which stops
// it) and limits.seconds of wall clock (a guard). Progress::step("glpk", elapsed / guard) is called
// a few times a second; a CancelledError it throws stops GLPK and is rethrown.
MatchingResult solve_with_glpk(const MatchingProblem& problem, const GlpkConfig& config,
                               const SolveLimits& limits, const Progress& progress);

}  // namespace tessera::matching
