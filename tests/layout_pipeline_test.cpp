// The quad layout end to end on generated meshes (core/layout/quad_layout.h): valid layouts on a
// sphere, a genus-2 surface and a boxy genus-2 part; the refined mesh covers the input; every arc
// edge separates two patches; each patch's four corner angles add up to 360 degrees in parameter
// space (a flat quadrilateral); the same input gives the same layout.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>

#include "field/field_topology.h"
#include "layout/layout_json.h"
#include "layout/metrics.h"
#include "layout/quad_layout.h"
#include "layout_test_util.h"
#include "mesh/geometry.h"
#include "mesh/shapes.h"

namespace tessera {
namespace {

using test::LayoutRun;
using test::run_layout;

double total_area(const Mesh& mesh) {
  const std::vector<double> areas = face_areas(mesh);
  return std::accumulate(areas.begin(), areas.end(), 0.0);
}

void expect_valid_layout(const LayoutRun& run) {
  const layout::QuadLayout& l = run.layout;
  ASSERT_TRUE(l.matching.has_solution());
  EXPECT_TRUE(l.check.valid()) << (l.check.problems.empty() ? "" : l.check.problems[0]);
  EXPECT_EQ(l.arcs.size(), l.matching.edges.size());
  EXPECT_NEAR(total_area(l.refined.mesh), total_area(run.input.mesh),
              1e-9 * total_area(run.input.mesh));
  const std::vector<std::int32_t>& patch = l.refined.mesh.face_attributes.at("patch");
  // Every arc edge of the refined mesh has a different patch on either side.
  const Connectivity c = build_connectivity(l.refined.mesh);
  std::size_t arc_sides = 0;
  for (Index h = 0; h < c.corner_count; ++h) {
    const std::pair<Index, Index> edge = std::minmax(c.from_vertex(h), c.to_vertex[h]);
    if (!std::binary_search(l.refined.arc_edges.begin(), l.refined.arc_edges.end(), edge)) continue;
    ++arc_sides;
    EXPECT_NE(patch[c.face[h]], patch[c.face[c.twin[h]]]);
  }
  EXPECT_EQ(arc_sides, 2 * l.refined.arc_edges.size());
  // Straight arcs, flat patches: the corners of a patch add up to a full turn.
  const std::vector<double> angles = layout::corner_angles(l.refined, patch, l.check);
  ASSERT_EQ(angles.size(), 4 * l.check.patch_count);
  for (std::size_t p = 0; p < l.check.patch_count; ++p) {
    EXPECT_NEAR(angles[4 * p] + angles[4 * p + 1] + angles[4 * p + 2] + angles[4 * p + 3], 360,
                1e-6)
        << "patch " << p;
    for (int k = 0; k < 4; ++k) EXPECT_GT(angles[4 * p + k], 0);
  }
}

TEST(QuadLayout, SphereIsValid) {
  const LayoutRun run = run_layout(icosphere(3));
  expect_valid_layout(run);
  EXPECT_EQ(run.graph.graph.ports.points.size(), 8u);
  EXPECT_GE(run.layout.check.patch_count, 6u);
}

TEST(QuadLayout, GenusTwoIsValid) {
  expect_valid_layout(run_layout(double_torus(3)));
}

TEST(QuadLayout, MechanicalPartIsValidAndFollowsItsEdges) {
  const LayoutRun run = run_layout(mechanical_part(2));
  expect_valid_layout(run);
  EXPECT_LT(run.layout.angle_rsd, 1.0);  // boxy: every patch corner is a right angle
}

TEST(QuadLayout, AlphaZeroIsValidToo) {
  expect_valid_layout(run_layout(icosphere(3), 0));
}

TEST(QuadLayout, SameInputSameLayout) {
  const LayoutRun a = run_layout(double_torus(3));
  const LayoutRun b = run_layout(double_torus(3));
  nlohmann::ordered_json ja = layout::layout_json(a.graph, a.layout);
  nlohmann::ordered_json jb = layout::layout_json(b.graph, b.layout);
  ja.erase("seconds");
  jb.erase("seconds");
  EXPECT_EQ(ja, jb);
  EXPECT_EQ(a.layout.refined.mesh.face_attributes, b.layout.refined.mesh.face_attributes);
}

// A constant direction projected onto a sphere turns a full turn around the two points where it
// is normal; the bisector of two such fields, for directions a and c, turns half a turn: index
// 1/2 (two ports) at +-a and +-c. The field splits each into two singularities of valence 3
// (field_topology.h), and their layout is valid.
TEST(QuadLayout, FieldOfIndexOneHalfIsSplitAndValid) {
  const Mesh sphere = icosphere(3);
  const Eigen::Vector3d a = sphere.positions[0].normalized();
  Index far = 0;  // the vertex nearest a quarter turn from a
  for (Index v = 0; v < sphere.vertex_count(); ++v)
    if (std::abs(sphere.positions[v].dot(a)) < std::abs(sphere.positions[far].dot(a))) far = v;
  const Eigen::Vector3d c = sphere.positions[far].normalized();
  std::vector<int> merged;
  const LayoutRun run = run_layout(test::parameterized_with(
      sphere, [&](const Mesh& m, const Connectivity& connectivity, const FaceFrames& frames) {
        std::vector<double> angle(m.face_count());
        for (Index f = 0; f < m.face_count(); ++f)
          angle[f] = (frames.angle(f, a) + frames.angle(f, c)) / 2;
        const CrossField field = cross_field_from_angles(m, connectivity, frames, angle);
        const Matching principal = principal_matching(connectivity, field.angle, field.kappa);
        merged = vertex_indices(m, connectivity, frames, field.angle, principal.turn);
        return field;
      }));
  EXPECT_EQ(std::count(merged.begin(), merged.end(), 2), 4);  // before the split
  EXPECT_EQ(std::count(merged.begin(), merged.end(), 0), merged.size() - 4);
  expect_valid_layout(run);
  ASSERT_EQ(run.graph.graph.ports.points.size(), 8u);
  for (const layout::SingularPoint& point : run.graph.graph.ports.points)
    EXPECT_EQ(point.valence, 3);
}

}  // namespace
}  // namespace tessera
