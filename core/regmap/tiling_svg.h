// The picture of Tri(G) as in thesis Fig. 9.8b: the fundamental polygon with its triangles coloured
// by the face of the map they belong to (two shades: orientation-preserving or not), map edges
// drawn dark, and each pair of identified boundary edges drawn in a colour of its own with the same
// number and an arrow from the vertex (N) end to the midpoint (O) end, which the pairing maps onto
// each other. Hyperbolic maps are drawn in the Poincare disk, torus maps in the plane, spherical
// maps as two orthographic hemispheres (front, and back seen from behind).
#pragma once

#include <string>

#include "regmap/finite_group.h"
#include "regmap/triangle_tiling.h"

namespace tessera::regmap {

// SVG text of the tiling, `width_px` wide, with `title` as its <title>.
std::string tiling_svg(const FiniteGroup& group, const TriangleTiling& tiling,
                       const std::string& title, double width_px = 1000);

}  // namespace tessera::regmap
