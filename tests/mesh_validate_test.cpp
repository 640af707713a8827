#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "base/error.h"
#include "mesh/connectivity.h"
#include "mesh/shapes.h"
#include "mesh/topology.h"
#include "mesh/validate.h"
#include "mesh_test_util.h"

namespace tessera {
namespace {

using test::joined;
using test::torus_cracked_at_seam;

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// Runs validate_mesh() expecting error type E whose message contains `part`.
template <class E>
void expect_refused(Mesh mesh, const std::string& part) {
  try {
    validate_mesh(mesh);
    FAIL() << "expected an error mentioning '" << part << "'";
  } catch (const E& e) {
    EXPECT_TRUE(contains(e.what(), part)) << e.what();
  }
}

std::string all_warnings(const ValidationReport& report) {
  std::string text;
  for (const auto& w : report.warnings) text += w + "\n";
  return text;
}

// The unit square as two triangles, each with its own copy of the shared diagonal's vertices.
Mesh square_with_split_diagonal(double offset) {
  return triangle_mesh({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 0, offset}, {1, 1, offset}, {0, 1, 0}},
                       {{0, 1, 2}, {3, 4, 5}});
}

TEST(Validate, WeldsNearDuplicatesAndReportsThem) {
  Mesh mesh = square_with_split_diagonal(1e-9);
  const ValidationReport report = validate_mesh(mesh);
  EXPECT_EQ(report.welded_vertices, 2u);
  EXPECT_EQ(mesh.vertex_count(), 4u);
  EXPECT_TRUE(contains(all_warnings(report), "2 duplicate vertices welded"))
      << all_warnings(report);
  EXPECT_EQ(surface_topology(mesh, build_connectivity(mesh)).boundary_loops, 1u);
}

TEST(Validate, KeepsVerticesFartherThanTheTolerance) {
  Mesh mesh = square_with_split_diagonal(1e-3);
  EXPECT_EQ(validate_mesh(mesh).welded_vertices, 0u);
  EXPECT_EQ(mesh.vertex_count(), 6u);
  Mesh exact_only = square_with_split_diagonal(1e-9);
  EXPECT_EQ(validate_mesh(exact_only, {.weld_tolerance = 0}).welded_vertices, 0u);
}

TEST(Validate, DropsDegenerateFacesAndCollapsesRepeatedCorners) {
  Mesh mesh = icosphere(1);
  mesh.add_face({0, 0, 1});
  mesh.add_face({2, 3, 2});
  mesh.face_attributes["patch"] = std::vector<std::int32_t>(mesh.face_count(), 7);
  const std::size_t real_faces = mesh.face_count() - 2;
  const ValidationReport report = validate_mesh(mesh);
  EXPECT_EQ(report.dropped_faces, 2u);
  EXPECT_EQ(mesh.face_count(), real_faces);
  EXPECT_EQ(mesh.face_attributes["patch"].size(), real_faces);

  Mesh quad;
  for (const Eigen::Vector3d p :
       {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0)})
    quad.add_vertex(p);
  quad.add_face({0, 1, 1, 2});
  EXPECT_EQ(validate_mesh(quad).collapsed_faces, 1u);
  EXPECT_EQ(quad.face_size(0), 3u);
}

TEST(Validate, RemovesUnreferencedVertices) {
  Mesh mesh = icosphere(0);
  mesh.add_vertex({5, 5, 5});
  const ValidationReport report = validate_mesh(mesh);
  EXPECT_EQ(report.unreferenced_vertices, 1u);
  EXPECT_EQ(mesh.vertex_count(), 12u);
}

TEST(Validate, ReportsZeroAreaFacesAndRefusesAMeshOfOnlyThose) {
  Mesh mesh = triangle_mesh({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {2, 0, 0}}, {{0, 1, 2}, {0, 3, 1}});
  const ValidationReport report = validate_mesh(mesh);
  EXPECT_EQ(report.zero_area_faces, 1u);
  EXPECT_TRUE(contains(all_warnings(report), "face 1 (vertices 0 3 1)")) << all_warnings(report);
  expect_refused<GeometryError>(triangle_mesh({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}, {{0, 1, 2}}),
                                "zero area");
}

TEST(Validate, RefusesNonFiniteCoordinates) {
  Mesh mesh = icosphere(0);
  mesh.positions[5].y() = std::numeric_limits<double>::quiet_NaN();
  expect_refused<GeometryError>(mesh, "vertex 5");
  mesh.positions[5].y() = std::numeric_limits<double>::infinity();
  expect_refused<GeometryError>(mesh, "vertex 5");
}

TEST(Validate, RefusesIndicesOutOfRangeAndEmptyMeshes) {
  expect_refused<TopologyError>(triangle_mesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 3}}),
                                "face 0 refers to vertex 3");
  expect_refused<TopologyError>(triangle_mesh({{0, 0, 0}}, {}), "no faces");
}

TEST(Validate, RefusesNonManifoldEdgeNamingIt) {
  // Three triangles on the edge 0-1.
  Mesh mesh = triangle_mesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}},
                            {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}});
  expect_refused<TopologyError>(mesh, "edge 0-1");
  expect_refused<TopologyError>(mesh, "shared by 3 faces");
}

TEST(Validate, RefusesNonManifoldVertexNamingIt) {
  // Two cones (closed tetrahedra) sharing only vertex 0.
  Mesh mesh = triangle_mesh(
      {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-1, 0, 0}, {0, -1, 0}, {0, 0, -1}},
      {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}, {0, 5, 4}, {0, 4, 6}, {4, 5, 6}, {0, 6, 5}});
  expect_refused<TopologyError>(mesh, "vertex 0");
  // Two triangles touching at a vertex: a pinched boundary.
  expect_refused<TopologyError>(
      triangle_mesh({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {-1, 0, 0}, {-1, -1, 0}},
                    {{0, 1, 2}, {0, 3, 4}}),
      "vertex 0");
}

// Validated without welding and with the default weld, `mesh` must load both ways (a repair never
// makes a valid mesh invalid); returns the default's report, and the welded mesh in `mesh`.
ValidationReport expect_loads_with_and_without_welding(Mesh& mesh) {
  Mesh unwelded = mesh;
  EXPECT_NO_THROW(validate_mesh(unwelded, {.weld_tolerance = -1}));
  ValidationReport report;
  try {
    report = validate_mesh(mesh);
  } catch (const Error& e) {
    ADD_FAILURE() << "refused with the default weld: " << e.what();
  }
  return report;
}

TEST(Validate, KeepsApartAWeldThatWouldPinchTwoSheets) {
  // Two triangles whose tips nearly touch: welded, they would pinch at one vertex.
  Mesh mesh =
      triangle_mesh({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {1e-9, 0, 0}, {-1, 0, 0}, {-1, -1, 0}},
                    {{0, 1, 2}, {3, 4, 5}});
  const ValidationReport report = expect_loads_with_and_without_welding(mesh);
  EXPECT_EQ(report.components, 2u);
  EXPECT_EQ(report.welded_vertices, 0u);
  EXPECT_EQ(report.unwelded_groups, 1u);
  const std::string warnings = all_warnings(report);
  EXPECT_TRUE(contains(warnings, "1 groups of near-duplicate vertices kept apart")) << warnings;
  EXPECT_TRUE(contains(warnings, "1 would make a pinched vertex")) << warnings;
  EXPECT_TRUE(contains(warnings, "e.g. at vertex 0 at (0, 0, 0)")) << warnings;
}

TEST(Validate, LeavesClosedPartsTouchingAtAVertexApart) {
  // Two spheres touching at one vertex (closer than the tolerance, and bit-identical): closed,
  // nothing to repair, two components.
  const Mesh sphere = icosphere(1);
  const Eigen::Vector3d p = sphere.positions[0];  // its antipode is a vertex too
  for (const double gap : {1e-9, 0.0}) {
    Mesh mesh = joined(sphere, sphere, 2 * p * (1 + gap));
    const ValidationReport report = expect_loads_with_and_without_welding(mesh);
    EXPECT_EQ(report.components, 2u);
    EXPECT_EQ(report.welded_vertices, 0u);
    EXPECT_EQ(mesh.vertex_count(), 2 * sphere.vertex_count());
  }
}

TEST(Validate, KeepsApartWeldsThatWouldMakeAnEdgeOfFourFaces) {
  // Two squares, each two triangles, at right angles along a common diagonal 1e-9 apart: welded,
  // the diagonal would have four faces.
  Mesh mesh = triangle_mesh({{0, 0, 0},
                             {1, 0, 0},
                             {1, 1, 0},
                             {0, 1, 0},
                             {0, 0, 1e-9},
                             {1, 1, 1e-9},
                             {0.5, 0.5, 0.7},
                             {0.5, 0.5, -0.7}},
                            {{0, 1, 2}, {0, 2, 3}, {4, 6, 5}, {4, 5, 7}});
  const ValidationReport report = expect_loads_with_and_without_welding(mesh);
  EXPECT_EQ(report.components, 2u);
  EXPECT_EQ(report.welded_vertices, 0u);
  EXPECT_EQ(report.unwelded_groups, 2u);
  EXPECT_TRUE(contains(all_warnings(report), "2 would make an edge of more than two faces"))
      << all_warnings(report);
}

TEST(Validate, KeepsApartAWeldThatWouldMakeAMoebiusStrip) {
  // A band of 8 quads whose last column lies on its first with a half twist: as given an open
  // strip; welded, a Moebius strip.
  Mesh mesh;
  const int n = 8;
  for (int i = 0; i <= n; ++i) {
    const double u = 2 * M_PI * i / n, half = u / 2;
    for (double s : {-0.3, 0.3}) {
      const double r = 1 + s * std::cos(half);
      mesh.add_vertex({r * std::cos(u), r * std::sin(u), s * std::sin(half)});
    }
  }
  for (Index i = 0; i < n; ++i) mesh.add_face({2 * i, 2 * i + 2, 2 * i + 3, 2 * i + 1});
  const ValidationReport report = expect_loads_with_and_without_welding(mesh);
  EXPECT_EQ(report.welded_vertices, 0u);
  EXPECT_TRUE(contains(all_warnings(report), "would make a non-orientable surface"))
      << all_warnings(report);
  EXPECT_EQ(surface_topology(mesh, build_connectivity(mesh)).boundary_loops, 1u);
}

TEST(Validate, WeldsACrackClosed) {
  Mesh mesh = torus_cracked_at_seam(24, 12);
  const ValidationReport report = expect_loads_with_and_without_welding(mesh);
  EXPECT_EQ(report.welded_vertices, 12u);
  EXPECT_EQ(report.unwelded_groups, 0u);
  const SurfaceTopology topology = surface_topology(mesh, build_connectivity(mesh));
  EXPECT_EQ(topology.boundary_loops, 0u);
  EXPECT_EQ(topology.genus, 1);
}

TEST(Validate, NeverCollapsesTheInterior) {
  // A closed box thinner than the tolerance: welding its top to its bottom would fold it flat.
  Mesh box = triangle_mesh({{0, 0, 0},
                            {1, 0, 0},
                            {1, 1, 0},
                            {0, 1, 0},
                            {0, 0, 1e-9},
                            {1, 0, 1e-9},
                            {1, 1, 1e-9},
                            {0, 1, 1e-9}},
                           {{0, 2, 1},
                            {0, 3, 2},
                            {4, 5, 6},
                            {4, 6, 7},
                            {0, 1, 5},
                            {0, 5, 4},
                            {1, 2, 6},
                            {1, 6, 5},
                            {2, 3, 7},
                            {2, 7, 6},
                            {3, 0, 4},
                            {3, 4, 7}});
  EXPECT_EQ(expect_loads_with_and_without_welding(box).welded_vertices, 0u);
  EXPECT_EQ(box.vertex_count(), 8u);
  // A very short interior edge of a sphere.
  Mesh sphere = icosphere(2);
  const auto face = sphere.face(0);
  sphere.positions[face[1]] = sphere.positions[face[0]] + Eigen::Vector3d(1e-9, 0, 0);
  const std::size_t vertices = sphere.vertex_count();
  EXPECT_EQ(expect_loads_with_and_without_welding(sphere).welded_vertices, 0u);
  EXPECT_EQ(sphere.vertex_count(), vertices);
}

TEST(Validate, StillRefusesAMeshInvalidWithoutWelding) {
  // Three triangles on the edge 0-1, beside a square whose split diagonal welding closes.
  const Mesh fin = triangle_mesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}},
                                 {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}});
  const Mesh mesh = joined(fin, square_with_split_diagonal(1e-9), {5, 0, 0});
  expect_refused<TopologyError>(mesh, "edge 0-1");
  expect_refused<TopologyError>(mesh, "shared by 3 faces");
}

TEST(Validate, ReorientsInconsistentFacesAndReportsThem) {
  Mesh mesh = icosphere(2);
  const Mesh original = mesh;
  for (Index f : {3u, 50u, 51u}) {
    auto begin = mesh.face_vertices.begin() + mesh.face_offsets[f];
    std::reverse(begin, begin + 3);
  }
  const ValidationReport report = validate_mesh(mesh);
  EXPECT_EQ(report.flipped_faces, 3u);
  EXPECT_FALSE(report.oriented_as_given());
  EXPECT_TRUE(contains(all_warnings(report), "3 faces flipped"));
  EXPECT_NO_THROW(build_connectivity(mesh));
  // Flipped back, each face lists the same cycle as before (perhaps from another corner).
  for (Index f : {3u, 50u, 51u}) {
    const auto a = mesh.face(f), b = original.face(f);
    const std::size_t k = std::find(a.begin(), a.end(), b[0]) - a.begin();
    ASSERT_LT(k, 3u);
    EXPECT_EQ(a[(k + 1) % 3], b[1]);
    EXPECT_EQ(a[(k + 2) % 3], b[2]);
  }
}

TEST(Validate, RefusesNonOrientableSurface) {
  // A Moebius strip: a band of 8 quads whose ends are glued with a half twist.
  Mesh mesh;
  const int n = 8;
  for (int i = 0; i < n; ++i) {
    const double u = 2 * M_PI * i / n;
    const double half = u / 2;
    for (double s : {-0.3, 0.3}) {
      const double r = 1 + s * std::cos(half);
      mesh.add_vertex({r * std::cos(u), r * std::sin(u), s * std::sin(half)});
    }
  }
  for (Index i = 0; i < n; ++i) {
    const Index a = 2 * i, b = 2 * i + 1;
    const bool last = i + 1 == n;
    const Index c = last ? 1 : 2 * (i + 1),
                d = last ? 0 : 2 * (i + 1) + 1;  // the twist swaps sides
    mesh.add_face({a, c, d, b});
  }
  expect_refused<TopologyError>(mesh, "not orientable");
}

TEST(Validate, WarnsAboutSeveralComponents) {
  Mesh mesh = icosphere(0);
  Mesh second = icosphere(0);
  const Index offset = static_cast<Index>(mesh.vertex_count());
  for (const auto& p : second.positions) mesh.add_vertex(p + Eigen::Vector3d(5, 0, 0));
  for (std::size_t f = 0; f < second.face_count(); ++f) {
    const auto t = second.face(f);
    mesh.add_face({t[0] + offset, t[1] + offset, t[2] + offset});
  }
  const ValidationReport report = validate_mesh(mesh);
  EXPECT_EQ(report.components, 2u);
  EXPECT_TRUE(contains(all_warnings(report), "2 connected components"));
}

}  // namespace
}  // namespace tessera
