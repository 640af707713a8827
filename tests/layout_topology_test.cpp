// Quad layouts on generated surfaces with handles and with boundary (core/layout/quad_layout.h):
// loops of arcs around a handle must not leave patches that touch themselves (conflicts.h,
// loop_pairs()); the layout is valid and the same input gives the same layout.
#include <gtest/gtest.h>

#include "layout/layout_json.h"
#include "layout/quad_layout.h"
#include "layout_test_util.h"
#include "mesh/shapes.h"

namespace tessera {
namespace {

using test::LayoutRun;
using test::run_layout;

// The faces of `mesh` whose centroid has x > cut, with the vertices they use.
Mesh faces_beyond(const Mesh& mesh, double cut) {
  Mesh part;
  std::vector<Index> renumbered(mesh.vertex_count(), kNoIndex);
  for (Index f = 0; f < mesh.face_count(); ++f) {
    double x = 0;
    for (Index h = mesh.face_offsets[f]; h < mesh.face_offsets[f + 1]; ++h)
      x += mesh.positions[mesh.face_vertices[h]].x();
    if (x / double(mesh.face_offsets[f + 1] - mesh.face_offsets[f]) <= cut) continue;
    std::vector<Index> face;
    for (Index h = mesh.face_offsets[f]; h < mesh.face_offsets[f + 1]; ++h) {
      Index& v = renumbered[mesh.face_vertices[h]];
      if (v == kNoIndex) v = part.add_vertex(mesh.positions[mesh.face_vertices[h]]);
      face.push_back(v);
    }
    part.add_face(face);
  }
  return part;
}

void expect_valid(const LayoutRun& run) {
  ASSERT_TRUE(run.layout.matching.has_solution())
      << matching::to_string(run.layout.matching.status) << ", unmatchable ports "
      << run.graph.unmatchable_ports.size();
  EXPECT_TRUE(run.layout.check.valid())
      << (run.layout.check.problems.empty() ? "" : run.layout.check.problems[0]);
}

// A thin torus whose smoothest field has four singularities: the first matching closes loops of
// arcs around the tube (patches touching themselves), the rounds of solve_layout() remove them.
Mesh thin_torus() {
  return torus(1, 0.25, 64, 12);
}

TEST(LayoutTopology, TorusLoopsAreResolved) {
  const LayoutRun run = run_layout(thin_torus());
  EXPECT_EQ(run.graph.graph.ports.points.size(), 4u);
  expect_valid(run);
  EXPECT_FALSE(run.layout.loop_rounds.empty());
}

TEST(LayoutTopology, HalfTorusWithBoundaryIsValid) {
  const LayoutRun run = run_layout(faces_beyond(torus(1, 0.5, 32, 16), 0));
  EXPECT_GT(run.graph.graph.virtual_ports.size(), 0u);
  expect_valid(run);
}

// Boundaries that are not parameter lines leave patches with two or three corners beside them;
// the parameterization keeps every boundary edge on an isoline (param/seams.h), so a hemisphere's
// boundary circle carries the layout.
TEST(LayoutTopology, HemisphereWithBoundaryIsValid) {
  const LayoutRun run = run_layout(faces_beyond(icosphere(3), 0));
  EXPECT_GT(run.graph.graph.virtual_ports.size(), 0u);
  expect_valid(run);
}

// Caps cut from an icosphere by planes through its triangles: staircase boundaries whose edges
// stand up to 60 degrees off the cut. The field and the boundary's parameter line follow the cut,
// not the steps (mesh/boundary_tangents.h): a handful of singularities (174 on such a cap when the
// steps were read edge by edge) and a valid layout.
TEST(LayoutTopology, CapsCutThroughTrianglesAreValid) {
  for (double cut : {0.13, 0.31, -0.27}) {
    SCOPED_TRACE("cut at x = " + std::to_string(cut));
    const LayoutRun run = run_layout(faces_beyond(icosphere(4), cut));
    EXPECT_LE(run.input.param.singularities.size(), 10u);
    expect_valid(run);
  }
}

// The cut that left 3-cornered patches on the double torus (x > 0.3), and planes through the
// triangles of a torus and of the mechanical part (its sharp edges meeting the cut's staircase).
TEST(LayoutTopology, HandlebodiesCutThroughTrianglesAreValid) {
  struct Cut {
    const char* name;
    Mesh mesh;
  };
  const std::vector<Cut> cuts = {
      {"double torus, x > 0.3", faces_beyond(double_torus(), 0.3)},
      {"double torus, x > -0.2", faces_beyond(double_torus(), -0.2)},
      {"torus, x > 0.37", faces_beyond(torus(1, 0.35, 96, 40), 0.37)},
      {"mechanical part, x > 0.3", faces_beyond(mechanical_part(), 0.3)}};
  for (const Cut& cut : cuts) {
    SCOPED_TRACE(cut.name);
    expect_valid(run_layout(cut.mesh));
  }
}

// Annuli whose field has no singularity (it runs along both boundary loops): two regular boundary
// vertices stand in as nodes (ports.cpp, stand_in_nodes()), and their separatrices cut the annulus
// into two patches. Without them the layout was the annulus itself, no disk.
TEST(LayoutTopology, SingularityFreeAnnuliGetTwoPatches) {
  Mesh ring = torus(1, 0.35, 96, 40);  // the torus's upper part, z > 0.1, cut through triangles
  for (Eigen::Vector3d& p : ring.positions) std::swap(p.x(), p.z());
  const std::vector<Mesh> annuli = {open_cylinder(1, 2, 32, 8), faces_beyond(ring, 0.1)};
  for (const Mesh& annulus : annuli) {
    const LayoutRun run = run_layout(annulus);
    EXPECT_TRUE(run.input.param.singularities.empty());
    expect_valid(run);
    EXPECT_EQ(run.layout.check.patch_count, 2u);
    EXPECT_EQ(layout::layout_json(run.graph, run.layout)["stand_in_nodes"], 2);
  }
}

TEST(LayoutTopology, SameInputSameLayout) {
  const LayoutRun a = run_layout(thin_torus());
  const LayoutRun b = run_layout(thin_torus());
  nlohmann::ordered_json ja = layout::layout_json(a.graph, a.layout);
  nlohmann::ordered_json jb = layout::layout_json(b.graph, b.layout);
  ja.erase("seconds");
  jb.erase("seconds");
  EXPECT_EQ(ja, jb);
  EXPECT_EQ(a.layout.refined.mesh.face_attributes, b.layout.refined.mesh.face_attributes);
}

// The alpha slider on the thin torus's graph of the ports (its layout at alpha 5 takes a loop
// round): P1 solved again per alpha, with a ResolveCache or without (null).
class ThinTorusSlider : public ::testing::Test {
 protected:
  layout::QuadLayout solve(double alpha, layout::ResolveCache* cache) const {
    return layout::solve_layout(input_.charts(), graph_, alpha, matching::SolverKind::exact,
                                options_.limits, Progress(), cache);
  }
  bool presolve(double alpha, layout::ResolveCache& cache, double seconds = 60) const {
    Limits limits = options_.limits;
    limits.max_solve_seconds = seconds;
    return layout::presolve_layout(input_.charts(), graph_, alpha, matching::SolverKind::exact,
                                   limits, Progress(), cache);
  }

 private:
  const test::Parameterized input_ = test::parameterized(thin_torus());
  const layout::LayoutOptions options_{};
  const layout::LayoutGraph graph_ =
      layout::build_layout_graph(input_.charts(), options_, Progress());
};

// The slider's re-solves through one ResolveCache give the layouts of fresh solves; a matching laid
// out before (the failed first round, the last layout) is not laid out again.
TEST_F(ThinTorusSlider, AResolveCacheGivesTheLayoutsOfFreshSolves) {
  layout::ResolveCache cache;
  std::vector<int> reused;
  for (double alpha : {5.0, 5.0, 1.0, 5.0, 5.5}) {
    const layout::QuadLayout fresh = solve(alpha, nullptr);
    const layout::QuadLayout cached = solve(alpha, &cache);
    const std::string what = "alpha " + std::to_string(alpha);
    EXPECT_EQ(fresh.reused_rounds, 0) << what;
    EXPECT_EQ(cached.matching.edges, fresh.matching.edges) << what;
    EXPECT_EQ(cached.matching.objective, fresh.matching.objective) << what;
    EXPECT_EQ(cached.rounds(), fresh.rounds()) << what;
    EXPECT_EQ(cached.loop_rounds, fresh.loop_rounds) << what;
    EXPECT_EQ(cached.check.valid(), fresh.check.valid()) << what;
    EXPECT_EQ(cached.check.patch_count, fresh.check.patch_count) << what;
    EXPECT_EQ(cached.angle_rsd, fresh.angle_rsd) << what;
    EXPECT_EQ(cached.refined.mesh.face_attributes, fresh.refined.mesh.face_attributes) << what;
    reused.push_back(cached.reused_rounds);
  }
  ASSERT_GT(cache.failed.size(), 0u);  // the first round's loops around the tube
  EXPECT_EQ(reused[0], 0);
  EXPECT_EQ(reused[1], 2);  // both rounds of alpha 5: the failed one and the last layout
  EXPECT_NE(reused[2], 2);  // alpha 1 has another layout than alpha 5
  EXPECT_EQ(reused[3], 1);  // alpha 1's layout was last: only the failed round is known
}

// The page's worker presolves the slider's alphas when idle: a solve at a presolved alpha runs no
// round of P1 and gives the layout of a fresh solve; presolving keeps the last layout returned.
TEST_F(ThinTorusSlider, APresolvedAlphaIsLaidOutWithoutSolving) {
  layout::ResolveCache cache;
  const layout::QuadLayout first = solve(5.0, &cache);
  EXPECT_FALSE(presolve(1.0, cache, 1e-9));  // out of time: nothing kept, as it may differ
  EXPECT_TRUE(cache.solved.size() == 1 &&
              cache.solved.contains({matching::SolverKind::exact, 5.0}));
  for (double alpha : {1.0, 0.0, 20.0}) EXPECT_TRUE(presolve(alpha, cache));
  ASSERT_TRUE(cache.last);
  EXPECT_EQ(cache.last->alpha, 5.0);
  EXPECT_EQ(cache.last->matching.edges, first.matching.edges);
  EXPECT_FALSE(cache.solved.contains({matching::SolverKind::glpk, 1.0}));
  int most_rounds = 0;
  for (double alpha : {1.0, 0.0, 20.0, 5.0}) {
    const layout::QuadLayout fresh = solve(alpha, nullptr);
    const layout::QuadLayout presolved = solve(alpha, &cache);
    const std::string what = "alpha " + std::to_string(alpha);
    EXPECT_FALSE(fresh.solved_before) << what;
    EXPECT_TRUE(presolved.solved_before) << what;
    EXPECT_EQ(presolved.matching.edges, fresh.matching.edges) << what;
    EXPECT_EQ(presolved.matching.objective, fresh.matching.objective) << what;
    EXPECT_EQ(presolved.rounds(), fresh.rounds()) << what;
    EXPECT_GE(presolved.reused_rounds, fresh.rounds() - 1) << what;  // the failed rounds
    most_rounds = std::max(most_rounds, fresh.rounds());
    EXPECT_EQ(presolved.loop_rounds, fresh.loop_rounds) << what;
    EXPECT_EQ(presolved.check.valid(), fresh.check.valid()) << what;
    EXPECT_EQ(presolved.angle_rsd, fresh.angle_rsd) << what;
    EXPECT_EQ(presolved.refined.mesh.face_attributes, fresh.refined.mesh.face_attributes) << what;
  }
  EXPECT_EQ(most_rounds, 2);  // alpha 5's loop round: a presolve that solves in rounds
}

}  // namespace
}  // namespace tessera
