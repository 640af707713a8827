// Arcs of G's edges (core/layout/arcs.h): a straight arc ends at its far singularity coming in
// along its far port's hypotenuse. An edge whose far port is swapped for a neighbour at the same
// singularity traces the very same line, which now comes in through the wrong sector: it has no
// arc (it would take the place of the neighbour's arc there).
#include <gtest/gtest.h>

#include "layout/arcs.h"
#include "layout_test_util.h"
#include "mesh/shapes.h"

namespace tessera {
namespace {

TEST(Arcs, ArriveThroughTheirFarPortOnly) {
  const test::LayoutRun run = test::run_layout(double_torus(3));
  const layout::Charts charts = run.input.charts();
  layout::PortGraph graph = run.graph.graph;
  std::size_t checked = 0;
  for (Index e = 0; e < graph.edges.size(); ++e) {
    const layout::GraphEdge edge = graph.edges[e];
    if (edge.kind == layout::EdgeKind::boundary) continue;
    ASSERT_TRUE(layout::trace_arc(charts, graph, e).has_value()) << "edge " << e;
    for (int step : {-1, 1}) {
      const Index neighbour = graph.ports.neighbour(edge.v, step);
      if (neighbour == kNoIndex || neighbour == edge.u) continue;
      graph.edges[e].v = neighbour;
      EXPECT_FALSE(layout::trace_arc(charts, graph, e).has_value()) << "edge " << e;
      graph.edges[e].v = edge.v;
      ++checked;
    }
  }
  EXPECT_GT(checked, 100u);
}

}  // namespace
}  // namespace tessera
