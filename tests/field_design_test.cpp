// Cross fields on generated meshes: Poincare-Hopf, the smoothest field on a sphere and a torus,
// boundary and sharp-edge alignment, matching conventions, determinism (core/field, Sec. 6.3).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>

#include "field/alignment.h"
#include "field/design.h"
#include "mesh/geometry.h"
#include "mesh/shapes.h"

namespace tessera {
namespace {

struct Fielded {
  Mesh mesh;
  Connectivity connectivity;
  FaceFrames frames;
  CrossField field;
};

Fielded design(Mesh mesh, FieldOptions options = {}) {
  Fielded r{std::move(mesh), {}, {}, {}};
  r.connectivity = build_connectivity(r.mesh);
  r.frames = face_frames(r.mesh);
  r.field = design_cross_field(r.mesh, r.connectivity, r.frames, options, Progress());
  return r;
}

// The angle between the field's cross and direction d in face f, modulo a quarter turn.
double cross_misalignment(const Fielded& r, Index f, const Eigen::Vector3d& d) {
  return std::abs(std::remainder(r.field.angle[f] - r.frames.angle(f, d), std::numbers::pi / 2));
}

void expect_poincare_hopf(const Fielded& r, long chi) {
  EXPECT_EQ(r.field.euler_characteristic, chi);
  EXPECT_EQ(r.field.index_sum, static_cast<double>(chi));
  double sum = 0;
  for (const Singularity& s : r.field.singularities) {
    EXPECT_NE(s.index, 0.0);
    EXPECT_EQ(s.index * 4, r.field.vertex_index[s.vertex]);
    sum += s.index;
  }
  EXPECT_EQ(sum, static_cast<double>(chi));
}

TEST(FieldDesign, PoincareHopfOnGeneratedSurfaces) {
  expect_poincare_hopf(design(icosphere(3)), 2);
  expect_poincare_hopf(design(torus(1.0, 0.4, 48, 16)), 0);
  expect_poincare_hopf(design(double_torus(2)), -2);
  expect_poincare_hopf(design(open_cylinder(1.0, 2.0, 32, 8)), 0);
  expect_poincare_hopf(design(mechanical_part(2)), -2);
  FieldOptions curvature;
  curvature.align = FieldAlignment::curvature;
  expect_poincare_hopf(design(double_torus(2), curvature), -2);
}

TEST(FieldDesign, SphereHasTotalIndexTwoInValenceThreeAndFive) {
  const Fielded r = design(icosphere(3));
  EXPECT_EQ(r.field.index_sum, 2.0);
  ASSERT_FALSE(r.field.singularities.empty());
  for (const Singularity& s : r.field.singularities) {
    EXPECT_EQ(s.valence, 4 - static_cast<int>(4 * s.index));
    EXPECT_TRUE(s.valence == 3 || s.valence == 5) << "vertex " << s.vertex;
  }
}

TEST(FieldDesign, SmoothestFieldOnATorusHasNoSingularities) {
  EXPECT_TRUE(design(torus(1.0, 0.4, 48, 16)).field.singularities.empty());
  EXPECT_TRUE(design(torus(1.0, 0.3, 64, 20)).field.singularities.empty());
}

TEST(FieldDesign, CurvatureAlignedTorusFollowsTheParallels) {
  FieldOptions options;
  options.align = FieldAlignment::curvature;
  const Fielded r = design(torus(1.0, 0.3, 48, 16), options);
  EXPECT_TRUE(r.field.singularities.empty());
  // Principal directions of a torus of revolution: along the parallels and the meridians.
  for (Index f = 0; f < r.mesh.face_count(); ++f) {
    const auto v = r.mesh.face(f);
    const Eigen::Vector3d centre =
        (r.mesh.positions[v[0]] + r.mesh.positions[v[1]] + r.mesh.positions[v[2]]) / 3;
    EXPECT_LT(cross_misalignment(r, f, Eigen::Vector3d(-centre.y(), centre.x(), 0)), 0.1)
        << "face " << f;
  }
}

TEST(FieldDesign, BoundaryAlignedCylinderHasNoSingularities) {
  const Fielded r = design(open_cylinder(1.0, 2.0, 32, 8));
  EXPECT_TRUE(r.field.singularities.empty());
  const Connectivity& c = r.connectivity;
  for (Index h = 0; h < c.corner_count; ++h)
    if (c.is_boundary_halfedge(c.twin[h]))
      EXPECT_LT(cross_misalignment(r, c.face[h], halfedge_vector(r.mesh, c, h)), 1e-9);
}

TEST(FieldDesign, SharpEdgesAreHardConstraints) {
  const Fielded r = design(mechanical_part(2));
  const Connectivity& c = r.connectivity;
  std::size_t sharp_faces = 0;
  for (Index h = 0; h < c.corner_count; ++h) {
    const Index t = c.twin[h];
    const double cosine = r.frames.normal[c.face[h]].dot(r.frames.normal[c.face[t]]);
    if (cosine > 0.5) continue;  // the bracket's sharp edges are at 90 degrees
    ++sharp_faces;
    EXPECT_LT(cross_misalignment(r, c.face[h], halfedge_vector(r.mesh, c, h)), 1e-9);
  }
  EXPECT_GT(sharp_faces, 0u);
  // Without sharp constraints the field is free to cross the edges at any angle.
  FieldOptions off;
  off.sharp_degrees = 180;
  const Fielded free = design(mechanical_part(2), off);
  EXPECT_NE(free.field.angle, r.field.angle);
}

// An icosphere with its vertices moved radially by deterministic noise: like a coarse scan, many of
// its edges are sharper than 35 degrees in every direction.
Mesh noisy_sphere() {
  Mesh mesh = icosphere(4);
  std::uint32_t state = 12345;
  for (Eigen::Vector3d& p : mesh.positions) {
    state = state * 1664525u + 1013904223u;
    p *= 1.0 + 0.06 * (static_cast<double>(state >> 8) / (1u << 24) - 0.5);
  }
  return mesh;
}

TEST(FieldDesign, SharpConstraintsOfAdjacentFacesNeverConflict) {
  const Mesh mesh = noisy_sphere();
  const Connectivity c = build_connectivity(mesh);
  const FaceFrames frames = face_frames(mesh);
  const std::vector<double> dihedral = dihedral_angles(mesh, c);
  const double sharp = 35 * std::numbers::pi / 180;
  const auto sharp_edges = std::count_if(dihedral.begin(), dihedral.end(),
                                         [&](double a) { return std::abs(a) > sharp; });
  ASSERT_GT(sharp_edges * 10, static_cast<long>(c.edge_count()));  // over a tenth: noisy

  const std::vector<double> kappa = connection_angles(mesh, c, frames);
  const FaceConstraints constraints = feature_constraints(mesh, c, frames, kappa, sharp);
  EXPECT_GT(constraints.count, 0u);  // consistent runs of sharp edges keep theirs
  for (Index h = 0; h < c.corner_count; ++h) {
    const Index f = c.face[h];
    const Index g = c.face[c.twin[h]];
    if (!constraints.fixed[f] || !constraints.fixed[g]) continue;
    const double turn = std::remainder(constraints.angle[f] + kappa[h] - constraints.angle[g],
                                       std::numbers::pi / 2);
    EXPECT_LE(std::abs(turn), std::numbers::pi / 6 + 1e-12) << "faces " << f << ", " << g;
  }
}

TEST(FieldDesign, PeriodJumpsFollowTheConvention) {
  const Fielded r = design(icosphere(2));
  const Connectivity& c = r.connectivity;
  for (Index h = 0; h < c.corner_count; ++h) {
    const Index t = c.twin[h];
    EXPECT_EQ((r.field.period_jump[h] + r.field.period_jump[t]) % 4, 0);
    EXPECT_DOUBLE_EQ(r.field.kappa[h], -r.field.kappa[t]);
    // theta_g = theta_f + kappa - p pi/2 + delta with |delta| <= pi/4 (cross_field.h).
    const double delta =
        std::remainder(r.field.angle[c.face[t]] - r.field.angle[c.face[h]] - r.field.kappa[h] +
                           r.field.period_jump[h] * std::numbers::pi / 2,
                       2 * std::numbers::pi);
    EXPECT_LE(std::abs(delta), std::numbers::pi / 4 + 1e-12);
  }
}

TEST(FieldDesign, IsDeterministic) {
  const Fielded a = design(double_torus(2));
  const Fielded b = design(double_torus(2));
  EXPECT_EQ(a.field.angle, b.field.angle);
  EXPECT_EQ(a.field.period_jump, b.field.period_jump);
}

TEST(FieldDesign, DirectionsRoundTrip) {
  const Fielded r = design(double_torus(2));
  const CrossField again =
      cross_field_from_directions(r.mesh, r.connectivity, r.frames, r.field.direction);
  EXPECT_EQ(again.vertex_index, r.field.vertex_index);
  EXPECT_EQ(again.period_jump, r.field.period_jump);
}

// A flat disk of two rings of `n` vertices around vertex 0; the centre and the first ring are
// interior.
Mesh two_ring_disk(int n) {
  std::vector<Eigen::Vector3d> positions{Eigen::Vector3d::Zero()};
  for (int ring = 1; ring <= 2; ++ring)
    for (int i = 0; i < n; ++i) {
      const double phi = 2 * std::numbers::pi * (i + 0.5 * ring) / n;
      positions.push_back(ring * Eigen::Vector3d(std::cos(phi), std::sin(phi), 0));
    }
  std::vector<std::array<Index, 3>> triangles;
  const auto inner = [n](int i) { return Index(1 + (i % n)); };
  const auto outer = [n](int i) { return Index(1 + n + (i % n)); };
  for (int i = 0; i < n; ++i) {
    triangles.push_back({0, inner(i), inner(i + 1)});
    triangles.push_back({inner(i), outer(i), inner(i + 1)});
    triangles.push_back({inner(i + 1), outer(i), outer(i + 1)});
  }
  return triangle_mesh(std::move(positions), triangles);
}

// A vertex of index 1/2 or 3/4 (the cross turning k quarter turns around the disk's centre) is
// split into k singularities of index 1/4 at the centre and its neighbours, by k - 1 period jumps
// that leave principal matching; the index sum stays.
TEST(FieldDesign, MergedSingularitiesAreSplitIntoValenceThree) {
  for (int quarters : {1, 2, 3}) {
    Fielded r{two_ring_disk(12), {}, {}, {}};
    r.connectivity = build_connectivity(r.mesh);
    r.frames = face_frames(r.mesh);
    std::vector<Eigen::Vector3d> directions;
    for (Index f = 0; f < r.mesh.face_count(); ++f) {
      Eigen::Vector3d centre = Eigen::Vector3d::Zero();
      for (Index v : r.mesh.face(f)) centre += r.mesh.positions[v] / 3;
      const double turned = quarters / 4.0 * std::atan2(centre.y(), centre.x());
      directions.push_back({std::cos(turned), std::sin(turned), 0});
    }
    r.field = cross_field_from_directions(r.mesh, r.connectivity, r.frames, directions);
    expect_poincare_hopf(r, 1);
    int split = 0;
    for (const Singularity& s : r.field.singularities) {
      if (r.connectivity.is_boundary_vertex(s.vertex)) continue;
      EXPECT_EQ(s.valence, 3) << "vertex " << s.vertex;
      EXPECT_TRUE(s.vertex == 0 || r.mesh.positions[s.vertex].norm() < 1.5) << s.vertex;
      ++split;
    }
    EXPECT_EQ(split, quarters);
    int unprincipal = 0;
    for (Index h = 0; h < r.connectivity.corner_count; ++h) {
      const Index t = r.connectivity.twin[h];
      if (r.connectivity.is_boundary_halfedge(t)) continue;
      const double delta = std::remainder(
          r.field.angle[r.connectivity.face[t]] - r.field.angle[r.connectivity.face[h]] -
              r.field.kappa[h] + r.field.period_jump[h] * std::numbers::pi / 2,
          2 * std::numbers::pi);
      unprincipal += std::abs(delta) > std::numbers::pi / 4 + 1e-12;
    }
    EXPECT_EQ(unprincipal, 2 * (quarters - 1));  // both halfedges of each changed edge
  }
}

TEST(FieldDesign, RejectsBadInput) {
  Mesh quads = quad_torus(1.0, 0.4, 8, 4);
  EXPECT_THROW(face_frames(quads), TopologyError);
  const Fielded r = design(icosphere(1));
  std::vector<Eigen::Vector3d> short_list(r.mesh.face_count() - 1, Eigen::Vector3d::UnitX());
  EXPECT_THROW(cross_field_from_directions(r.mesh, r.connectivity, r.frames, short_list),
               InputError);
  std::vector<Eigen::Vector3d> normals = r.frames.normal;
  EXPECT_THROW(cross_field_from_directions(r.mesh, r.connectivity, r.frames, normals), InputError);
  FieldOptions bad;
  bad.sharp_degrees = -1;
  EXPECT_THROW(design(icosphere(1), bad), InputError);
}

}  // namespace
}  // namespace tessera
