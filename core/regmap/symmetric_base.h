// Placements of an edge graph built from a model instead of relaxed (thesis Sec. 9.6): a double
// cover of a Platonic solid (platonic_base.h), one junction (bouquet_base.h), two junctions on a
// spine (spine_base.h). Each keeps every two tubes apart by construction.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "regmap/embedded_graph.h"
#include "regmap/tubification.h"

namespace tessera::regmap {

struct SymmetricPlacement {
  std::string name;  // "2-Octahedron", "bouquet", "spine", ...
  EmbeddedGraph embedded;
  std::vector<Eigen::Matrix3d> symmetries;  // rotations about the origin that map it to itself
};

// The Platonic base if one fits, else the bouquet for one junction, the spine for two, else
// nothing.
std::optional<SymmetricPlacement> symmetric_placement(const EdgeGraph& graph,
                                                      const JunctionOrder& order,
                                                      const TubeShape& shape);

}  // namespace tessera::regmap
