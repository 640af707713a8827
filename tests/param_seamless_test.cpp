// The seamless Poisson parameterization on generated meshes (core/param, Sec. 6.5, 6.6, App. A):
// seamlessness across every edge, cone angles matching the field's indices, no flipped triangles
// outside the singularities' one-rings, sizing, determinism.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "field/design.h"
#include "mesh/shapes.h"
#include "param/poisson.h"
#include "param/seamless_param.h"

namespace tessera {
namespace {

struct Parameterized {
  Mesh mesh;
  Connectivity c;
  CrossField field;
  SeamlessParam param;
};

Parameterized parameterize(Mesh mesh, ParamOptions options = {}, FieldOptions field = {}) {
  Parameterized r{std::move(mesh), {}, {}, {}};
  r.c = build_connectivity(r.mesh);
  const FaceFrames frames = face_frames(r.mesh);
  r.field = design_cross_field(r.mesh, r.c, frames, field, Progress());
  r.param = seamless_parameterization(r.mesh, r.c, frames, r.field, options, Progress());
  return r;
}

double domain_size(const Parameterized& r) {
  Eigen::Vector2d low = r.param.uv.front(), high = r.param.uv.front();
  for (const Eigen::Vector2d& p : r.param.uv) {
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  return (high - low).norm();
}

// Across every interior edge, at both of its ends, the twin's chart is the transition of h's:
// uv_g = J^r uv_f + t (with r = 0, t = 0 where the mesh is not cut).
void expect_seamless(const Parameterized& r) {
  const Connectivity& c = r.c;
  const double tolerance = 1e-8 * domain_size(r);
  for (Index h = 0; h < c.corner_count; ++h) {
    const Index t = c.twin[h];
    if (c.is_boundary_halfedge(t)) continue;
    const int rotation = r.param.rotation[h];
    const Eigen::Vector2d& shift = r.param.translation[h];
    if (!r.param.cut[c.edge[h]]) {
      EXPECT_EQ(rotation, 0);
      EXPECT_EQ(shift, Eigen::Vector2d::Zero());
    }
    EXPECT_EQ((rotation + r.param.rotation[t]) % 4, 0);
    // h runs a -> b in face f; corner next(t) of g sits at a, corner t at b.
    EXPECT_LT((r.param.uv[c.next[t]] - quarter_turns(r.param.uv[h], rotation) - shift).norm(),
              tolerance);
    EXPECT_LT((r.param.uv[t] - quarter_turns(r.param.uv[c.next[h]], rotation) - shift).norm(),
              tolerance);
  }
  EXPECT_LT(r.param.max_seam_error, 1e-8);
}

double signed_area(const Parameterized& r, Index f) {
  const Index c0 = r.mesh.face_offsets[f];
  const Eigen::Vector2d a = r.param.uv[c0 + 1] - r.param.uv[c0];
  const Eigen::Vector2d b = r.param.uv[c0 + 2] - r.param.uv[c0];
  return a.x() * b.y() - a.y() * b.x();
}

// Around a vertex whose triangles are not flipped, the uv corner angles add up to valence x 90
// degrees (Def. 2.3): 360 at regular interior vertices, 270 at valence 3, 450 at valence 5.
void expect_cone_angles(const Parameterized& r) {
  std::size_t checked = 0;
  for (Index v = 0; v < r.c.vertex_count(); ++v) {
    double total = 0;
    bool flipped = false;
    for (Index h : outgoing_halfedges(r.c, v)) {
      if (r.c.is_boundary_halfedge(h)) continue;
      flipped |= signed_area(r, r.c.face[h]) <= 0;
      const Eigen::Vector2d a = r.param.uv[r.c.next[h]] - r.param.uv[h];
      const Eigen::Vector2d b = r.param.uv[r.c.prev[h]] - r.param.uv[h];
      total += std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
    }
    if (flipped) continue;
    const int regular = r.c.is_boundary_vertex(v) ? 2 : 4;
    EXPECT_NEAR(total, (regular - r.field.vertex_index[v]) * std::numbers::pi / 2, 1e-6)
        << "vertex " << v;
    ++checked;
  }
  EXPECT_GT(checked, r.c.vertex_count() / 2);
}

void expect_injective_outside_singular_rings(const Parameterized& r) {
  std::size_t flipped = 0, outside = 0;
  for (Index f = 0; f < r.mesh.face_count(); ++f) {
    if (signed_area(r, f) > 0) continue;
    ++flipped;
    bool singular = false;
    for (Index v : r.mesh.face(f)) singular |= r.field.vertex_index[v] != 0;
    outside += !singular;
  }
  EXPECT_EQ(flipped, r.param.flipped_triangles);
  EXPECT_EQ(outside, r.param.flipped_outside_singular_rings);
  EXPECT_EQ(outside, 0u);
}

void expect_valid(const Parameterized& r) {
  ASSERT_EQ(r.param.uv.size(), r.mesh.corner_count());
  expect_seamless(r);
  expect_cone_angles(r);
  expect_injective_outside_singular_rings(r);
}

TEST(SeamlessParam, Icosphere) {
  expect_valid(parameterize(icosphere(3)));
}
TEST(SeamlessParam, TorusWithPrincipalField) {
  FieldOptions curvature;
  curvature.align = FieldAlignment::curvature;
  const Parameterized r = parameterize(torus(1.0, 0.4, 48, 16), {}, curvature);
  expect_valid(r);
  EXPECT_EQ(r.param.flipped_triangles, 0u);
}

TEST(SeamlessParam, RefusesASingularityFreeFieldTurningAroundALoop) {
  // The smoothest field of this torus turns around the tube; a flat torus cannot follow it.
  EXPECT_THROW(parameterize(torus(1.0, 0.4, 48, 16)), InputError);
}
TEST(SeamlessParam, DoubleTorus) {
  expect_valid(parameterize(double_torus(3)));
}
TEST(SeamlessParam, CylinderWithBoundary) {
  expect_valid(parameterize(open_cylinder(1.0, 2.0, 32, 8)));
}
TEST(SeamlessParam, MechanicalPart) {
  expect_valid(parameterize(mechanical_part(2)));
}

TEST(SeamlessParam, ParameterUnitIsH) {
  ParamOptions options;
  options.h_relative = 0.02;
  const Parameterized r = parameterize(icosphere(3), options);
  EXPECT_NEAR(r.param.h, 0.02 * 2 * std::sqrt(3.0), 1e-3);  // icosphere bbox: about a 2-cube
  double surface = 0, parameter = 0;
  for (Index h = 0; h < r.c.corner_count; ++h) {
    surface += halfedge_vector(r.mesh, r.c, h).norm();
    parameter += (r.param.uv[r.c.next[h]] - r.param.uv[h]).norm();
  }
  EXPECT_NEAR(parameter / (surface / r.param.h), 1.0, 0.1);
  EXPECT_LT(r.param.energy, 0.1);
}

TEST(SeamlessParam, ReportsStepTimes) {
  const Parameterized r = parameterize(icosphere(2));
  ASSERT_EQ(r.param.seconds.size(), 4u);
  EXPECT_EQ(r.param.seconds[0].step, "cut graph");
  EXPECT_EQ(r.param.seconds[3].step, "injectivity");
  for (const StepTime& t : r.param.seconds) EXPECT_GE(t.seconds, 0.0);
}

TEST(SeamlessParam, IsDeterministic) {
  const Parameterized a = parameterize(double_torus(2));
  const Parameterized b = parameterize(double_torus(2));
  EXPECT_EQ(a.param.uv, b.param.uv);
  EXPECT_EQ(a.param.rotation, b.param.rotation);
}

TEST(SeamlessParam, RejectsBadSizing) {
  ParamOptions options;
  options.h_relative = 0;
  EXPECT_THROW(parameterize(icosphere(1), options), InputError);
  options.h_relative = std::nan("");
  EXPECT_THROW(parameterize(icosphere(1), options), InputError);
}

}  // namespace
}  // namespace tessera
