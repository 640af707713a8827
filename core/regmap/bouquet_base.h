// The placement of an edge graph with one junction, a bouquet of q/2 loops (thesis Sec. 9.6's
// one-junction surfaces, R2.4's genus-5 surface of Fig. 9.6 among them), where high valence makes
// the relaxation tangle its tubes. The rotation group <S> is then cyclic of order q, so the half
// turn RS is S^(q/2): every loop joins two opposite darts. Each loop is an arch over the junction
// in the vertical plane of its darts; two such planes meet only in the axis, and the arches cross
// the axis at heights a clearance and a half apart, so no two tubes meet. The half turn about the
// axis maps every arch to itself.
//
// In:  an edge graph with its junction order; a tube shape (for the sizes).
// Out: the placement, or nothing when the graph has more than one junction.
#pragma once

#include <optional>

#include "regmap/symmetric_base.h"

namespace tessera::regmap {

std::optional<SymmetricPlacement> bouquet_placement(const EdgeGraph& graph,
                                                    const JunctionOrder& order,
                                                    const TubeShape& shape);

}  // namespace tessera::regmap
