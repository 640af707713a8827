// Symmetric bases for edge graphs of one or two junctions: the bouquets and dipoles, a third of
// the census up to genus 29 (the thesis's "hosohedral surfaces", Sec. 9.6), where high valence
// makes the relaxation tangle its tubes. Both placements keep every two tubes apart by
// construction.
//
//  - One junction, a bouquet of q/2 loops. The rotation group <S> is then cyclic of order q, so
//    the half turn RS is S^(q/2): every loop joins two opposite darts. Each loop is an arch over
//    the junction in the vertical plane of its darts; two such planes meet only in the axis, and
//    the arches cross the axis at heights a clearance and a half apart.
//  - Two junctions, a dipole of q edges. The junctions sit on the vertical axis, normals
//    outwards. Each edge leaves the top junction radially, goes down a cylinder about the axis,
//    turning by the angle between its two ends' directions, and enters the bottom junction
//    radially. Tubes on one cylinder keep apart when their turns do (checked along the height);
//    an edge that would come too close to one goes to a larger cylinder. The bottom junction's
//    side and turn about the axis are the ones with the least turning, so a hosohedron's edges
//    become straight meridians.
//
// In:  an edge graph with its junction order; a tube shape (for the sizes).
// Out: the placement (symmetric under the half turn about the axis for a bouquet), or nothing
//      when the graph has more than two junctions or loops at one of two.
#pragma once

#include <optional>

#include "regmap/symmetric_base.h"

namespace tessera::regmap {

std::optional<SymmetricPlacement> hosohedral_placement(const EdgeGraph& graph,
                                                       const JunctionOrder& order,
                                                       const TubeShape& shape);

}  // namespace tessera::regmap
