// The map of each patch onto its n x m rectangle (thesis Sec. 8.2) and the grid pulled back onto
// the surface.
//  - The patch's triangles of the refined mesh are unfolded into one chart: across each edge inside
//    the patch the two corner charts differ by a quarter turn and a shift (LAYOUT_NOTES "Charts and
//    transitions"), and a patch is a disk without singularities inside, so the unfolding is single
//    valued. There the patch is a quadrilateral with straight sides (the arcs are straight lines
//    in parameter space).
//  - Wachspress coordinates over that quadrilateral map each of its vertices to the rectangle
//    [0, n] x [0, m], corners to corners (Sec. 8.2, [Wac75]); on a side they interpolate linearly,
//    that is, by parametric arc length.
//  - Each integer point inside the rectangle is found in a mapped triangle and pulled back to 3D by
//    the triangle's barycentric coordinates. The points on the sides are placed by side_points(),
//    once per side, by parametric arc length, so neighbouring patches share them.
// The unfolding and the Wachspress coordinates (PatchChart) and the sides' arc lengths (SideTrack)
// do not depend on n and m: they are computed once per layout, and a new quad count only places
// the points again.
//
// In:  the refined mesh of a layout (per corner uv in its parent face's chart), its connectivity,
//      the patch ids, the sides (patch_sides.h) and the integer lengths (side_lengths.h).
// Out: 3D points with the surface normal under them.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "layout/refine.h"
#include "remesh/patch_sides.h"

namespace tessera::remesh {

struct SurfaceSample {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();  // of the refined face it lies on
};

// What does not depend on the side's number of segments: the parametric arc length at each of
// its vertices (measured in the chart of a face along each edge, from 0) and, per edge, the normal
// of the face along it.
struct SideTrack {
  std::vector<double> at;
  std::vector<Eigen::Vector3d> normal;
  double length() const { return at.back(); }
};

SideTrack side_track(const layout::RefinedMesh& refined, const Connectivity& connectivity,
                     const LayoutSide& side);

// The side's length along the surface.
double side_length_3d(const layout::RefinedMesh& refined, const LayoutSide& side);

// The segments + 1 points of side `side` at equal parametric arc length, from its first vertex to
// its last.
std::vector<SurfaceSample> side_points(const layout::RefinedMesh& refined, const LayoutSide& side,
                                       const SideTrack& track, int segments);

// A patch unfolded into one chart, as the Wachspress coordinates of its vertices in its
// quadrilateral: what does not depend on the patch's n x m.
struct PatchChart {
  std::vector<Index> faces;                         // the refined faces of the patch
  std::vector<std::array<std::uint32_t, 3>> local;  // per face, its corners into `weights`
  std::vector<Eigen::Vector4d> weights;             // per vertex of the patch
};

// `faces` are the refined faces of the patch, `corners` its four corner vertices.
PatchChart patch_chart(const layout::RefinedMesh& refined, const Connectivity& connectivity,
                       const std::vector<Index>& faces, const std::vector<Index>& corners);

// The grid points (i, j), 0 < i < n, 0 < j < m, of the patch, in the order
// (i - 1) + (j - 1)(n - 1). `unlocated` counts the points found in no mapped triangle (placed on
// the nearest one instead).
std::vector<SurfaceSample> patch_interior_points(const layout::RefinedMesh& refined,
                                                 const PatchChart& chart, int n, int m,
                                                 std::size_t& unlocated);

// Wachspress coordinates of x in the quadrilateral q (counterclockwise), in the product form
// w_i ~ A(q_{i-1}, q_i, q_{i+1}) A(x, q_{i+1}, q_{i+2}) A(x, q_{i+2}, q_{i+3}), which stays finite
// on the sides.
Eigen::Vector4d wachspress(const std::array<Eigen::Vector2d, 4>& q, const Eigen::Vector2d& x);

}  // namespace tessera::remesh
