#include "regmap/symmetric_base.h"

#include "regmap/bouquet_base.h"
#include "regmap/platonic_base.h"
#include "regmap/spine_base.h"

namespace tessera::regmap {

std::optional<SymmetricPlacement> symmetric_placement(const EdgeGraph& graph,
                                                      const JunctionOrder& order,
                                                      const TubeShape& shape) {
  if (auto platonic = platonic_placement(graph, order, shape)) return platonic;
  if (auto bouquet = bouquet_placement(graph, order, shape)) return bouquet;
  if (graph.node_count == 2) return spine_placement(graph, order, shape);
  return std::nullopt;
}

}  // namespace tessera::regmap
