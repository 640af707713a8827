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

// Two pieces of one triangle of a subdivided surface, their sides on one of its edges at disjoint
// stretches (from the drawing of R9.3' on R2.1'): rounding put the collinear sides a hair off one
// line, which read as a crossing.
TEST(SelfIntersection, DisjointSidesOnOneLine) {
  EXPECT_FALSE(
      triangles_intersect({-3.1477898740010453, 1.3857889943490682, -0.43035719124587868},
                          {-3.1632263381659813, 1.3184406056872626, -0.268727554860764},
                          {-3.1894745628790666, 1.3472916638671864, -0.26041937008264565},
                          {-3.1320152192798854, 1.3216025796238371, -0.34826017304403956},
                          {-3.1193988457188291, 1.2702670797328535, -0.28259999421972026},
                          {-3.1516940416948422, 1.3057647405545207, -0.27237779982192145}));
}

// A sliver and a small triangle on the two sides of a nearly flat fold (planes 7e-7 rad apart;
// from R5.8 on R2.4): apart, though their planes' common line is too ill conditioned to tell.
TEST(SelfIntersection, NeighboursAcrossANearlyFlatFold) {
  EXPECT_FALSE(
      triangles_intersect({-0.90489373221604164, 0.58084335411569221, 1.6157724804901714},
                          {-0.92198114655140206, 0.59603216899118239, 1.8114581744668434},
                          {-0.92204888868771517, 0.59612490501464421, 1.8117293500881844},
                          {-0.92200536063310623, 0.59605371733214707, 1.8117350899375124},
                          {-0.92138992544267528, 0.59522281313684966, 1.8090914827704412},
                          {-0.92162243704570523, 0.59542746736518859, 1.8117855843534845}));
  // Nearly parallel triangles that do overlap are still found.
  EXPECT_TRUE(triangles_intersect({0, 0, 0}, {1, 0, 0}, {0, 1, 1e-7}, {0.2, 0.2, 0},
                                  {1.2, 0.2, 1e-7}, {0.2, 1.2, 0}));
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
