// Beyond the thesis (issue 39): the per-patch maps of Sec. 8.2 are only C0 across patch sides, and
// they keep the layout's arcs where they are, so a quad at a layout corner that is wide on the
// surface stays wide. This pass relaxes the whole quad mesh at once: in each round every free
// vertex in turn moves halfway to the mean of its neighbours and is projected back onto the input
// surface (its nearest point), unless that lowers the least scaled Jacobian of its quads below
// both its old value and 0.5 (so no quad gets flipped or worse than that). The layout's nodes
// and the vertices on the surface's boundary stay fixed, and no quad changes its vertices, so the
// base complex is still the layout; the arcs between nodes may move.
//
// In:  the quad mesh with the surface normal at each vertex, which vertices are fixed, the input
//      triangle mesh, the number of rounds. Out: the positions and normals, moved.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "mesh/mesh.h"

namespace tessera::remesh {

void smooth_on_surface(Mesh& quads, std::vector<Eigen::Vector3d>& normal,
                       const std::vector<bool>& fixed, const Mesh& surface, int rounds);

// The point of triangle (a, b, c) nearest to p.
Eigen::Vector3d nearest_on_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                    const Eigen::Vector3d& b, const Eigen::Vector3d& c);

}  // namespace tessera::remesh
