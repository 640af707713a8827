// Program P1 (thesis Ch. 5, (5.1)-(5.4)) for a port graph: the nodes are the ports (matched
// exactly once) and the virtual ports (at most once, Sec. 4.4; so are the folded ports of a
// singular ring the parameterization left flipped, ports.h), the edges carry
// w = L_base + alpha L_height (4.1), the conflicts are I with Z (Sec. 4.6). core/matching solves it
// and tells which ports no matching can cover (Sec. 5.1).
//
// In:  a port graph with its conflicts, alpha >= 0. Out: the MatchingProblem of core/matching.
#pragma once

#include "layout/port_graph.h"
#include "matching/problem.h"

namespace tessera::layout {

matching::MatchingProblem matching_problem(const PortGraph& graph, double alpha);

// The pairs of chosen edges that closed loops in a round's layout (Ch. 5, conflicts.h
// loop_pairs()) as conflicts of P1 for the next round.
void add_loop_conflicts(const std::vector<EdgePair>& loop_pairs,
                        matching::MatchingProblem& problem);

}  // namespace tessera::layout
