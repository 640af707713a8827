// The illegal crossings I (thesis Sec. 4.6, Algorithm 1, Remarks 4.1 and 4.2). At every
// intersection m of gamma_a and gamma_b (possibly one self-crossing separatrix, Remark 4.1), the
// parameter chart around m is a common local frame: every edge whose triangle has a side on a (on
// b) is laid out in it by walking along a (along b) from m, its hypotenuse a segment there. Two
// edges with the same alignment (bases parallel) whose hypotenuses cross are an illegal pair;
// differently aligned crossings are legal. Illegality in one frame suffices. The zero-area pairs Z
// of case 3 are added. Algorithm 1 names the set K of intersections that satisfy C1; every
// intersection is used here, because two edges can cross where neither of the lines through the
// crossing point gave an edge there (the frame still holds both triangles).
//
// Only pairs with one edge on a and the other on b are tested: two edges on the same line either
// share a port (never matched together), are differently aligned, or lie on opposite sides of it.
//
// In:  the grown PortGraph. Out: I union Z, sorted, without pairs of edges sharing a node.
#pragma once

#include <vector>

#include "base/progress.h"
#include "layout/arcs.h"

namespace tessera::layout {

std::vector<EdgePair> illegal_crossings(const PortGraph& graph, const Progress& progress);

// The same relation read off the surface: the arcs of all edges (keep_edges_with_arcs()) are
// intersected face by face, and two crossing arcs are an illegal pair when their bases, turned
// into the crossing face's chart, are parallel (bases are isolines: axis-parallel in every chart).
// This finds the crossings that no frame of Algorithm 1 holds, where the separatrices through the
// crossing stopped before it (at L_max, by the spiral test or at a singularity).
//
// In:  the charts, the graph, one arc per edge. Out: the illegal pairs, sorted, without pairs of
//      edges sharing a node.
std::vector<EdgePair> illegal_arc_crossings(const Charts& charts, const PortGraph& graph,
                                            const std::vector<Arc>& arcs, const Progress& progress);

// The pairs among the chosen arcs that close a loop with two convex corners: arcs joining the same
// two singularities, and arcs leaving one singularity that cross (the loop runs from it to the
// crossing). By Gauss-Bonnet on the flat charts such a loop bounds no disk without a cone inside,
// so it runs around a handle, and unless other arcs cut across it the patches beside it are no
// disks: they touch themselves at its corners. Program P1 cannot see this (Lemma 5.1 takes every
// region it leaves for a disk), so solve_layout() adds these pairs as conflicts when its check
// fails and solves again.
//
// In:  the charts, the graph, the arcs of the chosen edges. Out: pairs of their edges, sorted.
std::vector<EdgePair> loop_pairs(const Charts& charts, const PortGraph& graph,
                                 const std::vector<Arc>& chosen);

}  // namespace tessera::layout
