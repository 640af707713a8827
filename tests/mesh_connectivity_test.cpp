#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "base/error.h"
#include "mesh/connectivity.h"
#include "mesh/geometry.h"
#include "mesh/topology.h"

namespace tessera {
namespace {

Mesh tetrahedron() {
  return triangle_mesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
                       {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}});
}

// Two triangles forming the unit square: one boundary loop of four halfedges.
Mesh square() {
  return triangle_mesh({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{0, 1, 2}, {0, 2, 3}});
}

TEST(Connectivity, ClosedTetrahedronHasTwinsEverywhere) {
  const Mesh mesh = tetrahedron();
  const Connectivity c = build_connectivity(mesh);
  EXPECT_EQ(c.halfedge_count(), 12u);
  EXPECT_EQ(c.edge_count(), 6u);
  for (Index h = 0; h < c.halfedge_count(); ++h) {
    EXPECT_EQ(c.twin[c.twin[h]], h);
    EXPECT_EQ(c.prev[c.next[h]], h);
    EXPECT_EQ(c.from_vertex(c.twin[h]), c.to_vertex[h]);
    EXPECT_EQ(c.from_vertex(h), mesh.face_vertices[h]);  // halfedge h is corner h
    EXPECT_FALSE(c.is_boundary_halfedge(h));
  }
  for (Index v = 0; v < 4; ++v) EXPECT_EQ(outgoing_halfedges(c, v).size(), 3u);
}

TEST(Connectivity, SquareHasOneBoundaryLoop) {
  const Mesh mesh = square();
  const Connectivity c = build_connectivity(mesh);
  EXPECT_EQ(c.edge_count(), 5u);
  EXPECT_EQ(c.halfedge_count(), 10u);
  const auto loops = boundary_loops(c);
  ASSERT_EQ(loops.size(), 1u);
  EXPECT_EQ(loops[0].size(), 4u);
  for (Index v = 0; v < 4; ++v) EXPECT_TRUE(c.is_boundary_vertex(v));
  // Rotation around vertex 0 starts at its boundary halfedge and meets all three edges.
  EXPECT_EQ(outgoing_halfedges(c, 0).size(), 3u);
}

TEST(Connectivity, RejectsEdgeWithThreeFaces) {
  const Mesh mesh = triangle_mesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}},
                                  {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}});
  try {
    build_connectivity(mesh);
    FAIL() << "expected a TopologyError";
  } catch (const TopologyError& e) {
    EXPECT_NE(std::string(e.what()).find("edge 0-1"), std::string::npos) << e.what();
  }
}

TEST(Connectivity, RejectsBowtieVertex) {
  // Two triangles touching only at vertex 0.
  const Mesh mesh = triangle_mesh({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {-1, 0, 0}, {-1, -1, 0}},
                                  {{0, 1, 2}, {0, 3, 4}});
  try {
    build_connectivity(mesh);
    FAIL() << "expected a TopologyError";
  } catch (const TopologyError& e) {
    EXPECT_NE(std::string(e.what()).find("vertex 0"), std::string::npos) << e.what();
  }
}

TEST(Connectivity, RejectsTwoClosedSheetsSharingAVertex) {
  // Two tetrahedra glued at one vertex: every edge is manifold, vertex 0 has two closed fans.
  Mesh mesh = tetrahedron();
  for (const Eigen::Vector3d p :
       {Eigen::Vector3d(-1, 0, 0), Eigen::Vector3d(0, -1, 0), Eigen::Vector3d(0, 0, -1)})
    mesh.add_vertex(p);
  for (const auto& t :
       std::vector<std::array<Index, 3>>{{0, 5, 4}, {0, 4, 6}, {4, 5, 6}, {0, 6, 5}})
    mesh.add_face(t);
  EXPECT_THROW(build_connectivity(mesh), TopologyError);
}

TEST(Connectivity, RejectsInconsistentOrientation) {
  const Mesh mesh =
      triangle_mesh({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{0, 1, 2}, {0, 3, 2}});
  EXPECT_THROW(build_connectivity(mesh), TopologyError);
}

TEST(Connectivity, RejectsOutOfRangeIndexWithoutCrashing) {
  const Mesh mesh = triangle_mesh({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}}, {{0, 1, 7}});
  EXPECT_THROW(build_connectivity(mesh), TopologyError);
}

TEST(Topology, TetrahedronIsASphere) {
  const Mesh mesh = tetrahedron();
  const SurfaceTopology t = surface_topology(mesh, build_connectivity(mesh));
  EXPECT_EQ(t.vertices, 4u);
  EXPECT_EQ(t.edges, 6u);
  EXPECT_EQ(t.faces, 4u);
  EXPECT_EQ(t.euler_characteristic, 2);
  EXPECT_EQ(t.genus, 0);
  EXPECT_EQ(t.boundary_loops, 0u);
  EXPECT_EQ(t.components, 1u);
}

TEST(Topology, SquareIsADisk) {
  const Mesh mesh = square();
  const SurfaceTopology t = surface_topology(mesh, build_connectivity(mesh));
  EXPECT_EQ(t.euler_characteristic, 1);
  EXPECT_EQ(t.boundary_loops, 1u);
  EXPECT_EQ(t.genus, 0);
}

TEST(Topology, ComponentsAreCountedSeparately) {
  Mesh mesh = square();
  for (const Eigen::Vector3d p :
       {Eigen::Vector3d(5, 0, 0), Eigen::Vector3d(6, 0, 0), Eigen::Vector3d(5, 1, 0)})
    mesh.add_vertex(p);
  mesh.add_face({4, 5, 6});
  const Connectivity c = build_connectivity(mesh);
  const Components components = connected_components(mesh, c);
  EXPECT_EQ(components.count, 2u);
  EXPECT_EQ(components.face_component[2], 1u);
  const SurfaceTopology t = surface_topology(mesh, c);
  EXPECT_EQ(t.components, 2u);
  EXPECT_EQ(t.boundary_loops, 2u);
  EXPECT_EQ(t.euler_characteristic, 2);
}

TEST(Geometry, AreasNormalsAndDihedralAngles) {
  const Mesh mesh = tetrahedron();
  EXPECT_DOUBLE_EQ(face_area(mesh, 0), 0.5);
  EXPECT_TRUE(face_normal(mesh, 0).isApprox(Eigen::Vector3d(0, 0, -1)));
  const Connectivity c = build_connectivity(mesh);
  const auto angles = dihedral_angles(mesh, c);
  // The edges at the right-angled corner bend by 90 degrees; all edges are convex.
  for (Index e = 0; e < c.edge_count(); ++e) EXPECT_GT(angles[e], 0.0);
  const Index h = mesh.face_offsets[0];  // edge 0-2, between the faces z=0 and x=0
  EXPECT_NEAR(angles[c.edge[h]], std::numbers::pi / 2, 1e-12);
  EXPECT_NEAR(bounding_box(mesh).diagonal(), std::sqrt(3.0), 1e-15);
}

TEST(Geometry, QuadAreaAndFlatSquareHasZeroDihedral) {
  Mesh quad;
  for (const Eigen::Vector3d p : {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(2, 0, 0),
                                  Eigen::Vector3d(2, 3, 0), Eigen::Vector3d(0, 3, 0)})
    quad.add_vertex(p);
  quad.add_face({0, 1, 2, 3});
  EXPECT_DOUBLE_EQ(face_area(quad, 0), 6.0);
  const Mesh flat = square();
  const auto angles = dihedral_angles(flat, build_connectivity(flat));
  for (double a : angles) EXPECT_DOUBLE_EQ(a, 0.0);
}

}  // namespace
}  // namespace tessera
