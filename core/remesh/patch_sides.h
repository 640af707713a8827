// The sides of a layout's patches as the remeshing sees them (thesis Sec. 8.1): every patch of a
// valid layout is a disk with four corners, and its boundary from corner k to corner k + 1 is side
// k. A side shared by two patches is one LayoutSide, walked once; the patch on the other side of it
// runs along it backwards. Sides on the surface's boundary belong to one patch.
//
// In:  the refined mesh of a layout, its connectivity, the patch id per face and the layout's check
//      (valid: four corners per patch, counterclockwise).
// Out: the sides as vertex chains of the refined mesh (node to node) and per patch its four sides.
// Throws InputError naming the patch if the check is not valid or a side cannot be walked.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "layout/layout_check.h"
#include "mesh/connectivity.h"
#include "mesh/mesh.h"

namespace tessera::remesh {

struct LayoutSide {
  std::vector<Index> vertices;  // of the refined mesh, from one corner node to the next
};

struct PatchSide {
  std::size_t side = 0;  // into PatchSides::sides
  bool forward = true;   // the side's vertices run from corner k to corner k + 1 of the patch
};

struct PatchSides {
  std::vector<LayoutSide> sides;
  std::vector<std::array<PatchSide, 4>> patches;  // per patch, side k from corner k to k + 1
};

PatchSides patch_sides(const Connectivity& connectivity, const std::vector<std::int32_t>& patch,
                       const layout::LayoutCheck& check);

}  // namespace tessera::remesh
