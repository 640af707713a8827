// Cancellation of adjacent dipoles by rematching. Where principal matching (field_topology.h) meets
// an edge whose turn is close to the ambiguous 45 degrees, a tiny change of the field flips the
// chosen period jump and leaves a valence-3 and a valence-5 singularity on the two ends of that
// edge. Such a pair sits in one triangle, whose bisector constraints (6.2), (6.3) then cannot all
// hold, and the triangle stays flipped in the parameterization (Sec. 6.5). Taking the other period
// jump on that edge (turn delta -/+ pi/2) gives both ends index 0: the field's directions are kept,
// only their matching across one edge changes, and the pair disappears.
//
// In:  a cross field (cross_field.h) and the edges to rematch where they join such a pair.
// Out: the field with changed period jumps, vertex indices and singularities; nothing throws.
#pragma once

#include <cstddef>

#include "field/cross_field.h"

namespace tessera {

struct DipoleRematching {
  CrossField field;
  std::size_t cancelled = 0;  // pairs of singularities removed
};

// Over the marked edges (per edge 1) joining an index-1/4 and an index-(-1/4) vertex, the
// smallest new turn |delta| first (a vertex in several pairs is cancelled once). The last pair of
// a field is kept: a field without singularities may turn around a loop of a torus, which admits
// no seamless parameterization.
DipoleRematching cancel_adjacent_dipoles(const Connectivity& connectivity, CrossField field,
                                         const std::vector<std::uint8_t>& edges);

}  // namespace tessera
