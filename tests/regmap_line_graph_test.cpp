// Line(G) and the edge graph: the identification yields V nodes of valence q, E edges, a rotation
// system whose faces number F, counterclockwise in the polygon, with positions on the Jemisphere.
#include <gtest/gtest.h>

#include "base/error.h"
#include "regmap/catalog.h"
#include "regmap/conder_format.h"
#include "regmap/line_graph.h"

namespace tessera::regmap {
namespace {

using enum Letter;

const std::string kCatalogPath =
    std::string(TESSERA_SOURCE_DIR) + "/data/regmaps/catalog_g2-101.tsv";

void expect_edge_graph_of_map(const FiniteGroup& group, const std::string& name) {
  const MapFigures f = map_figures(group);
  const TriangleTiling tiling = build_tiling(group);
  const LineGraph line = build_line_graph(group, tiling);
  const EdgeGraph& graph = line.graph;
  ASSERT_EQ(graph.node_count, f.vertices) << name;
  ASSERT_EQ(graph.edge_count, f.edges) << name;
  ASSERT_EQ(graph.dart_element.size(), 2 * f.edges) << name;
  EXPECT_EQ(rotation_system_faces(graph), f.faces) << name;
  std::vector<int> valence(graph.node_count, 0), ends(graph.edge_count, 0);
  for (std::size_t d = 0; d < graph.dart_element.size(); ++d) {
    const auto o = static_cast<std::size_t>(graph.opposite[d]);
    EXPECT_NE(o, d) << name;
    EXPECT_EQ(static_cast<std::size_t>(graph.opposite[o]), d) << name;
    EXPECT_EQ(graph.dart_edge[o], graph.dart_edge[d]) << name;
    EXPECT_EQ(graph.dart_node[static_cast<std::size_t>(graph.next_around[d])], graph.dart_node[d]);
    ++valence[static_cast<std::size_t>(graph.dart_node[d])];
    ++ends[static_cast<std::size_t>(graph.dart_edge[d])];
    // Walking next_around from a dart returns after exactly q steps.
    std::size_t steps = 0;
    auto e = static_cast<std::int32_t>(d);
    do {
      e = graph.next_around[static_cast<std::size_t>(e)];
      ++steps;
    } while (static_cast<std::size_t>(e) != d && steps <= static_cast<std::size_t>(group.q));
    EXPECT_EQ(steps, static_cast<std::size_t>(group.q)) << name;
  }
  for (int v : valence) EXPECT_EQ(v, group.q) << name;
  for (int e : ends) EXPECT_EQ(e, 2) << name;
  // Each segment and its partner g*S^-1*T are the two sides of one half edge.
  for (std::size_t g = 0; g < group.order(); ++g) {
    const auto h = static_cast<std::size_t>(line.partner[g]);
    EXPECT_EQ(static_cast<std::size_t>(line.partner[h]), g) << name;
    EXPECT_EQ(line.node_of[h], line.node_of[g]) << name;
    EXPECT_EQ(line.edge_of[h], line.edge_of[g]) << name;
  }
}

TEST(RegmapLineGraph, CatalogMapsUpToGenus10) {
  std::size_t maps = 0;
  for (const CatalogEntry& entry : read_catalog(kCatalogPath)) {
    if (entry.genus > 10) continue;
    expect_edge_graph_of_map(enumerate_group(presentation_of(entry), Limits()), entry.name);
    expect_edge_graph_of_map(enumerate_group(presentation_of(dual(entry)), Limits()),
                             entry.name + "'");
    ++maps;
  }
  EXPECT_EQ(maps, 138u);
}

// Around the vertex N0 of the root triangle (inside the polygon), the darts g, g*S, g*S^2, ... have
// their edge midpoints in counterclockwise order.
TEST(RegmapLineGraph, RotationIsCounterclockwiseInThePolygon) {
  const FiniteGroup group =
      enumerate_group(presentation_of(find_map(read_catalog(kCatalogPath), "R3.1")), Limits());
  const TriangleTiling tiling = build_tiling(group);
  Element g = 0;
  const Complex n = to_plane(tiling.corners[0][kN]);
  for (int k = 0; k < group.q; ++k) {
    const Element next = group.times(g, S);
    const Complex a = to_plane(tiling.corners[static_cast<std::size_t>(g)][kO]) - n;
    const Complex b = to_plane(tiling.corners[static_cast<std::size_t>(next)][kO]) - n;
    EXPECT_GT((std::conj(a) * b).imag(), 0.0) << k;
    EXPECT_LT(std::abs(to_plane(tiling.corners[static_cast<std::size_t>(next)][kN]) - n), 1e-12);
    g = next;
  }
  EXPECT_EQ(g, 0);
}

TEST(RegmapLineGraph, NodesLieOnTheJemisphere) {
  const FiniteGroup group =
      enumerate_group(presentation_of(find_map(read_catalog(kCatalogPath), "R2.4")), Limits());
  const LineGraph line = build_line_graph(group, build_tiling(group));
  ASSERT_EQ(line.graph.node_count, 1u);
  for (const Vec3& v : line.graph.node_position) {
    EXPECT_NEAR(v.x * v.x + v.y * v.y + v.z * v.z, 1.0, 1e-12);
    EXPECT_GT(v.z, 0.0);  // the open upper hemisphere: the disk's inside
  }
  for (const Vec3& v : line.graph.edge_position) EXPECT_GT(v.z, 0.0);
}

TEST(RegmapLineGraph, TorusAndPlatonicMaps) {
  expect_edge_graph_of_map(
      enumerate_group(parse_conder_entry("Type {4,4}\n[ (R * S^-1)^4 ]", "torus"), Limits()),
      "{4,4}_(4,0)");
  expect_edge_graph_of_map(
      enumerate_group(parse_conder_entry("Type {5,3}\n[ T^2 ]", "d"), Limits()), "dodecahedron");
}

}  // namespace
}  // namespace tessera::regmap
