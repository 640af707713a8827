// Symmetric bases from the Platonic solids (thesis Sec. 9.6, Fig. 9.19): the double covers of the
// solids branched at their face centres, "our favorite embeddings":
//   2-Tetrahedron {6,3} (genus 1), 2-Cube {8,3} (genus 2), 2-Octahedron {6,4} (genus 3),
//   2-Dodecahedron {10,3} (genus 5), 2-Icosahedron {6,5} (genus 9),
// whose tubified edge graphs have genus 7, 9, 13, 21 and 37.
//
// A double cover has two copies (sheets) of every vertex v of the solid; an edge vw lifts to the
// two edges (v, s) - (w, s + c(vw)), s = 0, 1, where the cochain c sums to 1 (mod 2) around every
// face, so that going once around a face centre changes the sheet: the face centres are the branch
// points. A lifted vertex has the solid's rotation. In space the sheets are two concentric copies
// of the solid, each junction's normal pointing outwards; an edge joining the sheets is one of a
// crossing pair (v_in w_out, v_out w_in) whose midpoints are pushed apart along v x w, a rule
// every rotation preserves. A rotation of the solid is a symmetry of the placement when it keeps
// c: for c = 1 on every edge, which sums to 1 around the odd faces of the tetrahedron, octahedron,
// dodecahedron and icosahedron, that is the whole rotation group ("we only lost the non-oriented
// symmetry"); the cube's square faces allow no invariant c, and the c with the most symmetries is
// taken (the thesis's "one C3 axis and one C2 axis").
//
// In:  an edge graph with its junction order; a tube shape (for the scale).
// Out: the placement of the base whose map is isomorphic to the graph's (map_isomorphism.h), in
//      the graph's own numbering, with the rotations it is symmetric under; nothing if no base
//      fits.
#pragma once

#include <optional>

#include "regmap/symmetric_base.h"

namespace tessera::regmap {

std::optional<SymmetricPlacement> platonic_placement(const EdgeGraph& graph,
                                                     const JunctionOrder& order,
                                                     const TubeShape& shape);

}  // namespace tessera::regmap
