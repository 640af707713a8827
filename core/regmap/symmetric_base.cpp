#include "regmap/symmetric_base.h"

#include "regmap/hosohedral_base.h"
#include "regmap/platonic_base.h"

namespace tessera::regmap {

std::optional<SymmetricPlacement> symmetric_placement(const EdgeGraph& graph,
                                                      const JunctionOrder& order,
                                                      const TubeShape& shape) {
  if (auto platonic = platonic_placement(graph, order, shape)) return platonic;
  return hosohedral_placement(graph, order, shape);
}

}  // namespace tessera::regmap
