// Symmetric placements of an edge graph (thesis Sec. 9.6): instead of the relaxation, a placement
// built from a symmetric model when the map has one — a double cover of a Platonic solid
// (platonic_base.h), or one or two junctions (hosohedral_base.h).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "regmap/embedded_graph.h"
#include "regmap/tubification.h"

namespace tessera::regmap {

struct SymmetricPlacement {
  std::string name;  // "2-Octahedron", "bouquet", "dipole", ...
  EmbeddedGraph embedded;
  std::vector<Eigen::Matrix3d> symmetries;  // rotations about the origin that map it to itself
};

// The Platonic base if one fits, else the hosohedral one, else nothing.
std::optional<SymmetricPlacement> symmetric_placement(const EdgeGraph& graph,
                                                      const JunctionOrder& order,
                                                      const TubeShape& shape);

}  // namespace tessera::regmap
