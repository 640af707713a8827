// Program P1 from the port graph (core/layout/p1.h): weights (4.1) per alpha, virtual ports, and
// the perfect-matching test of Sec. 5.1 (Edmonds' blossom algorithm) on small graphs, odd cycles
// included.
#include <gtest/gtest.h>

#include "layout/p1.h"

namespace tessera {
namespace {

matching::MatchingProblem problem_of(std::size_t ports, std::size_t virtual_ports,
                                     const std::vector<std::pair<Index, Index>>& edges) {
  matching::MatchingProblem p;
  p.is_virtual.assign(ports, 0);
  p.is_virtual.resize(ports + virtual_ports, 1);
  for (const auto& [u, v] : edges) p.edges.push_back({u, v, 1.0});
  return p;
}

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

TEST(P1, BlossomFindsPerfectMatchingsThroughOddCycles) {
  // A triangle has none; a triangle with a pendant pair needs the blossom: 0-1-2 odd cycle,
  // 2-3, 3-4, 4-5.
  EXPECT_FALSE(layout::has_perfect_matching(problem_of(3, 0, {{0, 1}, {1, 2}, {2, 0}})));
  EXPECT_TRUE(layout::has_perfect_matching(
      problem_of(6, 0, {{0, 1}, {1, 2}, {2, 0}, {2, 3}, {3, 4}, {4, 5}, {0, 5}})));
  // Two odd cycles joined by one edge.
  EXPECT_TRUE(layout::has_perfect_matching(
      problem_of(6, 0, {{0, 1}, {1, 2}, {2, 0}, {3, 4}, {4, 5}, {5, 3}, {2, 3}})));
  // A star: the centre can take only one leaf.
  EXPECT_FALSE(layout::has_perfect_matching(problem_of(4, 0, {{0, 1}, {0, 2}, {0, 3}})));
}

TEST(P1, VirtualPortsMayStayFree) {
  // Ports 0, 1 matched together; virtual ports 2, 3 free.
  EXPECT_TRUE(layout::has_perfect_matching(problem_of(2, 2, {{0, 1}, {0, 2}})));
  // Two ports whose only edges go to the same virtual port: one of them stays unmatched.
  EXPECT_FALSE(layout::has_perfect_matching(problem_of(2, 1, {{0, 2}, {1, 2}})));
  // Each port to its own virtual port, three of them (odd count of nodes).
  EXPECT_TRUE(layout::has_perfect_matching(problem_of(3, 4, {{0, 3}, {1, 4}, {2, 5}})));
}

}  // namespace
}  // namespace tessera
