// A quad mesh from a quad layout (thesis Ch. 8): the integer side lengths (Sec. 8.1,
// side_lengths.h), the map of each patch onto its rectangle (Sec. 8.2, patch_map.h), and one
// conforming all-quad mesh out of the grids: the layout's nodes, the points on each side and the
// points inside each patch are vertices once, so that neighbouring patches share vertex indices.
//
// In:  a valid quad layout (layout/quad_layout.h), the size target, optionally smoothing rounds.
// Out: the quad mesh with the face attribute "patch" (the layout's patch of each quad), the
//      integer lengths, the quality figures (quad_quality.h) and the seconds per step.
// Throws InputError for an invalid layout or target (naming the patch or side at fault).
//
// What the size target does not change (the sides with their parametric arc lengths, each patch
// unfolded with its Wachspress coordinates) is a RemeshPrep of the layout, made once: a new target
// then solves only (8.1)-(8.3) again and places the points (the page's quad-count slider).
#pragma once

#include <string>
#include <vector>

#include "layout/quad_layout.h"
#include "mesh/connectivity.h"
#include "remesh/patch_map.h"
#include "remesh/patch_sides.h"
#include "remesh/quad_quality.h"
#include "remesh/side_lengths.h"

namespace tessera::remesh {

struct QuadMesh {
  Mesh mesh;  // all quads; face_attributes["patch"]
  SideLengths lengths;
  QuadQuality quality;
  std::size_t patch_count = 0;          // of the layout
  std::size_t unlocated_points = 0;     // grid points found in no mapped triangle (patch_map.h)
  std::size_t irregular_off_nodes = 0;  // irregular vertices that are no node of the layout
  // Quad corners with a scaled Jacobian <= 0 that sit at a node of the layout: where the layout's
  // own corner is reflex on the surface, which no map of the patch can straighten (Sec. 8.1 end).
  std::size_t nonpositive_corners_at_nodes = 0;
  std::vector<layout::StageSeconds> seconds;
};

struct RemeshPrep {
  Connectivity connectivity;  // of layout.refined.mesh
  PatchSides sides;
  std::vector<SideTrack> tracks;   // per side
  std::vector<double> length_3d;   // per side
  std::vector<PatchChart> charts;  // per patch
  std::vector<layout::StageSeconds> seconds;
};

// Throws InputError for an invalid layout (patch_sides.h).
RemeshPrep prepare_remesh(const layout::QuadLayout& layout);

// The quad mesh of `layout` from its prep (made of this very layout), as remesh_layout().
QuadMesh remesh_prepared(const layout::QuadLayout& layout, const RemeshPrep& prep,
                         const SizeTarget& target, int smoothing_rounds = 0,
                         const Mesh* surface = nullptr);

// `smoothing_rounds` > 0: that many rounds of smooth_on_surface() (smoothing.h) over the input
// surface `surface` (the layout's input mesh) before the quality figures.
QuadMesh remesh_layout(const layout::QuadLayout& layout, const SizeTarget& target,
                       int smoothing_rounds = 0, const Mesh* surface = nullptr);

}  // namespace tessera::remesh
