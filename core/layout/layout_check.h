// The validity checker of a quad layout (SPEC "Invariants"), from the refined mesh and the patch
// id of each face alone, and the patch graph it finds on the way.
//
// A node is a vertex where at least three sides meet (the fans of faces of one patch around it,
// the surface's boundary counting as a side), or a corner of the boundary curve: where it turns by
// more than 45 degrees, read over a few edges on either side (mesh/boundary_tangents.h), so that
// the steps of a boundary cut through triangles are no corners. The layout is valid iff
//  - the patches cover the surface: every face has a patch id in [0, patch count), every id is
//  used;
//  - every patch is a topological disk: one edge-connected piece, Euler characteristic 1, one
//    simple boundary loop (no vertex where the patch touches itself);
//  - every patch has exactly four corners: the nodes on its boundary loop. Arcs (the edges between
//    different patches) then meet only at nodes, and a T-junction (an arc ending in the middle of a
//    side) shows as a fifth corner of the patch it ends on.
//
// In:  a triangle mesh (any faces), one patch id per face. Out: nodes, per patch its corners and
// the
//      patch across each side, the arcs as vertex chains, the first problems found. Nothing throws.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "mesh/connectivity.h"
#include "mesh/mesh.h"

namespace tessera::layout {

struct LayoutArc {
  std::vector<Index> vertices;  // from one node to another along patch boundaries
  std::int32_t left = -1;       // the patch on each side (-1: the surface's boundary)
  std::int32_t right = -1;
};

struct LayoutCheck {
  std::size_t patch_count = 0;
  std::vector<Index> nodes;
  std::vector<std::vector<Index>> corners;            // per patch, counterclockwise
  std::vector<std::vector<std::int32_t>> neighbours;  // per patch, across side k (corner k to k+1)
  std::vector<LayoutArc> arcs;
  std::vector<std::string> problems;         // the first few, e.g. "patch 7 has 5 corners (...)"
  std::vector<std::int32_t> faulty_patches;  // every patch a problem names, increasing
  std::size_t problem_count = 0;
  bool valid() const { return problem_count == 0 && patch_count > 0; }
};

LayoutCheck check_layout(const Mesh& mesh, const std::vector<std::int32_t>& patch);
// The same with the mesh's connectivity (build_connectivity()) given, e.g. the one the patches
// were assigned on.
LayoutCheck check_layout(const Mesh& mesh, const Connectivity& connectivity,
                         const std::vector<std::int32_t>& patch);

}  // namespace tessera::layout
