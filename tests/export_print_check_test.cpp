// The print check: scale, watertightness, orientation, self-intersections and the thinnest wall on
// generated surfaces whose thickness is known.
#include <gtest/gtest.h>

#include <algorithm>

#include "base/error.h"
#include "export/print_check.h"
#include "mesh/geometry.h"
#include "mesh/shapes.h"

namespace tessera {
namespace {

Mesh reversed(Mesh mesh) {
  for (std::size_t f = 0; f < mesh.face_count(); ++f)
    std::reverse(mesh.face_vertices.begin() + mesh.face_offsets[f] + 1,
                 mesh.face_vertices.begin() + mesh.face_offsets[f + 1]);
  return mesh;
}

TEST(PrintCheck, TorusTubeIsItsDiameterThick) {
  // Largest side 2 (3 + 0.5) = 7 model units at 70 mm: 10 mm per unit, the tube 10 mm across.
  const Mesh torus = tessera::torus(3.0, 0.5, 96, 32);
  const PrintCheck check = check_print(torus, {70.0, 2.0});
  EXPECT_NEAR(check.scale, 10.0, 1e-9);
  EXPECT_NEAR(check.extent_mm.maxCoeff(), 70.0, 1e-9);
  EXPECT_NEAR(check.extent_mm.minCoeff(), 10.0, 1e-6);
  EXPECT_TRUE(check.closed);
  EXPECT_TRUE(check.oriented);
  EXPECT_EQ(check.self_intersections, 0u);
  EXPECT_NEAR(check.thinnest_mm, 10.0, 0.1);  // the polygonal tube is a little thinner
  EXPECT_LE(check.thinnest_mm, 10.0);
  EXPECT_EQ(check.thin_vertices, 0u);
  EXPECT_TRUE(check.printable());
  EXPECT_TRUE(check.problems().empty());
}

TEST(PrintCheck, WallThickerThanTheTubeSaysHowLargeToPrint) {
  const Mesh torus = tessera::torus(3.0, 0.5, 96, 32);
  const PrintCheck check = check_print(torus, {35.0, 6.0});  // the tube is 5 mm across
  EXPECT_FALSE(check.printable());
  EXPECT_EQ(check.thin_vertices, torus.vertex_count());
  ASSERT_EQ(check.problems().size(), 1u);
  const std::string problem = check.problems()[0];
  EXPECT_NE(problem.find("thinner than the 6 mm wall"), std::string::npos) << problem;
  EXPECT_NE(problem.find("at least 42"), std::string::npos) << problem;  // 35 x 6 / 5
}

TEST(PrintCheck, InwardFacesAreTurnedAndTheSolidRestsOnThePlate) {
  const Mesh sphere = reversed(icosphere(3, 2.0));
  const PrintCheck check = check_print(sphere, {40.0, 1.0});
  EXPECT_TRUE(check.inward);
  EXPECT_NEAR(check.thinnest_mm, 40.0, 1.0);  // through the centre: the diameter
  const Mesh printed = print_mesh(sphere, check);
  const BoundingBox box = bounding_box(printed);
  EXPECT_NEAR(box.min.z(), 0.0, 1e-9);
  EXPECT_NEAR(box.max.z(), 40.0, 1e-9);
  EXPECT_NEAR(box.min.x() + box.max.x(), 0.0, 1e-9);
  EXPECT_FALSE(check_print(printed, {40.0, 1.0}).inward);
}

TEST(PrintCheck, OpenAndCrossingSurfacesAreNotPrintable) {
  const PrintCheck open = check_print(open_cylinder(1.0, 2.0, 24, 4), {50.0, 1.0});
  EXPECT_FALSE(open.closed);
  EXPECT_FALSE(open.printable());
  EXPECT_NE(open.problems()[0].find("holes"), std::string::npos);

  Mesh two = icosphere(2, 1.0);
  const Mesh other = icosphere(2, 1.0);
  const Index offset = two.vertex_count();
  for (Eigen::Vector3d p : other.positions) two.positions.push_back(p + Eigen::Vector3d(1, 0, 0));
  for (std::size_t f = 0; f < other.face_count(); ++f) {
    std::vector<Index> face;
    for (Index v : other.face(f)) face.push_back(v + offset);
    two.add_face(face);
  }
  const PrintCheck crossing = check_print(two, {50.0, 1.0});
  EXPECT_TRUE(crossing.closed);
  EXPECT_GT(crossing.self_intersections, 0u);
  EXPECT_FALSE(crossing.printable());
}

TEST(PrintCheck, SizesThatAreNotLengthsAreRefused) {
  const Mesh sphere = icosphere(1);
  EXPECT_THROW(check_print(sphere, {0.0, 1.0}), InputError);
  EXPECT_THROW(check_print(sphere, {std::nan(""), 1.0}), InputError);
  EXPECT_THROW(check_print(sphere, {1e9, 1.0}), InputError);
  EXPECT_THROW(check_print(sphere, {50.0, -1.0}), InputError);
  EXPECT_THROW(check_print(sphere, {50.0, 60.0}), InputError);
}

}  // namespace
}  // namespace tessera
