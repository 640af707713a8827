// Combing and the cut graph (core/field/cut_graph, Sec. 6.6): the cut opens every surface to a
// disk, passes through every singularity, has no dangling branches, and the combed field has no
// jump across the dual tree.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "field/cut_graph.h"
#include "field/design.h"
#include "mesh/shapes.h"
#include "param/wedges.h"

namespace tessera {
namespace {

struct Cut {
  Mesh mesh;
  Connectivity c;
  CrossField field;
  DualTree tree;
  CrossField combed;
  std::vector<std::uint8_t> cut;
};

Cut cut_open(Mesh mesh) {
  Cut r{std::move(mesh), {}, {}, {}, {}, {}};
  r.c = build_connectivity(r.mesh);
  const FaceFrames frames = face_frames(r.mesh);
  r.field = design_cross_field(r.mesh, r.c, frames, {}, Progress());
  r.tree = dual_spanning_tree(r.c, r.field);
  r.combed = comb(r.c, frames, r.field, r.tree);
  r.cut = cut_graph(r.c, r.combed, r.tree);
  return r;
}

std::vector<int> cut_degree(const Cut& r) {
  std::vector<int> degree(r.c.vertex_count(), 0);
  for (Index e = 0; e < r.c.edge_count(); ++e) {
    if (!r.cut[e]) continue;
    ++degree[r.c.from_vertex(r.c.edge_halfedge[e])];
    ++degree[r.c.to_vertex[r.c.edge_halfedge[e]]];
  }
  return degree;
}

void expect_disk_cut(const Cut& r) {
  // The mesh cut open has one vertex per wedge and one more edge per cut edge: a disk has
  // Euler characteristic 1.
  const Wedges wedges = cut_wedges(r.c, r.cut);
  std::size_t cut_edges = 0;
  for (std::uint8_t x : r.cut) cut_edges += x;
  EXPECT_EQ(static_cast<long>(wedges.count) - static_cast<long>(r.c.edge_count() + cut_edges) +
                static_cast<long>(r.mesh.face_count()),
            1);
  const std::vector<int> degree = cut_degree(r);
  for (Index v = 0; v < r.c.vertex_count(); ++v) {
    if (r.c.is_boundary_vertex(v)) continue;
    if (r.field.vertex_index[v] != 0)
      EXPECT_GE(degree[v], 1) << "singular vertex " << v;
    else
      EXPECT_NE(degree[v], 1) << "dangling branch at vertex " << v;
  }
  for (Index f = 0; f < r.mesh.face_count(); ++f) {
    const Index h = r.tree.parent_halfedge[f];
    if (h == kNoIndex) continue;
    EXPECT_EQ(r.c.face[r.c.twin[h]], f);
    EXPECT_EQ(r.combed.period_jump[h], 0) << "tree edge into face " << f;
    EXPECT_FALSE(r.cut[r.c.edge[h]]);
  }
  EXPECT_EQ(r.tree.order.size(), r.mesh.face_count());
}

TEST(CutGraph, OpensSurfacesToDisks) {
  expect_disk_cut(cut_open(icosphere(3)));
  expect_disk_cut(cut_open(torus(1.0, 0.4, 48, 16)));
  expect_disk_cut(cut_open(double_torus(2)));
  expect_disk_cut(cut_open(open_cylinder(1.0, 2.0, 32, 8)));
  expect_disk_cut(cut_open(mechanical_part(2)));
}

TEST(CutGraph, CombingKeepsTheFieldTopology) {
  const Cut r = cut_open(double_torus(2));
  EXPECT_EQ(r.combed.vertex_index, r.field.vertex_index);
  for (Index f = 0; f < r.mesh.face_count(); ++f) {
    // A representative turned by a multiple of 90 degrees: the same cross.
    const double turn = std::remainder(r.combed.angle[f] - r.field.angle[f], std::numbers::pi / 2);
    EXPECT_LT(std::abs(turn), 1e-12);
  }
}

TEST(CutGraph, SphereCutIsATreeThroughTheSingularities) {
  const Cut r = cut_open(icosphere(3));
  // On a sphere the cut graph is a tree whose leaves are singularities.
  const std::vector<int> degree = cut_degree(r);
  std::size_t edges = 0, vertices = 0;
  for (std::uint8_t x : r.cut) edges += x;
  for (int d : degree) vertices += d > 0;
  EXPECT_EQ(edges + 1, vertices);
}

}  // namespace
}  // namespace tessera
