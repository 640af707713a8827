// Combing a cross field into a cut graph (Sec. 6.6, App. A): a dual spanning tree over the faces,
// the field's representatives turned along the tree so that the period jump is 0 across every tree
// edge, and the primal edges the tree does not cross as the cut graph. Cutting along it opens every
// component of the surface to a topological disk on which the combed field has no jumps; the cut
// runs through every singularity.
//
// In:  connectivity, frames and a cross field of the same mesh.
// Out: plain values; nothing throws.
#pragma once

#include <cstdint>
#include <vector>

#include "field/cross_field.h"

namespace tessera {

struct DualTree {
  std::vector<Index> order;            // faces, each after the face it is reached from
  std::vector<Index> parent_halfedge;  // per face: the halfedge of its parent face through which
                                       // the tree reaches it; kNoIndex for the root of a component
};

// Breadth-first from the lowest face of each component, across edges with zero period jump first
// (so that combing turns few faces), then across the others.
DualTree dual_spanning_tree(const Connectivity& connectivity, const CrossField& field);

// The field with the representative of every face turned by a multiple of 90 degrees so that the
// period jump across every tree edge is 0; the other edges' jumps change to match.
CrossField comb(const Connectivity& connectivity, const FaceFrames& frames, const CrossField& field,
                const DualTree& tree);

// Per edge 1 if it is on the cut graph: interior edges not crossed by the tree, without the
// dangling branches that end at a regular interior vertex (cutting those would open nothing).
std::vector<std::uint8_t> cut_graph(const Connectivity& connectivity, const CrossField& field,
                                    const DualTree& tree);

}  // namespace tessera
