// Program P1 (thesis Ch. 5, (5.1)-(5.4)) for a port graph: the nodes are the ports (matched
// exactly once) and the virtual ports (at most once, Sec. 4.4), the edges carry
// w = L_base + alpha L_height (4.1), the conflicts are I with Z (Sec. 4.6). Before solving,
// Sec. 5.1 asks whether G has a perfect matching at all, ignoring the conflicts: Edmonds' blossom
// algorithm (LEMON's maximum weighted matching, every edge weighted by the ports it covers) decides
// it.
//
// In:  a port graph with its conflicts, alpha >= 0. Out: the MatchingProblem of core/matching.
#pragma once

#include "layout/port_graph.h"
#include "matching/problem.h"

namespace tessera::layout {

matching::MatchingProblem matching_problem(const PortGraph& graph, double alpha);

// True iff some set of edges covers every port once and every virtual port at most once.
bool has_perfect_matching(const matching::MatchingProblem& problem);

}  // namespace tessera::layout
