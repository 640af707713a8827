// The supergraph G of quad meshes built in code (thesis Sec. 7.3, 7.4) and the optimized layouts
// P1 gives over them (Sec. 7.5), checked by the project's layout checker.
#include <gtest/gtest.h>

#include <numeric>

#include "base/error.h"
#include "mesh/shapes.h"
#include "quadmesh/optimize_quads.h"
#include "quadmesh_test_util.h"

namespace tessera {
namespace {

using quadmesh::QuadGraph;
using quadmesh::QuadLayoutResult;

// A torus grid of n x m quads (vertex (i, j) is m i + j; 24 x 12 unless given) with the edge
// from (i, j) to (i + 1, j) rotated at each given i, j: every rotation plants two valence-3 and
// two valence-5 vertices side by side.
Mesh torus_with_rotated_edges(const std::vector<std::pair<int, int>>& at, int n = 24, int m = 12) {
  Mesh torus = quad_torus(3, 1, n, m);
  for (const auto& [i, j] : at)
    test::rotate_quad_edge(torus, Index(m * i + j), Index(m * (i + 1) + j));
  return torus;
}

QuadGraph graph_of(const Mesh& quads, bool diagonals = true) {
  quadmesh::SupergraphOptions options;
  options.diagonals = diagonals;
  return quadmesh::build_quad_graph(quads, options, Progress());
}

QuadLayoutResult optimize(const QuadGraph& graph, double alpha) {
  return quadmesh::optimize_quad_layout(graph, alpha, matching::SolverKind::exact, Limits(),
                                        Progress());
}

std::string first_problem(const QuadLayoutResult& r) {
  return r.check.problems.empty() ? "" : r.check.problems.front();
}

int valence_sum(const QuadGraph& graph) {
  int sum = 0;
  for (const Singularity& s : graph.charts.param.singularities) sum += s.valence;
  return sum;
}

// Every patch of a quad layout has four corners; the corners at a singularity are its valence,
// at a crossing of two arcs four: 4 F = sum of valences + 4 X, so F >= (sum of valences) / 4.
TEST(QuadmeshLayout, NearMissOnATorusIsClosedToTheCornerCountBound) {
  // Two clusters half the torus apart, the second one row off: their lines around the torus miss
  // each other by one edge (a near miss, Fig. 7.1), and B has twice the patches it needs.
  const QuadGraph graph = graph_of(torus_with_rotated_edges({{5, 4}, {17, 5}}));
  EXPECT_EQ(graph.charts.param.singularities.size(), 8u);
  EXPECT_EQ(graph.base.patch_count, 16u);
  EXPECT_TRUE(graph.base.check.valid());
  const QuadLayoutResult r = optimize(graph, 0);
  ASSERT_EQ(r.layout.matching.status, matching::SolveStatus::optimal);
  EXPECT_TRUE(r.check.valid()) << first_problem(r);
  EXPECT_EQ(r.check.patch_count, std::size_t(valence_sum(graph) / 4));
  EXPECT_EQ(r.check.patch_count, 8u);
  EXPECT_EQ(r.layout.check.patch_count, 8u);  // on the refined triangles as well
  EXPECT_GT(r.cut_quads, 0u);                 // the near misses are closed by slanted arcs
  // GLPK's plain model of P1 (the reference) agrees.
  const QuadLayoutResult reference =
      quadmesh::optimize_quad_layout(graph, 0, matching::SolverKind::glpk, Limits(), Progress());
  EXPECT_NEAR(reference.layout.matching.objective, r.layout.matching.objective, 1e-6);
  EXPECT_EQ(reference.check.patch_count, 8u);
}

TEST(QuadmeshLayout, AlignedClustersAreJoinedAlongTheirOwnLines) {
  const QuadGraph graph = graph_of(torus_with_rotated_edges({{5, 4}, {17, 4}}));
  EXPECT_EQ(graph.base.patch_count, 12u);
  const QuadLayoutResult r = optimize(graph, 0);
  EXPECT_TRUE(r.check.valid()) << first_problem(r);
  EXPECT_EQ(r.check.patch_count, 8u);
}

TEST(QuadmeshLayout, SupergraphHasTheSizesOfSection74) {
  const QuadGraph graph = graph_of(torus_with_rotated_edges({{5, 4}, {17, 5}}));
  const layout::PortGraph& g = graph.layout_graph.graph;
  // Sec. 7.4: sum of valences vertices; at most 4 |V_M| + |E_B| edges.
  EXPECT_EQ(g.port_count(), std::size_t(valence_sum(graph)));
  EXPECT_EQ(g.node_count(), g.port_count());  // closed: no virtual ports
  const std::size_t b_edges = graph.base.lines.size() / 2;
  EXPECT_EQ(graph.supergraph.separatrix_edges, b_edges);
  EXPECT_GT(g.edges.size(), b_edges);
  EXPECT_LE(g.edges.size(), 4 * graph.quads.vertex_count() + b_edges);
  EXPECT_GT(graph.supergraph.rejected_by_window, 0u);
  // Every diagonal edge is one of a zero-area pair or alone; the pairs are conflicts.
  for (const layout::EdgePair& pair : g.zero_area) {
    EXPECT_TRUE(g.edges[pair.first].diagonal && g.edges[pair.second].diagonal);
    EXPECT_TRUE(std::binary_search(g.conflicts.begin(), g.conflicts.end(), pair));
  }
}

TEST(QuadmeshLayout, WithoutDiagonalsNoEdgeHasEqualSides) {
  const QuadGraph graph = graph_of(torus_with_rotated_edges({{5, 4}, {17, 5}}), false);
  const layout::PortGraph& g = graph.layout_graph.graph;
  EXPECT_EQ(graph.supergraph.diagonal_edges, 0u);
  EXPECT_TRUE(g.zero_area.empty());
  for (const layout::GraphEdge& e : g.edges) EXPECT_NE(e.base, e.height);
  const QuadLayoutResult r = optimize(graph, 0);
  EXPECT_TRUE(r.check.valid()) << first_problem(r);
  EXPECT_LE(r.check.patch_count, graph.base.patch_count);
}

// Alpha 0 on one cluster: the cheapest matching of P1 leaves annuli (Lemma 5.1 assumes disks);
// the repair's pairs (quadmesh/repair.h) rule it out and the next round is valid.
TEST(QuadmeshLayout, AnnuliOfAFailedRoundAreRepaired) {
  const QuadGraph graph = graph_of(torus_with_rotated_edges({{5, 4}}));
  EXPECT_EQ(graph.base.patch_count, 6u);
  const QuadLayoutResult r = optimize(graph, 0);
  EXPECT_GE(r.layout.rounds(), 2);
  EXPECT_TRUE(r.check.valid()) << first_problem(r);
  EXPECT_LE(r.check.patch_count, graph.base.patch_count);
}

TEST(QuadmeshLayout, FlatGridWithARotatedEdgeUsesVirtualPorts) {
  Mesh grid = test::flat_quad_grid(8, 8);
  test::rotate_quad_edge(grid, 4 * 9 + 4, 5 * 9 + 4);
  const QuadGraph graph = graph_of(grid);
  const layout::PortGraph& g = graph.layout_graph.graph;
  std::size_t to_boundary = 0;
  for (const quadmesh::BaseLine& line : graph.base.lines)
    to_boundary += line.end == quadmesh::LineEnd::boundary;
  EXPECT_EQ(g.virtual_ports.size(), to_boundary);
  EXPECT_GT(to_boundary, 0u);
  EXPECT_TRUE(graph.base.check.valid());
  for (double alpha : {0.0, 5.0}) {
    const QuadLayoutResult r = optimize(graph, alpha);
    EXPECT_TRUE(r.check.valid()) << alpha << ": " << first_problem(r);
    EXPECT_LE(r.check.patch_count, graph.base.patch_count);
  }
}

// An L of 8 x 8 quads without its 4 x 4 corner: the concave corner (three quads on the boundary)
// sends two lines to the boundary, which P1 must keep (each port once; no other port to match):
// three rectangles, before and after.
TEST(QuadmeshLayout, ConcaveBoundaryCornerKeepsItsTwoLines) {
  Mesh l_shape = test::flat_quad_grid(8, 8, [](int i, int j) { return i >= 4 && j >= 4; });
  remove_unreferenced_vertices(l_shape);
  const QuadGraph graph = graph_of(l_shape);
  const layout::PortGraph& g = graph.layout_graph.graph;
  EXPECT_EQ(graph.charts.param.singularities.size(), 6u);  // five convex corners, one concave
  EXPECT_EQ(g.port_count(), 2u);
  EXPECT_EQ(g.virtual_ports.size(), 2u);
  EXPECT_EQ(graph.base.patch_count, 3u);
  const QuadLayoutResult r = optimize(graph, 5);
  EXPECT_TRUE(r.check.valid()) << first_problem(r);
  EXPECT_EQ(r.check.patch_count, 3u);
  EXPECT_EQ(r.cut_quads, 0u);
}

TEST(QuadmeshLayout, FlatGridIsOnePatch) {
  const QuadGraph graph = graph_of(test::flat_quad_grid(4, 6));
  const QuadLayoutResult r = optimize(graph, 5);
  EXPECT_EQ(graph.layout_graph.graph.port_count(), 0u);
  EXPECT_TRUE(r.check.valid()) << first_problem(r);
  EXPECT_EQ(r.check.patch_count, 1u);
  EXPECT_EQ(r.mesh.face_count(), 24u);  // every quad kept
  EXPECT_EQ(r.cut_quads, 0u);
}

TEST(QuadmeshLayout, LayoutOverQuadsKeepsTheQuadsNoArcCuts) {
  const Mesh quads = torus_with_rotated_edges({{5, 4}, {17, 5}});
  const QuadGraph graph = graph_of(quads);
  const QuadLayoutResult r = optimize(graph, 0);
  std::size_t kept = 0;
  for (std::size_t f = 0; f < r.mesh.face_count(); ++f) kept += r.mesh.face_size(f) == 4;
  EXPECT_EQ(kept, quads.face_count() - r.cut_quads);
  const std::vector<std::int32_t>& quad_of = r.mesh.face_attributes.at("quad");
  EXPECT_EQ(quad_of.size(), r.mesh.face_count());
  EXPECT_EQ(r.check.patch_count, r.layout.check.patch_count);
}

// 20,480 quads with eight clusters (32 irregular vertices): the figures of this run, as a
// regression; the bound of the corner count is 32 patches.
TEST(QuadmeshLayout, TwentyThousandQuadsWithEightClusters) {
  const QuadGraph graph = graph_of(torus_with_rotated_edges(
      {{10, 5}, {37, 90}, {71, 33}, {95, 120}, {120, 64}, {140, 10}, {20, 70}, {150, 100}}, 160,
      128));
  EXPECT_EQ(graph.quads.face_count(), 20480u);
  EXPECT_EQ(graph.base.patch_count, 384u);
  const QuadLayoutResult r5 = optimize(graph, 5);
  EXPECT_TRUE(r5.check.valid()) << first_problem(r5);
  EXPECT_EQ(r5.check.patch_count, 104u);
  const QuadLayoutResult r0 = optimize(graph, 0);
  EXPECT_TRUE(r0.check.valid()) << first_problem(r0);
  EXPECT_EQ(r0.check.patch_count, 48u);
}

TEST(QuadmeshLayout, GridTorusWithoutIrregularVertexIsRefused) {
  EXPECT_THROW(graph_of(quad_torus(3, 1, 12, 6)), InputError);
}

}  // namespace
}  // namespace tessera
