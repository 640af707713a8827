// The mesh cut along the arcs (LAYOUT_NOTES "The layout itself"): every face crossed by an arc is
// split along the arc's pieces, so that arcs run along edges of the refined mesh. Inside a face the
// pieces are chords of the triangle; two chords cross iff their endpoints interleave along the
// triangle's boundary (decided combinatorially, the crossing point is a four-valent node), and the
// chords cut the triangle into convex polygons, which are triangulated. Points on an input edge are
// shared by both faces of the edge, so the refined mesh is conforming.
//
// In:  the charts and the arcs. Out: the refined triangle mesh (the input's vertices first, with
//      their numbers), per face the input face it lies in, per corner its (u, v) in that face's
//      chart, and the refined edges that lie on arcs.
#pragma once

#include <utility>
#include <vector>

#include "layout/arcs.h"

namespace tessera::layout {

struct RefinedMesh {
  Mesh mesh;
  std::vector<Index> parent;                       // per face
  std::vector<Eigen::Vector2d> uv;                 // per corner, chart of the parent face
  std::vector<std::pair<Index, Index>> arc_edges;  // (smaller vertex, larger vertex), sorted
};

RefinedMesh refine_along_arcs(const Charts& charts, const std::vector<Arc>& arcs);

}  // namespace tessera::layout
