// Tracing through the charts (core/layout/trace.h, ports.h): on a flat grid with every face's chart
// turned and shifted at random, lines along grid edges and through grid vertices are traced with
// the exact counts of vertex passes, the face on the line's left, and the exact length.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <set>

#include "layout/ports.h"
#include "layout/trace.h"
#include "layout_test_util.h"
#include "mesh/shapes.h"

namespace tessera {
namespace {

using layout::Charts;

constexpr int kGrid = 6;
Index grid_vertex(int i, int j) {
  return Index(j * (kGrid + 1) + i);
}

struct Trace {
  double length = 0;
  std::vector<Index> vertices;  // the vertices passed, each once, in order
  std::vector<Index> faces;     // every face entered
  Index last_vertex = kNoIndex;
};

Trace trace_to_boundary(const Charts& charts, layout::LineCursor cursor) {
  Trace trace;
  for (int steps = 0; steps < 1000; ++steps) {
    trace.faces.push_back(cursor.face);
    const layout::LineStep step = layout::line_step(charts, cursor);
    EXPECT_TRUE(step.valid);
    if (step.vertex != kNoIndex && (trace.vertices.empty() || trace.vertices.back() != step.vertex))
      trace.vertices.push_back(step.vertex);
    trace.length = cursor.length + step.length;
    if (!layout::cross_edge(charts, step, cursor)) return trace;
  }
  ADD_FAILURE() << "the line did not reach the boundary";
  return trace;
}

class FlatGridTrace : public ::testing::TestWithParam<unsigned> {};

// The four ports of a regular vertex run along the grid lines; each passes every grid vertex on its
// way, inside the faces on its left, and leaves at the boundary after the exact distance.
TEST_P(FlatGridTrace, PortsRunAlongGridLinesThroughEveryVertex) {
  const Index start = grid_vertex(1, 2);
  const test::Parameterized p =
      test::flat_parameterized(test::flat_grid(kGrid), GetParam(), {start});
  const Charts charts = p.charts();
  const layout::Ports ports = layout::find_ports(charts);
  ASSERT_EQ(ports.ports.size(), 4u);
  std::set<std::pair<int, int>> seen;
  for (const layout::Port& port : ports.ports) {
    ASSERT_NE(port.corner, kNoIndex);
    const Eigen::Vector2d w =
        test::world_direction(p, p.connectivity.face[port.corner], port.direction);
    const int dx = int(std::lround(w.x())), dy = int(std::lround(w.y()));
    seen.insert({dx, dy});
    const Trace trace =
        trace_to_boundary(charts, layout::cursor_at_corner(charts, port.corner, port.direction));
    // From (1, 2) to the boundary along (dx, dy): every grid vertex on the way, the last one on the
    // boundary.
    const int steps = dx > 0 ? kGrid - 1 : dx < 0 ? 1 : dy > 0 ? kGrid - 2 : 2;
    EXPECT_NEAR(trace.length, steps, 1e-12);
    ASSERT_EQ(trace.vertices.size(), std::size_t(steps));
    for (int k = 1; k <= steps; ++k)
      EXPECT_EQ(trace.vertices[k - 1], grid_vertex(1 + k * dx, 2 + k * dy));
    // The symbolic shift to the left: every face entered lies on the line's left.
    for (Index f : trace.faces) {
      Eigen::Vector3d centre = Eigen::Vector3d::Zero();
      for (Index v : p.mesh.face(f)) centre += p.mesh.positions[v] / 3;
      const Eigen::Vector2d offset(centre.x() - 1, centre.y() - 2);
      EXPECT_GT(dx * offset.y() - dy * offset.x(), 0) << "face " << f;
    }
  }
  EXPECT_EQ(seen.size(), 4u);
}

// A line along the cell diagonals passes the vertices (k, k) and runs along diagonal edges.
TEST_P(FlatGridTrace, DiagonalLineRunsAlongDiagonalEdges) {
  const Index start = grid_vertex(0, 0);
  const test::Parameterized p = test::flat_parameterized(test::flat_grid(kGrid), GetParam(), {});
  const Charts charts = p.charts();
  Index inside = kNoIndex;
  for (Index h : outgoing_halfedges(p.connectivity, start))
    if (!p.connectivity.is_boundary_halfedge(h)) inside = h;
  ASSERT_NE(inside, kNoIndex);
  // The direction (1, 1) in the chart of face(inside).
  const Eigen::Vector2d world(1 / std::sqrt(2.0), 1 / std::sqrt(2.0));
  const Eigen::Vector2d back = test::world_direction(p, p.connectivity.face[inside], {1, 0});
  const double turn = -std::atan2(back.y(), back.x());
  const Eigen::Vector2d d(std::cos(turn) * world.x() - std::sin(turn) * world.y(),
                          std::sin(turn) * world.x() + std::cos(turn) * world.y());
  ASSERT_TRUE(layout::corner_contains(charts, inside, d));
  const Trace trace = trace_to_boundary(charts, layout::cursor_at_corner(charts, inside, d));
  EXPECT_NEAR(trace.length, kGrid * std::sqrt(2.0), 1e-9);
  ASSERT_EQ(trace.vertices.size(), std::size_t(kGrid));
  for (int k = 1; k <= kGrid; ++k) EXPECT_EQ(trace.vertices[k - 1], grid_vertex(k, k));
}

INSTANTIATE_TEST_SUITE_P(Charts, FlatGridTrace, ::testing::Values(0u, 1u, 2u, 3u, 4u));

TEST(Ports, ValenceManyPortsCounterclockwiseOnAShape) {
  const test::Parameterized p = test::parameterized(icosphere(2));
  const layout::Ports ports = layout::find_ports(p.charts());
  ASSERT_EQ(ports.points.size(), p.param.singularities.size());
  for (std::size_t s = 0; s < ports.points.size(); ++s) {
    const layout::SingularPoint& point = ports.points[s];
    EXPECT_EQ(int(point.ports.size()), point.valence);
    EXPECT_NEAR(point.ring.total, point.valence * std::numbers::pi / 2, 1e-9);
    for (std::size_t k = 0; k < point.ports.size(); ++k) {
      const layout::Port& port = ports.ports[point.ports[k]];
      EXPECT_EQ(port.number, int(k));
      EXPECT_NEAR(port.angle - ports.ports[point.ports[0]].angle, k * std::numbers::pi / 2, 1e-9);
      EXPECT_TRUE(layout::corner_contains(p.charts(), port.corner, port.direction));
      EXPECT_EQ(ports.neighbour(point.ports[k], 1), point.ports[(k + 1) % point.ports.size()]);
      EXPECT_EQ(ports.nearest_port(Index(s), port.angle + 0.3), point.ports[k]);
    }
  }
}

}  // namespace
}  // namespace tessera
