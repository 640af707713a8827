// Tri(G): the isometries of the three geometries, and the polygon of every catalog map up to genus
// 29 (one disk, all open sides paired by an orientation-preserving isometry that carries one side
// onto the other).
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <numbers>

#include "base/error.h"
#include "regmap/catalog.h"
#include "regmap/conder_format.h"
#include "regmap/tiling_svg.h"
#include "regmap/triangle_tiling.h"

namespace tessera::regmap {
namespace {

const std::string kCatalogPath =
    std::string(TESSERA_SOURCE_DIR) + "/data/regmaps/catalog_g2-101.tsv";

constexpr double kTolerance = 1e-7;

// Isometries act projectively: equal up to the sign of (a, b).
bool same_isometry(const Isometry& f, const Isometry& g) {
  const double plus = std::abs(f.a - g.a) + std::abs(f.b - g.b);
  const double minus = std::abs(f.a + g.a) + std::abs(f.b + g.b);
  return f.reflects == g.reflects && std::min(plus, minus) < kTolerance;
}

Isometry power(Geometry geometry, const Isometry& f, int k) {
  Isometry result;
  for (int i = 0; i < k; ++i) result = compose(geometry, result, f);
  return result;
}

bool fixes(Geometry geometry, const Isometry& f, const Point& z) {
  return distance(geometry, apply(geometry, f, z), z) < kTolerance;
}

TEST(RegmapIsometry, GeneratorsSatisfyTheTriangleGroupRelations) {
  for (const auto& [p, q] : {std::pair{4, 3},
                             {3, 5},
                             {2, 7},
                             {4, 4},
                             {3, 6},
                             {6, 3},
                             {3, 7},
                             {5, 10},
                             {4, 404},
                             {12, 3}}) {
    const FundamentalTriangle d = fundamental_triangle(p, q);
    const Geometry g = d.geometry;
    const Isometry id;
    EXPECT_TRUE(same_isometry(power(g, d.r, p), id)) << p << "," << q;
    EXPECT_TRUE(same_isometry(power(g, d.s, q), id)) << p << "," << q;
    EXPECT_TRUE(same_isometry(power(g, d.t, 2), id)) << p << "," << q;
    EXPECT_TRUE(same_isometry(power(g, compose(g, d.r, d.s), 2), id)) << p << "," << q;
    EXPECT_TRUE(same_isometry(power(g, compose(g, d.r, d.t), 2), id)) << p << "," << q;
    EXPECT_TRUE(same_isometry(power(g, compose(g, d.s, d.t), 2), id)) << p << "," << q;
    // The reflections in the sides of D0 fix the side's corners: T in M N, T*S in N O, R*T in M O.
    const auto& c = d.corners;
    EXPECT_TRUE(fixes(g, d.t, c[kM]) && fixes(g, d.t, c[kN]));
    EXPECT_TRUE(fixes(g, compose(g, d.t, d.s), c[kN]) && fixes(g, compose(g, d.t, d.s), c[kO]));
    EXPECT_TRUE(fixes(g, compose(g, d.r, d.t), c[kM]) && fixes(g, compose(g, d.r, d.t), c[kO]));
    EXPECT_FALSE(fixes(g, compose(g, d.s, d.t), c[kO])) << "S*T is the other reflection at N";
    // The angle pi/p at M (the others follow from the orders of S and R*S above).
    EXPECT_NEAR(std::arg(to_plane(c[kO])), std::numbers::pi / p, 1e-12);
  }
}

TEST(RegmapIsometry, GeometryOfType) {
  EXPECT_EQ(geometry_of_type(4, 3), Geometry::Spherical);
  EXPECT_EQ(geometry_of_type(2, 100), Geometry::Spherical);
  EXPECT_EQ(geometry_of_type(4, 4), Geometry::Euclidean);
  EXPECT_EQ(geometry_of_type(6, 3), Geometry::Euclidean);
  EXPECT_EQ(geometry_of_type(3, 7), Geometry::Hyperbolic);
}

// Every open side is a map edge (N O), paired with its table neighbour's N O side by a
// sense-preserving isometry that maps corner to corner; the polygon is one disk.
void expect_valid_polygon(const FiniteGroup& group, const TriangleTiling& tiling,
                          const std::string& name) {
  const Geometry geometry = tiling.geometry();
  const PolygonShape shape = polygon_shape(tiling);
  EXPECT_EQ(shape.faces, group.order()) << name;
  EXPECT_EQ(shape.euler, 1) << name;
  EXPECT_EQ(shape.boundary_cycles, 1u) << name;
  EXPECT_EQ(2 * tiling.pairs.size(), shape.boundary_edges) << name;
  for (std::size_t g = 0; g < tiling.size(); ++g) {
    EXPECT_FALSE(tiling.open[g][index(Side::MN)] || tiling.open[g][index(Side::MO)]) << name;
  }
  for (const BoundaryPair& pair : tiling.pairs) {
    ASSERT_EQ(pair.side, Side::NO) << name;
    ASSERT_EQ(group.times(pair.second, side_word(pair.side)), pair.first) << name;
    EXPECT_FALSE(pair.pairing.reflects) << name;
    const auto& a = tiling.corners[static_cast<std::size_t>(pair.first)];
    const auto& b = tiling.corners[static_cast<std::size_t>(pair.second)];
    for (Corner k : side_corners(pair.side)) {
      EXPECT_LT(distance(geometry, apply(geometry, pair.pairing, b[k]), a[k]), 1e-6) << name;
    }
    EXPECT_NEAR(distance(geometry, a[kN], a[kO]), distance(geometry, b[kN], b[kO]), 1e-7) << name;
    EXPECT_GT(distance(geometry, a[kN], b[kN]) + distance(geometry, a[kO], b[kO]), 1e-3) << name;
  }
}

TEST(RegmapTiling, EveryCatalogMapUpToGenus29IsOnePairedPolygon) {
  std::size_t maps = 0, pairs = 0;
  double seconds = 0;
  for (const CatalogEntry& entry : read_catalog(kCatalogPath)) {
    if (entry.genus > 29) continue;
    const FiniteGroup group = enumerate_group(presentation_of(entry), Limits());
    const auto start = std::chrono::steady_clock::now();
    const TriangleTiling tiling = build_tiling(group);
    seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ASSERT_EQ(tiling.geometry(), Geometry::Hyperbolic);
    expect_valid_polygon(group, tiling, entry.name);
    pairs += tiling.pairs.size();
    ++maps;
  }
  EXPECT_EQ(maps, 573u);
  std::printf("[ tiling   ] %zu maps of genus 2-29 tiled in %.2f s, %zu boundary pairs checked\n",
              maps, seconds, pairs);
}

TEST(RegmapTiling, KleinQuarticPolygon) {
  const FiniteGroup group =
      enumerate_group(presentation_of(find_map(read_catalog(kCatalogPath), "R3.1")), Limits());
  const TriangleTiling tiling = build_tiling(group);
  expect_valid_polygon(group, tiling, "R3.1");
  // The root triangle is D0 itself, and 2p = 6 triangles meet at the origin.
  EXPECT_LT(std::abs(to_plane(tiling.corners[0][kM])), 1e-15);
  std::size_t at_origin = 0;
  for (const auto& c : tiling.corners) at_origin += std::abs(to_plane(c[kM])) < 1e-12;
  EXPECT_EQ(at_origin, 6u);
}

Presentation type(int p, int q, const std::string& relators) {
  return parse_conder_entry(
      "Type {" + std::to_string(p) + "," + std::to_string(q) + "}\n[ " + relators + " ]", "test");
}

TEST(RegmapTiling, PlatonicMapsCloseUpOnTheSphere) {
  for (const auto& [p, q] : {std::pair{4, 3}, {3, 5}, {2, 6}}) {
    const FiniteGroup group = enumerate_group(type(p, q, "T^2"), Limits());
    const TriangleTiling tiling = build_tiling(group);
    EXPECT_EQ(tiling.geometry(), Geometry::Spherical);
    EXPECT_TRUE(tiling.pairs.empty()) << p << "," << q;
    const PolygonShape shape = polygon_shape(tiling);
    EXPECT_EQ(shape.euler, 2) << p << "," << q;
    EXPECT_EQ(shape.boundary_edges, 0u);
  }
}

TEST(RegmapTiling, TorusMapIsAFundamentalDomainOfTranslations) {
  const FiniteGroup group = enumerate_group(type(4, 4, "(R * S^-1)^3"), Limits());
  const TriangleTiling tiling = build_tiling(group);
  EXPECT_EQ(tiling.geometry(), Geometry::Euclidean);
  expect_valid_polygon(group, tiling, "{4,4}_(3,0)");
  for (const BoundaryPair& pair : tiling.pairs) {
    // z -> (a z + b) / conj(a) is a translation when a / conj(a) = 1.
    EXPECT_NEAR(std::abs(pair.pairing.a / std::conj(pair.pairing.a) - 1.0), 0.0, 1e-9);
    EXPECT_GT(std::abs(pair.pairing.b), 1.0);  // by at least one edge (3 edges here)
  }
}

TEST(RegmapTiling, LargeGroupsHitTheTriangleLimit) {
  const FiniteGroup group =
      enumerate_group(presentation_of(find_map(read_catalog(kCatalogPath), "R3.1")), Limits());
  Limits limits;
  limits.max_tiling_triangles = 300;
  try {
    build_tiling(group, limits);
    ADD_FAILURE() << "no error";
  } catch (const LimitError& e) {
    EXPECT_NE(std::string(e.what()).find("--max-triangles"), std::string::npos) << e.what();
  }
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// One filled triangle per element, one numbered arrow per paired side (when large enough to
// carry one), the title escaped.
TEST(RegmapTiling, SvgOfR2_4) {
  const FiniteGroup group =
      enumerate_group(presentation_of(find_map(read_catalog(kCatalogPath), "R2.4")), Limits());
  const TriangleTiling tiling = build_tiling(group);
  const std::string svg = tiling_svg(group, tiling, "R2.4 <{5,10}>");
  EXPECT_NE(svg.find("<title>R2.4 &lt;{5,10}&gt;</title>"), std::string::npos);
  EXPECT_EQ(count(svg, "<polygon"), group.order() + 2 * tiling.pairs.size());
  EXPECT_EQ(count(svg, "<text"), 2 * tiling.pairs.size());
  for (std::size_t k = 1; k <= tiling.pairs.size(); ++k)
    EXPECT_EQ(count(svg, ">" + std::to_string(k) + "</text>"), 2u) << k;
}

TEST(RegmapTiling, SvgOfASphericalMapShowsEveryTriangle) {
  const FiniteGroup group = enumerate_group(type(4, 3, "T^2"), Limits());
  const std::string svg = tiling_svg(group, build_tiling(group), "cube");
  // Triangles across the equator are drawn in both hemispheres.
  EXPECT_GE(count(svg, "<polygon"), group.order());
  EXPECT_EQ(count(svg, "<circle"), 2u);
}

}  // namespace
}  // namespace tessera::regmap
