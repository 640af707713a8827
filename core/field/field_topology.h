// Topology of a cross field (Sec. 6.3, Def. 2.3): period jumps by principal matching, the field's
// turn across each edge, vertex indices, singularities and the Poincare-Hopf sum. The conventions
// are stated in cross_field.h.
//
// In:  mesh, connectivity, frames, per-face field angles and per-halfedge connection angles.
// Out: plain per-halfedge / per-vertex arrays; nothing throws.
#pragma once

#include <cstdint>
#include <vector>

#include "field/cross_field.h"

namespace tessera {

struct Matching {
  std::vector<std::uint8_t> period_jump;  // per halfedge, p_ij in {0, 1, 2, 3}
  std::vector<double> turn;               // per halfedge, delta_ij in [-pi/4, pi/4]
};

// Principal matching: per interior edge the p_ij that leaves the smallest turn |delta_ij|.
Matching principal_matching(const Connectivity& connectivity, const std::vector<double>& angle,
                            const std::vector<double>& kappa);

// 4 * index of every vertex (0 for a vertex in no face).
std::vector<int> vertex_indices(const Mesh& mesh, const Connectivity& connectivity,
                                const FaceFrames& frames, const std::vector<double>& angle,
                                const std::vector<double>& turn);

// The vertices with nonzero index, by vertex number, with their valence.
std::vector<Singularity> singularities(const Connectivity& connectivity,
                                       const std::vector<int>& vertex_index);

}  // namespace tessera
