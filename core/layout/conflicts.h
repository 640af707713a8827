// The illegal crossings I (thesis Sec. 4.6, Algorithm 1, Remarks 4.1 and 4.2): two edges whose
// hypotenuses cross with the same alignment (bases parallel) cannot both be arcs of a layout;
// differently aligned crossings are legal (they make a four-valent node); the zero-area pairs Z of
// case 3 are added.
//
// Algorithm 1 decides a crossing in a local frame at each intersection m of two separatrices, with
// every edge whose triangle has a side on either line laid out by walking along that line from m.
// That frame holds both triangles only where the region they span around m is flat; around
// clustered singularities it lays over each other triangles that lie on different sheets of the
// surface. On fertility 6,749 of the 83,263 pairs of the frames (bunny: 21,290 of 245,422) were
// such, with arcs that never meet, while every pair found on the surface was in a frame too. So
// the relation is read where it is exact, on the surface: the arcs of all edges
// (keep_edges_with_arcs()) are intersected face by face, and two that meet are an illegal pair
// when their bases, turned into that face's chart, are parallel (bases are isolines:
// axis-parallel in every chart). This also holds self-crossing separatrices (Remark 4.1) and
// crossings beyond where the separatrices through them stopped (L_max, spiral test, singularity).
#pragma once

#include <vector>

#include "base/progress.h"
#include "layout/arcs.h"

namespace tessera::layout {

// In:  the charts, the graph, one arc per edge. Out: I union Z, sorted, without pairs of edges
//      sharing a node.
std::vector<EdgePair> illegal_crossings(const Charts& charts, const PortGraph& graph,
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
