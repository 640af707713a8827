// Coset enumeration and the figures of a map: the thesis's maps, Platonic and torus maps, duals,
// and the limits that stop an infinite group.
#include <gtest/gtest.h>

#include <chrono>

#include "base/error.h"
#include "regmap/catalog.h"
#include "regmap/conder_format.h"
#include "regmap/finite_group.h"

namespace tessera::regmap {
namespace {

using enum Letter;

const std::string kCatalogPath =
    std::string(TESSERA_SOURCE_DIR) + "/data/regmaps/catalog_g2-101.tsv";

MapFigures figures_of(const Presentation& p, const Limits& limits = Limits()) {
  return map_figures(enumerate_group(p, limits));
}

Presentation type(int p, int q, const std::string& relators = "") {
  const std::string text = "Type {" + std::to_string(p) + "," + std::to_string(q) + "}\n[ " +
                           (relators.empty() ? "T^2" : relators) + " ]";
  return parse_conder_entry(text, "test");
}

TEST(RegmapGroup, KleinQuartic) {
  const Catalog catalog = read_catalog(kCatalogPath);
  const auto start = std::chrono::steady_clock::now();
  const MapFigures f = figures_of(presentation_of(find_map(catalog, "R3.1")));
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("[ figures  ] R3.1 enumerated and counted in %.4f s\n", seconds);
  EXPECT_EQ(f.order, 336u);
  EXPECT_EQ(f.vertices, 24u);
  EXPECT_EQ(f.edges, 84u);
  EXPECT_EQ(f.faces, 56u);
  EXPECT_EQ(f.genus, 3);
  EXPECT_EQ(f.petrie, 8u);
}

TEST(RegmapGroup, R2_4AndItsDual) {
  const Catalog catalog = read_catalog(kCatalogPath);
  const MapFigures f = figures_of(presentation_of(find_map(catalog, "R2.4")));
  EXPECT_EQ(f.order, 20u);
  EXPECT_EQ(f.vertices, 1u);
  EXPECT_EQ(f.edges, 5u);
  EXPECT_EQ(f.faces, 2u);
  EXPECT_EQ(f.genus, 2);
  const MapFigures d = figures_of(presentation_of(find_map(catalog, "R2.4'")));
  EXPECT_EQ(d.order, 20u);
  EXPECT_EQ(d.vertices, 2u);
  EXPECT_EQ(d.edges, 5u);
  EXPECT_EQ(d.faces, 1u);
  EXPECT_EQ(d.genus, 2);
}

// The dual's relators (R and S swapped) define the same group with V and F exchanged; the Petrie
// polygons of a map and its dual have the same length.
TEST(RegmapGroup, DualsSwapVerticesAndFaces) {
  std::size_t checked = 0;
  for (const CatalogEntry& entry : read_catalog(kCatalogPath)) {
    if (entry.genus > 12) continue;
    const MapFigures f = figures_of(presentation_of(dual(entry)));
    EXPECT_EQ(f.order, entry.order) << entry.name;
    EXPECT_EQ(f.vertices, entry.faces) << entry.name;
    EXPECT_EQ(f.faces, entry.vertices) << entry.name;
    EXPECT_EQ(f.genus, entry.genus) << entry.name;
    EXPECT_EQ(f.petrie, static_cast<std::size_t>(entry.petrie)) << entry.name;
    ++checked;
  }
  EXPECT_EQ(checked, 163u);
}

TEST(RegmapGroup, PlatonicSolids) {
  const struct {
    int p, q;
    std::size_t order, v, e, f;
  } solids[] = {{3, 3, 24, 4, 6, 4},     {4, 3, 48, 8, 12, 6},    {3, 4, 48, 6, 12, 8},
                {5, 3, 120, 20, 30, 12}, {3, 5, 120, 12, 30, 20}, {2, 5, 20, 2, 5, 5}};
  for (const auto& s : solids) {
    const MapFigures f = figures_of(type(s.p, s.q));
    EXPECT_EQ(f.order, s.order) << s.p << "," << s.q;
    EXPECT_EQ(f.vertices, s.v) << s.p << "," << s.q;
    EXPECT_EQ(f.edges, s.e) << s.p << "," << s.q;
    EXPECT_EQ(f.faces, s.f) << s.p << "," << s.q;
    EXPECT_EQ(f.genus, 0);
  }
}

// Cube from a presentation file in Conder's format, Petrie polygons of length 6 (the skew
// hexagons).
TEST(RegmapGroup, CubeFromPresentation) {
  const Presentation cube = parse_conder_entry(
      "Cube : Type {4,3}_6 Order 48\n[ T^2, R^4, S^3, (R * S)^2, (R * T)^2, (S * T)^2 ]", "cube");
  const MapFigures f = figures_of(cube);
  EXPECT_NO_THROW(check_stated_figures(cube, f));
  EXPECT_EQ(f.vertices, 8u);
  EXPECT_EQ(f.edges, 12u);
  EXPECT_EQ(f.faces, 6u);
  EXPECT_EQ(f.petrie, 6u);
}

// R*S^-1 translates by one edge in {4,4} (rotations by +90 and -90 degrees), so (R*S^-1)^b = 1 is
// the torus map {4,4}_(b,0) with b^2 vertices; in {3,6}, R*S^-2 is a translation likewise.
TEST(RegmapGroup, TorusMaps) {
  const MapFigures square = figures_of(type(4, 4, "(R * S^-1)^3"));
  EXPECT_EQ(square.order, 72u);
  EXPECT_EQ(square.vertices, 9u);
  EXPECT_EQ(square.edges, 18u);
  EXPECT_EQ(square.faces, 9u);
  EXPECT_EQ(square.genus, 1);
  const MapFigures hex = figures_of(type(3, 6, "(R * S^-2)^4"));
  EXPECT_EQ(hex.euler, 0);
  EXPECT_EQ(hex.genus, 1);
  EXPECT_EQ(hex.faces, 2 * hex.vertices);
}

TEST(RegmapGroup, InfiniteGroupHitsTheTableLimit) {
  Limits limits;
  limits.max_coset_table = 100'000;
  for (const auto& [p, q] : {std::pair{3, 7}, {4, 4}, {3, 6}}) {
    const auto start = std::chrono::steady_clock::now();
    try {
      enumerate_group(type(p, q), limits);
      ADD_FAILURE() << "{" << p << "," << q << "} enumerated";
    } catch (const LimitError& e) {
      EXPECT_NE(std::string(e.what()).find("--max-cosets"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("infinite"), std::string::npos) << e.what();
    }
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
              limits.max_coset_seconds);
  }
}

TEST(RegmapGroup, InfiniteGroupHitsTheTimeLimit) {
  Limits limits;
  limits.max_coset_seconds = 0.2;
  const auto start = std::chrono::steady_clock::now();
  try {
    enumerate_group(type(3, 7), limits);
    ADD_FAILURE() << "{3,7} enumerated";
  } catch (const LimitError& e) {
    // Whichever limit comes first on this machine names its own flag.
    const std::string what = e.what();
    EXPECT_TRUE(what.find("--max-seconds") != std::string::npos ||
                what.find("--max-cosets") != std::string::npos)
        << what;
  }
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 1.0);
}

TEST(RegmapGroup, CollapsingRelatorsAreReported) {
  try {
    figures_of(type(3, 7, "S"));
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("of order 1 instead of"), std::string::npos) << e.what();
  }
}

TEST(RegmapGroup, StatedFiguresAreChecked) {
  Presentation wrong = type(4, 3);
  wrong.stated_order = 50;
  EXPECT_THROW(check_stated_figures(wrong, figures_of(wrong)), InputError);
  wrong.stated_order = 48;
  wrong.stated_petrie = 5;
  EXPECT_THROW(check_stated_figures(wrong, figures_of(wrong)), InputError);
}

TEST(RegmapGroup, TableIsTheRegularRepresentation) {
  const FiniteGroup g = enumerate_group(type(3, 7, "(R * S^-1 * S^-1 * R * S^-1 * S^-1)^4"),
                                        Limits());  // not required to be the quartic
  for (Element e = 0; e < static_cast<Element>(g.order()); ++e) {
    EXPECT_EQ(g.times(g.times(e, R), Ri), e);
    EXPECT_EQ(g.times(g.times(e, S), Si), e);
    EXPECT_EQ(g.times(g.times(e, T), T), e);
    EXPECT_EQ(g.times(e, Word{R, S, R, S}), e);
  }
}

}  // namespace
}  // namespace tessera::regmap
