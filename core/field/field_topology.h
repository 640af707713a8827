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

// A vertex of index 1/2 or more (valence 2 or less) is no node of a quad layout (Def. 2.3): where
// two ports leave it, each of its two patches has a corner there that no third side marks, and a
// single port is an arc ending inside a patch. Such vertices are two or three index-1/4
// singularities that the mesh resolution merged into one. Each interior one gives a quarter of its
// index at a time to an interior neighbour of index 0 or less (a valence-5 neighbour cancels),
// across the edge whose turn is closest to the opposite quarter, by changing that edge's period
// jump (its turn then leaves [-pi/4, pi/4]); the indices are updated. Poincare-Hopf is kept. A
// vertex with no such neighbour is left as it is.
void split_merged_singularities(const Connectivity& connectivity, Matching& matching,
                                std::vector<int>& vertex_index);

// The vertices with nonzero index, by vertex number, with their valence.
std::vector<Singularity> singularities(const Connectivity& connectivity,
                                       const std::vector<int>& vertex_index);

}  // namespace tessera
