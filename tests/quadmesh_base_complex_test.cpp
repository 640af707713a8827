// The trivial base complex B of quad meshes built in code (thesis Sec. 7.2) and the input checks.
#include <gtest/gtest.h>

#include <cmath>
#include <utility>

#include "base/error.h"
#include "mesh/connectivity.h"
#include "mesh/shapes.h"
#include "param/poisson.h"
#include "quadmesh/base_complex.h"
#include "quadmesh/integer_charts.h"
#include "quadmesh/quad_input.h"
#include "quadmesh_test_util.h"

namespace tessera {
namespace {

using quadmesh::BaseComplex;
using quadmesh::trivial_base_complex;

BaseComplex base_of(const Mesh& quads) {
  return trivial_base_complex(quads, build_connectivity(quads));
}

TEST(QuadmeshBaseComplex, FlatGridIsOnePatchBoundedByItsCorners) {
  const Mesh grid = test::flat_quad_grid(5, 3);
  const BaseComplex b = base_of(grid);
  // The four corners are irregular (one quad, Sec. 7.2) but have no interior edge: no line.
  EXPECT_EQ(quadmesh::irregular_vertices(grid, build_connectivity(grid)).size(), 4u);
  EXPECT_TRUE(b.lines.empty());
  EXPECT_EQ(b.patch_count, 1u);
  EXPECT_TRUE(b.check.valid());
}

TEST(QuadmeshBaseComplex, RotatedEdgeInAGridTracesItsLinesToTheBoundary) {
  Mesh grid = test::flat_quad_grid(8, 8);
  // Vertices (4, 4) and (5, 4): the edge between them is shared by quads (4, 3) and (4, 4).
  test::rotate_quad_edge(grid, 4 * 9 + 4, 5 * 9 + 4);
  const Connectivity c = build_connectivity(grid);
  const std::vector<Singularity> irregular = quadmesh::irregular_vertices(grid, c);
  ASSERT_EQ(irregular.size(), 8u);  // two of valence 3, two of valence 5, four corners
  const BaseComplex b = trivial_base_complex(grid, c);
  std::size_t to_boundary = 0;
  for (const quadmesh::BaseLine& line : b.lines)
    to_boundary += line.end == quadmesh::LineEnd::boundary;
  EXPECT_EQ(b.lines.size(), 3u + 3u + 5u + 5u);
  EXPECT_TRUE(b.check.valid()) << (b.check.problems.empty() ? "" : b.check.problems[0]);
  // Three separatrices join the planted vertices (traced from both ends), ten reach the boundary.
  EXPECT_EQ(to_boundary, 10u);
  EXPECT_EQ(b.patch_count, 12u);
}

TEST(QuadmeshBaseComplex, TorusWithRotatedEdge) {
  Mesh torus = quad_torus(3, 1, 24, 12);
  test::rotate_quad_edge(torus, 5 * 12 + 4, 6 * 12 + 4);
  const BaseComplex b = base_of(torus);
  EXPECT_TRUE(b.check.valid()) << (b.check.problems.empty() ? "" : b.check.problems[0]);
  EXPECT_EQ(b.lines.size(), 16u);
  EXPECT_EQ(b.patch_count, 6u);
}

// The indices (4 - valence) / 4 inside and (2 - valence) / 4 on the boundary sum to the Euler
// characteristic (Poincare-Hopf in the integer metric, Sec. 7.2).
TEST(QuadmeshBaseComplex, IrregularVerticesSumToTheEulerCharacteristic) {
  Mesh grid = test::flat_quad_grid(8, 8);
  test::rotate_quad_edge(grid, 4 * 9 + 4, 5 * 9 + 4);
  Mesh torus = quad_torus(3, 1, 24, 12);
  test::rotate_quad_edge(torus, 5 * 12 + 4, 6 * 12 + 4);
  for (const auto& [mesh, chi] : {std::pair{grid, 1.0}, std::pair{torus, 0.0}}) {
    double sum = 0;
    for (const Singularity& s : quadmesh::irregular_vertices(mesh, build_connectivity(mesh)))
      sum += s.index;
    EXPECT_DOUBLE_EQ(sum, chi);
  }
}

// Every transition of the integer charts maps the shared edge onto itself with an integer
// translation (Sec. 7.1: the charts are unit squares, the metric counts edges).
TEST(QuadmeshBaseComplex, IntegerChartsAgreeAcrossEveryEdge) {
  Mesh torus = quad_torus(3, 1, 24, 12);
  test::rotate_quad_edge(torus, 5 * 12 + 4, 6 * 12 + 4);
  const quadmesh::IntegerCharts charts = quadmesh::integer_charts(torus, build_connectivity(torus));
  const Connectivity& c = charts.connectivity;
  const SeamlessParam& p = charts.param;
  for (Index h = 0; h < c.corner_count; ++h) {
    const Index t = c.twin[h];
    const Eigen::Vector2d& t_h = p.translation[h];
    EXPECT_EQ(t_h.x(), std::round(t_h.x()));
    EXPECT_EQ(t_h.y(), std::round(t_h.y()));
    // uv in face(t) = J^r uv in face(h) + t_h, at both ends of the edge.
    const auto image = [&](Index corner) -> Eigen::Vector2d {
      return quarter_turns(p.uv[corner], p.rotation[h]) + t_h;
    };
    EXPECT_LT((image(h) - p.uv[c.next[t]]).norm(), 1e-12);
    EXPECT_LT((image(c.next[h]) - p.uv[t]).norm(), 1e-12);
  }
  EXPECT_EQ(p.singularities.size(), 4u);
}

TEST(QuadmeshInput, TrianglesAreCountedAndNamed) {
  Mesh mesh = test::flat_quad_grid(2, 2);
  mesh.add_vertex({3, 0, 0});
  mesh.add_face({6, 9, 7});
  try {
    quadmesh::require_quad_mesh(mesh, "m.obj");
    FAIL() << "no error";
  } catch (const TopologyError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("m.obj: 1 of 5 faces are not quads (1 triangles"), std::string::npos)
        << message;
    EXPECT_NE(message.find("face 4 (3 corners"), std::string::npos) << message;
    EXPECT_NE(message.find("--split"), std::string::npos) << message;
  }
  const Mesh split = quadmesh::split_into_quads(mesh);
  EXPECT_NO_THROW(quadmesh::require_quad_mesh(split, "split"));
  EXPECT_EQ(split.face_count(), 4u * 4u + 3u);
}

}  // namespace
}  // namespace tessera
