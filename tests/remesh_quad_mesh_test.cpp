// Quad meshes from layouts (core/remesh, thesis Ch. 8) on generated meshes: the integer lengths
// (opposite sides equal, a target quad count met closely), the per-patch maps (Wachspress
// coordinates reproduce the corners and interpolate linearly on the sides), and the mesh itself:
// all quads, conforming (closed and manifold as the input), the same Euler characteristic, the
// layout's patches, no flipped quad, a positive scaled Jacobian, irregular vertices only at nodes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

#include "layout_test_util.h"
#include "mesh/shapes.h"
#include "remesh/hausdorff.h"
#include "remesh/patch_map.h"
#include "remesh/remesh.h"
#include "remesh/smoothing.h"

namespace tessera {
namespace {

using test::LayoutRun;
using test::run_layout;

// At alpha 10: at alpha 5 the sphere's layout has patch corners of up to 167 degrees in parameter
// space, and the quads at them have a reflex corner on the surface (see SphereAtAlphaFive).
const LayoutRun& sphere() {
  static const LayoutRun run = run_layout(icosphere(3), 10);
  return run;
}

const LayoutRun& genus_two() {
  static const LayoutRun run = run_layout(double_torus(3), 10);
  return run;
}

const LayoutRun& mechanical() {
  static const LayoutRun run = run_layout(mechanical_part(2));
  return run;
}

long euler_characteristic(const Mesh& mesh) {
  const Connectivity c = build_connectivity(mesh);
  return long(mesh.vertex_count()) - long(c.edge_count()) + long(mesh.face_count());
}

void expect_good_quad_mesh(const LayoutRun& run, const remesh::QuadMesh& q) {
  ASSERT_TRUE(run.layout.check.valid());
  const Mesh& mesh = q.mesh;
  EXPECT_EQ(mesh.corner_count(), 4 * mesh.face_count());
  EXPECT_EQ(q.lengths.quad_count(), mesh.face_count());
  ASSERT_TRUE(q.quality.manifold) << q.quality.problem;
  EXPECT_EQ(q.quality.boundary_edges, 0u);
  EXPECT_EQ(q.quality.euler_characteristic, euler_characteristic(run.input.mesh));
  EXPECT_EQ(q.quality.flipped_quads, 0u);
  EXPECT_EQ(q.quality.nonpositive_jacobian_quads, 0u);
  EXPECT_GT(q.quality.min_scaled_jacobian, 0);
  EXPECT_GT(q.quality.mean_scaled_jacobian, 0.8);
  EXPECT_EQ(q.irregular_off_nodes, 0u);
  EXPECT_EQ(q.unlocated_points, 0u);
  // Every patch of the layout is one block of n x m quads.
  const std::vector<std::int32_t>& patch = mesh.face_attributes.at("patch");
  ASSERT_EQ(patch.size(), mesh.face_count());
  std::vector<std::size_t> count(run.layout.check.patch_count, 0);
  for (std::int32_t p : patch) {
    ASSERT_GE(p, 0);
    ASSERT_LT(std::size_t(p), count.size());
    ++count[p];
  }
  for (std::size_t p = 0; p < count.size(); ++p)
    EXPECT_EQ(count[p], std::size_t(q.lengths.size[p][0]) * q.lengths.size[p][1]) << p;
  // No vertex is repeated at one position: neighbouring patches share their side vertices.
  std::set<std::array<long, 3>> at;
  for (const Eigen::Vector3d& x : mesh.positions)
    at.insert({std::lround(x.x() * 1e7), std::lround(x.y() * 1e7), std::lround(x.z() * 1e7)});
  EXPECT_EQ(at.size(), mesh.vertex_count());
}

TEST(Remesh, WachspressReproducesCornersAndSides) {
  const std::array<Eigen::Vector2d, 4> q{Eigen::Vector2d(0, 0), Eigen::Vector2d(3, 0.5),
                                         Eigen::Vector2d(2.5, 2), Eigen::Vector2d(-0.5, 1.5)};
  for (int k = 0; k < 4; ++k) {
    const Eigen::Vector4d w = remesh::wachspress(q, q[k]);
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(w[i], i == k ? 1 : 0, 1e-12);
  }
  const Eigen::Vector4d w = remesh::wachspress(q, 0.25 * q[1] + 0.75 * q[2]);
  EXPECT_NEAR(w[1], 0.25, 1e-12);
  EXPECT_NEAR(w[2], 0.75, 1e-12);
  const Eigen::Vector4d inside = remesh::wachspress(q, Eigen::Vector2d(1.2, 1));
  EXPECT_GT(inside.minCoeff(), 0);
  Eigen::Vector2d x = Eigen::Vector2d::Zero();
  for (int i = 0; i < 4; ++i) x += inside[i] * q[i];
  EXPECT_NEAR((x - Eigen::Vector2d(1.2, 1)).norm(), 0, 1e-12);  // linear precision
}

TEST(Remesh, OppositeSidesGetTheSameLength) {
  const remesh::QuadMesh q = remesh::remesh_layout(sphere().layout, {});
  const std::size_t sides = q.lengths.chain.size();
  EXPECT_EQ(q.lengths.length.size(), sides);
  for (int n : q.lengths.segments) EXPECT_GE(n, 1);
  // Each chain's integer is the nearest to its mean length over lambda (8.1).
  std::vector<double> sum(q.lengths.segments.size(), 0), members(sum.size(), 0);
  for (std::size_t i = 0; i < sides; ++i) {
    sum[q.lengths.chain[i]] += q.lengths.length[i];
    ++members[q.lengths.chain[i]];
  }
  for (std::size_t k = 0; k < sum.size(); ++k)
    EXPECT_LE(std::abs(sum[k] / members[k] / q.lengths.lambda - q.lengths.segments[k]), 0.5 + 1e-9)
        << "chain " << k;
}

TEST(Remesh, CompressedSidesAreTheSidesFarShorterThanTheirQuads) {
  remesh::SideLengths lengths;
  lengths.length = {10, 1, 9, 10};
  lengths.chain = {0, 0, 0, 1};
  lengths.segments = {7, 10};
  lengths.lambda = 1;
  EXPECT_EQ(remesh::compressed_sides(lengths), std::vector<std::size_t>{1});
  EXPECT_TRUE(remesh::compressed_sides(lengths, 10).empty());
}

TEST(Remesh, SphereGivesAGoodQuadMesh) {
  remesh::SizeTarget target;
  target.quads = 600;
  const remesh::QuadMesh q = remesh::remesh_layout(sphere().layout, target);
  expect_good_quad_mesh(sphere(), q);
  EXPECT_NEAR(double(q.mesh.face_count()), 600, 0.15 * 600);
}

TEST(Remesh, QuadCountFollowsTheTarget) {
  remesh::SizeTarget few, many;
  few.quads = 200;
  many.quads = 2000;
  const remesh::QuadMesh a = remesh::remesh_layout(sphere().layout, few);
  const remesh::QuadMesh b = remesh::remesh_layout(sphere().layout, many);
  EXPECT_NEAR(double(a.mesh.face_count()), 200, 0.25 * 200);
  EXPECT_NEAR(double(b.mesh.face_count()), 2000, 0.1 * 2000);
  EXPECT_GT(b.mesh.face_count(), 5 * a.mesh.face_count());
  expect_good_quad_mesh(sphere(), b);
}

// The page's slider: one prep of the layout, then any number of targets, each the very mesh a
// fresh remesh_layout() makes.
TEST(Remesh, OnePrepServesEveryTargetAsAFreshRemesh) {
  const remesh::RemeshPrep prep = remesh::prepare_remesh(sphere().layout);
  EXPECT_EQ(prep.charts.size(), sphere().layout.check.patch_count);
  EXPECT_EQ(prep.tracks.size(), prep.sides.sides.size());
  for (std::size_t quads : {150, 900, 3000}) {
    remesh::SizeTarget target;
    target.quads = quads;
    const remesh::QuadMesh kept = remesh::remesh_prepared(sphere().layout, prep, target);
    const remesh::QuadMesh fresh = remesh::remesh_layout(sphere().layout, target);
    EXPECT_EQ(kept.mesh.positions, fresh.mesh.positions) << quads;
    EXPECT_EQ(kept.mesh.face_vertices, fresh.mesh.face_vertices) << quads;
    EXPECT_EQ(kept.mesh.face_attributes.at("patch"), fresh.mesh.face_attributes.at("patch"));
    EXPECT_EQ(kept.lengths.segments, fresh.lengths.segments);
  }
}

TEST(Remesh, EdgeLengthSetsTheScale) {
  remesh::SizeTarget coarse, fine;
  coarse.edge_length = 0.3;
  fine.edge_length = 0.1;
  const remesh::QuadMesh a = remesh::remesh_layout(sphere().layout, coarse);
  const remesh::QuadMesh b = remesh::remesh_layout(sphere().layout, fine);
  // Area 4 pi of the unit sphere over edge^2, up to the layout's distortion.
  EXPECT_NEAR(double(b.mesh.face_count()), 4 * M_PI / 0.01, 0.35 * 4 * M_PI / 0.01);
  EXPECT_GT(b.mesh.face_count(), 5 * a.mesh.face_count());
}

TEST(Remesh, GenusTwoGivesAGoodQuadMesh) {
  remesh::SizeTarget target;
  target.quads = 1500;
  const remesh::QuadMesh q = remesh::remesh_layout(genus_two().layout, target);
  expect_good_quad_mesh(genus_two(), q);
  EXPECT_NEAR(double(q.mesh.face_count()), 1500, 0.15 * 1500);
}

TEST(Remesh, MechanicalPartGivesAGoodQuadMesh) {
  remesh::SizeTarget target;
  target.quads = 2000;
  const remesh::QuadMesh q = remesh::remesh_layout(mechanical().layout, target);
  expect_good_quad_mesh(mechanical(), q);
  EXPECT_NEAR(double(q.mesh.face_count()), 2000, 0.15 * 2000);
}

TEST(Remesh, SphereAtAlphaFiveIsConformingWithoutFlips) {
  const LayoutRun run = run_layout(icosphere(3), 5);
  remesh::SizeTarget target;
  target.quads = 500;
  const remesh::QuadMesh q = remesh::remesh_layout(run.layout, target);
  ASSERT_TRUE(q.quality.manifold) << q.quality.problem;
  EXPECT_EQ(q.quality.boundary_edges, 0u);
  EXPECT_EQ(q.quality.euler_characteristic, 2);
  EXPECT_EQ(q.quality.flipped_quads, 0u);
  EXPECT_EQ(q.irregular_off_nodes, 0u);
  EXPECT_EQ(q.quality.irregular_vertices, 8u);  // the eight singularities of valence 3
}

TEST(Remesh, NearestPointOnATriangle) {
  const Eigen::Vector3d a(0, 0, 0), b(2, 0, 0), c(0, 2, 0);
  EXPECT_NEAR(
      (remesh::nearest_on_triangle({0.5, 0.5, 3}, a, b, c) - Eigen::Vector3d(0.5, 0.5, 0)).norm(),
      0, 1e-12);
  EXPECT_NEAR((remesh::nearest_on_triangle({-1, -1, 1}, a, b, c) - a).norm(), 0, 1e-12);
  EXPECT_NEAR((remesh::nearest_on_triangle({1, -3, 0}, a, b, c) - Eigen::Vector3d(1, 0, 0)).norm(),
              0, 1e-12);
  EXPECT_NEAR((remesh::nearest_on_triangle({2, 2, 0}, a, b, c) - Eigen::Vector3d(1, 1, 0)).norm(),
              0, 1e-12);
}

// The smoothing pass keeps the connectivity and the nodes, keeps every vertex on the surface (the
// unit sphere, up to its triangles' sag), flips nothing and lowers no quad below min(its
// minimum, 0.5).
TEST(Remesh, SmoothingKeepsTheMeshOnTheSurfaceAndNeverWorsensTheMinimum) {
  const LayoutRun run = run_layout(icosphere(3), 5);
  remesh::SizeTarget target;
  target.quads = 800;
  const remesh::QuadMesh plain = remesh::remesh_layout(run.layout, target);
  const remesh::QuadMesh smooth = remesh::remesh_layout(run.layout, target, 10, &run.input.mesh);
  ASSERT_EQ(smooth.mesh.face_vertices, plain.mesh.face_vertices);
  EXPECT_EQ(smooth.quality.flipped_quads, 0u);
  EXPECT_GE(smooth.quality.min_scaled_jacobian,
            std::min(plain.quality.min_scaled_jacobian, 0.5) - 1e-12);
  EXPECT_GT(smooth.seconds.size(), plain.seconds.size());
  std::size_t moved = 0;
  for (std::size_t v = 0; v < smooth.mesh.vertex_count(); ++v) {
    EXPECT_NEAR(smooth.mesh.positions[v].norm(), 1, 0.01) << v;
    moved += (smooth.mesh.positions[v] - plain.mesh.positions[v]).norm() > 1e-9;
  }
  EXPECT_GT(moved, smooth.mesh.vertex_count() / 2);
  for (Index v : plain.quality.irregular)
    EXPECT_EQ(smooth.mesh.positions[v], plain.mesh.positions[v]);  // nodes stay
}

TEST(Remesh, HausdorffDistanceOfSpheres) {
  const Mesh unit = icosphere(2);
  EXPECT_NEAR(remesh::relative_hausdorff(unit, unit), 0, 1e-12);
  Mesh larger = unit;
  for (Eigen::Vector3d& x : larger.positions) x *= 1.1;
  // 0.1 apart at the vertices (more at the larger sphere's vertices against the unit sphere's
  // flat triangles), over the diagonal 2 sqrt(3) of the unit sphere's box.
  const double d = remesh::relative_hausdorff(unit, larger);
  EXPECT_GE(d, 0.1 / (2 * std::sqrt(3.0)) - 1e-9);
  EXPECT_LT(d, 0.15 / (2 * std::sqrt(3.0)));
}

// Every sample (vertices and face centroids) of `from` against every triangle of `to`.
double brute_force_one_sided(const Mesh& from, const Mesh& to) {
  std::vector<Eigen::Vector3d> samples = from.positions;
  for (std::size_t f = 0; f < from.face_count(); ++f) {
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (Index v : from.face(f)) centroid += from.positions[v];
    samples.push_back(centroid / double(from.face_size(f)));
  }
  double largest = 0;
  for (const Eigen::Vector3d& p : samples) {
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t f = 0; f < to.face_count(); ++f) {
      const auto c = to.face(f);
      for (std::size_t i = 1; i + 1 < c.size(); ++i)
        nearest = std::min(nearest,
                           (remesh::nearest_on_triangle(p, to.positions[c[0]], to.positions[c[i]],
                                                        to.positions[c[i + 1]]) -
                            p)
                               .norm());
    }
    largest = std::max(largest, nearest);
  }
  return largest;
}

// One reference for several meshes, each distance what every sample against every triangle gives
// (the grid's early settling of near samples loses none).
TEST(Remesh, HausdorffReferenceGivesTheBruteForceDistanceForEveryMesh) {
  const Mesh unit = icosphere(2);
  Eigen::AlignedBox3d box;
  for (const Eigen::Vector3d& x : unit.positions) box.extend(x);
  const remesh::HausdorffReference reference(unit);
  for (double scale : {1.0, 1.1, 0.8}) {
    Mesh other = icosphere(scale == 1.0 ? 2 : 1);
    for (Eigen::Vector3d& x : other.positions) x = scale * x + Eigen::Vector3d(0.05, 0, 0);
    const double expected =
        std::max(brute_force_one_sided(unit, other), brute_force_one_sided(other, unit)) /
        box.diagonal().norm();
    EXPECT_NEAR(reference.relative_to(other), expected, 1e-14) << scale;
    EXPECT_EQ(remesh::relative_hausdorff(unit, other), reference.relative_to(other));
  }
}

TEST(Remesh, InvalidLayoutIsAnInputErrorNamingTheProblem) {
  layout::QuadLayout broken = sphere().layout;
  broken.check.problem_count = 1;
  broken.check.problems = {"patch 3 has 5 corners"};
  try {
    remesh::remesh_layout(broken, {});
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("patch 3"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace tessera
