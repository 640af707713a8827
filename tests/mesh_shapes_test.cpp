#include <gtest/gtest.h>

#include "mesh/connectivity.h"
#include "mesh/geometry.h"
#include "mesh/shapes.h"
#include "mesh/topology.h"
#include "mesh/validate.h"

namespace tessera {
namespace {

struct Expected {
  long genus;
  std::size_t boundary_loops;
};

// The shape passes validation untouched and has the stated topology.
void expect_clean_surface(Mesh mesh, Expected expected) {
  const std::size_t vertices = mesh.vertex_count();
  const std::size_t faces = mesh.face_count();
  const ValidationReport report = validate_mesh(mesh);
  EXPECT_TRUE(report.warnings.empty()) << report.warnings.front();
  EXPECT_EQ(mesh.vertex_count(), vertices);
  EXPECT_EQ(mesh.face_count(), faces);
  const SurfaceTopology t = surface_topology(mesh, build_connectivity(mesh));
  EXPECT_EQ(t.components, 1u);
  EXPECT_EQ(t.genus, expected.genus);
  EXPECT_EQ(t.boundary_loops, expected.boundary_loops);
  EXPECT_EQ(t.euler_characteristic,
            2 - 2 * expected.genus - static_cast<long>(expected.boundary_loops));
}

// Positive for a closed surface whose faces are counterclockwise seen from outside.
double signed_volume(const Mesh& mesh) {
  double volume = 0;
  for (Index f = 0; f < mesh.face_count(); ++f)
    volume += mesh.positions[mesh.face(f)[0]].dot(face_vector_area(mesh, f)) / 3;
  return volume;
}

TEST(Shapes, IcosphereIsAnOutwardSphere) {
  const Mesh mesh = icosphere(2);
  EXPECT_EQ(mesh.face_count(), 320u);
  EXPECT_EQ(mesh.vertex_count(), 162u);
  expect_clean_surface(mesh, {0, 0});
  EXPECT_NEAR(signed_volume(icosphere(4)), 4.0 / 3.0 * M_PI, 0.02);
}

TEST(Shapes, TorusHasGenusOne) {
  expect_clean_surface(torus(1.0, 0.3, 24, 12), {1, 0});
  const Mesh quads = quad_torus(1.0, 0.3, 24, 12);
  EXPECT_EQ(quads.corner_count(), 4 * quads.face_count());
  expect_clean_surface(quads, {1, 0});
  EXPECT_GT(signed_volume(quads), 0.0);
}

TEST(Shapes, DoubleTorusHasGenusTwo) {
  for (int resolution : {1, 2, 4}) {
    const Mesh mesh = double_torus(resolution);
    expect_clean_surface(mesh, {2, 0});
    EXPECT_GT(signed_volume(mesh), 0.0);
  }
}

TEST(Shapes, MechanicalPartHasSharpEdgesAndGenusTwo) {
  const Mesh mesh = mechanical_part(2);
  expect_clean_surface(mesh, {2, 0});
  EXPECT_GT(signed_volume(mesh), 0.0);
  // The bracket's volume in unit cubes: 8x6x2 base + 2x6x6 upright - 2x2x2 - 2x2x2 holes.
  EXPECT_NEAR(signed_volume(mesh), 96 + 72 - 8 - 8, 1e-9);
  const Connectivity c = build_connectivity(mesh);
  std::size_t sharp = 0;
  for (double angle : dihedral_angles(mesh, c)) sharp += std::abs(angle) > 1.5;
  EXPECT_GT(sharp, 0u);
}

TEST(Shapes, OpenCylinderHasTwoBoundaryLoops) {
  expect_clean_surface(open_cylinder(1, 2, 16, 4), {0, 2});
}

TEST(Shapes, AreDeterministic) {
  const Mesh a = double_torus(3), b = double_torus(3);
  EXPECT_EQ(a.face_vertices, b.face_vertices);
  EXPECT_EQ(a.positions, b.positions);
}

}  // namespace
}  // namespace tessera
