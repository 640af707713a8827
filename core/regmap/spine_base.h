// A placement meant to be without crossings for an edge graph without loops: the junctions stacked
// on a vertical axis (the spine), every tube on a cylinder about it. It generalizes the thesis's
// hosohedral surfaces (Sec. 9.6: two junctions, the tubes between them) to any number of
// junctions; the automatic placement takes it for two junctions, and when the relaxation leaves
// a surface that crosses itself.
//
// The junctions are horizontal, one per level in breadth-first order, each facing up or down and
// turned about the axis so that its tubes to the levels above turn least (a hosohedron's tubes
// become straight meridians). A tube leaves its junction radially, rounds a quarter circle onto
// its cylinder, runs along it to the other junction's level and rounds back in. Its azimuth
// changes smoothly with height, and it passes every junction level in between through the middle
// of a gap between that junction's darts, where neither the junction's own corners nor its radial
// runs are. Tubes on one cylinder keep a clearance and a half apart all along the height (their
// azimuths compared at fine steps of height); a tube that would not goes to the next larger
// cylinder. So no two tubes meet on the catalog's graphs up to genus 8 with at most 64 junctions
// (tested); R7.1's (72 junctions) still crosses itself.
//
// In:  an edge graph with its junction order (at least two junctions, no loops); a tube shape.
// Out: the placement, or nothing for a graph with a loop or a single junction.
#pragma once

#include <optional>

#include "regmap/symmetric_base.h"

namespace tessera::regmap {

std::optional<SymmetricPlacement> spine_placement(const EdgeGraph& graph,
                                                  const JunctionOrder& order,
                                                  const TubeShape& shape);

}  // namespace tessera::regmap
