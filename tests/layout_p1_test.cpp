// Program P1 from the port graph (core/layout/p1.h): weights (4.1) per alpha, virtual ports,
// conflicts.
#include <gtest/gtest.h>

#include "layout/p1.h"

namespace tessera {
namespace {

TEST(P1, WeightsAndVirtualPortsFromTheGraph) {
  layout::PortGraph graph;
  graph.ports.ports.resize(2);
  graph.virtual_ports.resize(1);
  layout::GraphEdge e;
  e.u = 0;
  e.v = 1;
  e.base = 3;
  e.height = 2;
  graph.edges.push_back(e);
  e.kind = layout::EdgeKind::boundary;
  e.v = 2;
  e.height = 0;
  graph.edges.push_back(e);
  graph.conflicts.push_back({0, 1});
  const matching::MatchingProblem p = layout::matching_problem(graph, 5);
  EXPECT_EQ(p.is_virtual, (std::vector<std::uint8_t>{0, 0, 1}));
  ASSERT_EQ(p.edges.size(), 2u);
  EXPECT_EQ(p.edges[0].weight, 13);
  EXPECT_EQ(p.edges[1].weight, 3);
  EXPECT_EQ(layout::matching_problem(graph, 0).edges[0].weight, 3);
  ASSERT_EQ(p.conflicts.size(), 1u);
}

}  // namespace
}  // namespace tessera
