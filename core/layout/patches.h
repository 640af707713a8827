// Patches of a layout: the connected components of the refined mesh's faces, joined across every
// edge that is not on an arc (LAYOUT_NOTES "The layout itself").
//
// In:  the mesh refined along the arcs and its connectivity. Out: per face its patch id, 0-based,
//      numbered in the order of each patch's first face.
#pragma once

#include <cstdint>
#include <vector>

#include "layout/refine.h"
#include "mesh/connectivity.h"

namespace tessera::layout {

std::vector<std::int32_t> assign_patches(const RefinedMesh& refined, const Connectivity& c);

}  // namespace tessera::layout
