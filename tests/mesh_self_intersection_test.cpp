// Self-intersections: the triangle-triangle test on its cases, and the grid search on meshes that
// do and do not cross themselves.
#include <gtest/gtest.h>

#include <algorithm>

#include "mesh/self_intersection.h"
#include "mesh/shapes.h"

namespace tessera {
namespace {

using Eigen::Vector3d;

TEST(SelfIntersection, CrossingAndSeparateTriangles) {
  const Vector3d a(0, 0, 0), b(2, 0, 0), c(0, 2, 0);
  // Pierces abc's interior.
  EXPECT_TRUE(triangles_intersect(a, b, c, {0.5, 0.5, -1}, {0.5, 0.5, 1}, {3, 3, 1}));
  // Below abc.
  EXPECT_FALSE(triangles_intersect(a, b, c, {0.5, 0.5, -1}, {0.5, 0.6, -0.1}, {3, 3, -1}));
  // Crosses abc's plane outside abc.
  EXPECT_FALSE(triangles_intersect(a, b, c, {3, 3, -1}, {3, 3, 1}, {4, 3, 0}));
  // Touches abc at one point of its edge.
  EXPECT_TRUE(triangles_intersect(a, b, c, {1, 0, 0}, {1, -1, 1}, {1, -1, -1}));
}

TEST(SelfIntersection, CoplanarTriangles) {
  const Vector3d a(0, 0, 0), b(2, 0, 0), c(0, 2, 0);
  EXPECT_TRUE(triangles_intersect(a, b, c, {0.5, 0.5, 0}, {3, 0.5, 0}, {0.5, 3, 0}));
  EXPECT_TRUE(triangles_intersect(a, b, c, {0.2, 0.2, 0}, {0.4, 0.2, 0}, {0.2, 0.4, 0}));
  EXPECT_FALSE(triangles_intersect(a, b, c, {3, 3, 0}, {4, 3, 0}, {3, 4, 0}));
}

// Two faces of one cylinder, far apart along it, lie in one plane up to rounding: not crossing.
TEST(SelfIntersection, NearlyCoplanarDistantTriangles) {
  EXPECT_FALSE(triangles_intersect({1.839, 0.070, 0.473}, {1.839, 0.070, 0.240},
                                   {1.790, 0.049, 0.240}, {1.839, 0.070, -0.707},
                                   {1.790, 0.049, -0.707}, {1.790, 0.049, -0.473}));
  EXPECT_TRUE(triangles_intersect({1.839, 0.070, 0.473}, {1.839, 0.070, -0.240},
                                  {1.790, 0.049, 0.240}, {1.839, 0.070, -0.107},
                                  {1.790, 0.049, -0.707}, {1.790, 0.049, 0.473}));
}

TEST(SelfIntersection, ClosedSurfacesDoNotCrossThemselves) {
  EXPECT_EQ(find_self_intersections(icosphere(3)).triangle_pairs, 0u);
  EXPECT_EQ(find_self_intersections(torus(2.0, 0.5, 48, 24)).triangle_pairs, 0u);
}

// Two spheres that overlap cross along a circle; only faces near it are involved.
TEST(SelfIntersection, OverlappingSpheresCross) {
  Mesh mesh = icosphere(3);
  const Mesh other = icosphere(3);
  const auto offset = static_cast<Index>(mesh.vertex_count());
  for (const Vector3d& p : other.positions) mesh.add_vertex(p + Vector3d(1.0, 0.0, 0.0));
  for (std::size_t f = 0; f < other.face_count(); ++f) {
    const auto face = other.face(f);
    mesh.add_face({face[0] + offset, face[1] + offset, face[2] + offset});
  }
  const SelfIntersections found = find_self_intersections(mesh);
  EXPECT_GT(found.triangle_pairs, 0u);
  EXPECT_FALSE(found.faces.empty());
  EXPECT_LT(found.faces.size(), mesh.face_count() / 2);
  EXPECT_TRUE(std::is_sorted(found.faces.begin(), found.faces.end()));
}

}  // namespace
}  // namespace tessera
