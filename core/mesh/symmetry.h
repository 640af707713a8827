// Geometric symmetry of a mesh: which of some given rotations map its vertex set onto itself.
// A check of a symmetric construction on its output (e.g. the octahedral symmetry of a regular
// surface on the 2-Octahedron, thesis Sec. 9.6).
//
// In:  a mesh, rotations about the origin, a tolerance relative to the bounding-box diagonal.
// Out: for each rotation, whether every rotated vertex lies within the tolerance of a vertex.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "mesh/mesh.h"

namespace tessera {

std::vector<bool> keeps_vertex_set(const Mesh& mesh, const std::vector<Eigen::Matrix3d>& rotations,
                                   double relative_tolerance = 1e-6);

}  // namespace tessera
