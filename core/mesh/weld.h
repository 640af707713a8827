// Finding near-duplicate vertices, for validation (validate.h) to weld them.
//
// In:  positions and an absolute tolerance (0: bit-identical positions only).
// Out: per vertex, the earlier vertex it coincides with within the tolerance, or itself. Linear
//      time: a hash grid of cells twice the tolerance wide, so that each vertex looks at the 8
//      cells its tolerance ball can reach.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "mesh/mesh.h"

namespace tessera {

std::vector<Index> weld_targets(const std::vector<Eigen::Vector3d>& positions, double tolerance);

}  // namespace tessera
