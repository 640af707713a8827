// Twin edges of G (core/layout/twin_edges.h): the two corners of one rectangle give one edge, whose
// zero-area pairs are the union of both copies'; genuine multi-edges between two ports (other
// lengths, the other side) stay; on generated surfaces no twins are left and P1 keeps its layouts
// valid.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "layout/twin_edges.h"
#include "layout_test_util.h"
#include "mesh/shapes.h"

namespace tessera {
namespace {

using layout::EdgePair;
using layout::GraphEdge;

GraphEdge crossing_edge(Index u, Index v, double base, double height, int side) {
  GraphEdge e;
  e.u = u;
  e.v = v;
  e.base = base;
  e.height = height;
  e.side = side;
  return e;
}

TEST(TwinEdges, MergesTheCopiesAndTheirZeroAreaPairs) {
  layout::PortGraph graph;
  graph.edges = {
      crossing_edge(0, 1, 3.0, 1.0, 1),         // 0
      crossing_edge(2, 3, 2.0, 0.5, -1),        // 1
      crossing_edge(1, 0, 3.0, 1.0 + 1e-9, 1),  // 2: twin of 0, found at the other corner
      crossing_edge(0, 1, 3.0, 1.0, -1),        // 3: the mirror arc, another edge
      crossing_edge(0, 1, 4.0, 1.0, 1),         // 4: longer, another edge
      crossing_edge(4, 5, 1.0, 0.25, 1),        // 5
  };
  std::vector<layout::Arc> arcs(graph.edges.size());
  for (Index e = 0; e < arcs.size(); ++e) arcs[e].length = double(e);
  graph.zero_area = {{0, 1}, {1, 2}, {2, 5}, {3, 5}};

  EXPECT_EQ(layout::merge_twin_edges(graph, arcs), 1u);
  ASSERT_EQ(graph.edges.size(), 5u);
  ASSERT_EQ(arcs.size(), 5u);
  for (Index e = 0; e < arcs.size(); ++e) EXPECT_EQ(arcs[e].edge, e);
  EXPECT_EQ(arcs[2].length, 3.0);  // edge 3 is now edge 2
  EXPECT_EQ(arcs[4].length, 5.0);
  // 0-1 and 2-1 are one pair now; 2-5 became 0-4.
  EXPECT_EQ(graph.zero_area, (std::vector<EdgePair>{{0, 1}, {0, 4}, {2, 4}}));
}

TEST(TwinEdges, NoneAreLeftOnAGeneratedSurface) {
  const test::LayoutRun run = test::run_layout(double_torus(3));
  EXPECT_GT(run.graph.twin_edges, 0u);  // both corners of some rectangles were free
  std::map<std::pair<Index, Index>, std::vector<const GraphEdge*>> by_ports;
  for (const GraphEdge& e : run.graph.graph.edges) by_ports[std::minmax(e.u, e.v)].push_back(&e);
  for (const auto& [ports, edges] : by_ports)
    for (std::size_t i = 0; i < edges.size(); ++i)
      for (std::size_t j = 0; j < i; ++j) {
        const GraphEdge& a = *edges[i];
        const GraphEdge& b = *edges[j];
        const bool twins = a.kind == layout::EdgeKind::crossing &&
                           b.kind == layout::EdgeKind::crossing && a.side == b.side &&
                           std::abs(a.base - b.base) < 1e-6 * a.base &&
                           std::abs(a.height - b.height) < 1e-6 * a.base;
        EXPECT_FALSE(twins) << "ports " << ports.first << " and " << ports.second;
      }
  EXPECT_EQ(run.graph.arcs.size(), run.graph.graph.edges.size());
  EXPECT_TRUE(run.layout.check.valid());
}

}  // namespace
}  // namespace tessera
