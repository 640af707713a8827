// Boundary tangents and corners (core/mesh/boundary_tangents.h) on generated boundaries: straight
// and evenly curved ones, staircases of a cut through triangles, and corners.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "layout_test_util.h"
#include "mesh/boundary_tangents.h"
#include "mesh/connectivity.h"
#include "mesh/shapes.h"

namespace tessera {
namespace {

std::size_t corner_count(const BoundaryTangents& b) {
  std::size_t n = 0;
  for (std::uint8_t x : b.corner) n += x;
  return n;
}

double degrees_between_lines(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::acos(std::min(1.0, std::abs(a.normalized().dot(b.normalized())))) * 180 /
         std::numbers::pi;
}

// The faces of the n x n grid below the line y = x * slope + offset: a staircase boundary.
Mesh grid_below(int n, double slope, double offset) {
  const Mesh grid = test::flat_grid(n);
  Mesh part;
  std::vector<Index> renumbered(grid.vertex_count(), kNoIndex);
  for (Index f = 0; f < grid.face_count(); ++f) {
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (Index v : grid.face(f)) centroid += grid.positions[v] / 3;
    if (centroid.y() > centroid.x() * slope + offset) continue;
    std::vector<Index> face;
    for (Index v : grid.face(f)) {
      if (renumbered[v] == kNoIndex) renumbered[v] = part.add_vertex(grid.positions[v]);
      face.push_back(renumbered[v]);
    }
    part.add_face(face);
  }
  return part;
}

TEST(BoundaryTangents, ASquareHasFourCornersAndItsSidesTangents) {
  const Mesh mesh = test::flat_grid(12);
  const Connectivity c = build_connectivity(mesh);
  const BoundaryTangents b = boundary_tangents(mesh, c);
  EXPECT_EQ(corner_count(b), 4u);
  for (Index v : {Index(0), Index(12), Index(13 * 12), Index(13 * 13 - 1)})
    EXPECT_TRUE(b.corner[v]);
  for (Index e = 0; e < c.edge_count(); ++e) {
    if (!c.is_boundary_edge(e)) {
      EXPECT_EQ(b.edge_tangent[e].norm(), 0.0);
      continue;
    }
    const Index h = c.edge_halfedge[e];
    const Eigen::Vector3d edge = mesh.positions[c.to_vertex[h]] - mesh.positions[c.from_vertex(h)];
    EXPECT_LT(degrees_between_lines(b.edge_tangent[e], edge), 1e-9);
  }
}

// A cut at 30 degrees through the grid's triangles: its boundary edges stand up to 60 degrees
// off the cut; the tangents follow the cut, and none of its steps is a corner.
TEST(BoundaryTangents, AStaircaseFollowsItsCutAndHasNoCorners) {
  const double slope = std::tan(std::numbers::pi / 6);
  const Mesh mesh = grid_below(30, slope, 9.37);
  const Connectivity c = build_connectivity(mesh);
  const BoundaryTangents b = boundary_tangents(mesh, c);
  const Eigen::Vector3d cut(1, slope, 0);
  std::size_t staircase_edges = 0;
  double worst_edge = 0;
  for (Index e = 0; e < c.edge_count(); ++e) {
    if (!c.is_boundary_edge(e)) continue;
    const Index h = c.edge_halfedge[e];
    const Eigen::Vector3d a = mesh.positions[c.to_vertex[h]], o = mesh.positions[c.from_vertex(h)];
    // The edges of the staircase, away from the square's sides and their corners.
    const auto on_staircase = [&](const Eigen::Vector3d& p) {
      return p.x() > 5 && p.x() < 25 && p.y() > 5 && p.y() < 29;
    };
    if (!on_staircase(a) || !on_staircase(o)) continue;
    ++staircase_edges;
    worst_edge = std::max(worst_edge, degrees_between_lines(a - o, cut));
    EXPECT_LT(degrees_between_lines(b.edge_tangent[e], cut), 12) << "edge " << e;
  }
  EXPECT_GT(staircase_edges, 20u);
  EXPECT_GT(worst_edge, 25);  // a staircase indeed
  // The square's corners (0, 0) and (30, 0) and where the cut leaves the square's sides.
  EXPECT_EQ(corner_count(b), 4u);
}

// The rim of an open cylinder of 8 segments turns 180 degrees in space between chords of 4 edges,
// but not at all on the surface (it is a geodesic): no corner.
TEST(BoundaryTangents, ACoarseCircleHasNoCorners) {
  const Mesh mesh = open_cylinder(1, 2, 8, 6);
  const Connectivity c = build_connectivity(mesh);
  EXPECT_EQ(corner_count(boundary_tangents(mesh, c)), 0u);
}

}  // namespace
}  // namespace tessera
