// The conflicts a failed round of P1 adds on a quad mesh (layout/quad_layout.h RepairPairs).
//
// Theorem 5.1 rests on Lemma 5.1, which takes every region the matching leaves for a disk. On a
// surface with handles a matching with only legal crossings can leave annuli: on a torus grid with
// one rotated edge (two valence-3 and two valence-5 vertices side by side), alpha 0 takes the
// diagonal edges inside the cluster and three loops around the torus, and three of its four
// patches are annuli. The layout stage's loop_pairs() (layout/conflicts.h) sees loops with two
// convex corners only; this adds, for every patch the check faults (no disk, not four corners,
// touching itself at a vertex), the pairs of
// chosen edges near it of which one at least is no separatrix of B (an edge made at a crossing);
// a faulty patch that gives no such pair (an annulus around a handle bounded by separatrices of B:
// fertility_qf20k at alpha 0) pairs its edges with the crossing edges that took the ports of B's
// separatrices through it.
// B itself (Sec. 7.2) is a valid layout and meets none of these pairs, so P1 stays feasible, and
// each round rules out the matching that failed.
//
// In:  the charts, the graph, the failed round's layout. Out: loop_pairs() and these pairs, those
//      of two separatrices of B left out, sorted, without repeats and without pairs of edges that
//      share a port.
#pragma once

#include <vector>

#include "layout/quad_layout.h"

namespace tessera::quadmesh {

std::vector<layout::EdgePair> quad_repair_pairs(const layout::Charts& charts,
                                                const layout::PortGraph& graph,
                                                const layout::QuadLayout& failed);

}  // namespace tessera::quadmesh
