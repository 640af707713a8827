// Source maps drawn on target surfaces (thesis Sec. 9.5-9.6): the generated targets have the
// figures their names promise; every pairing the search returns satisfies the target's relators
// and generates a group of the target's order; a map drawn through a pairing has, on the built
// mesh, exactly the source's V, E, F with every face a disk, on a closed oriented surface of the
// source's genus.
#include <gtest/gtest.h>

#include <array>
#include <set>
#include <utility>

#include "base/error.h"
#include "regmap/catalog.h"
#include "regmap/mapped_map.h"
#include "regmap/pairing.h"
#include "regmap/target_maps.h"

namespace tessera::regmap {
namespace {

const std::string kCatalogPath =
    std::string(TESSERA_SOURCE_DIR) + "/data/regmaps/catalog_g2-101.tsv";

const Catalog& catalog() {
  static const Catalog parsed = read_catalog(kCatalogPath);
  return parsed;
}

TEST(RegmapTargets, GeneratedTargetsHaveTheirStatedFigures) {
  std::size_t checked = 0;
  for (const TargetMap& t : all_targets(catalog(), 9)) {
    if (t.kind == TargetKind::Catalog) continue;
    SCOPED_TRACE(t.name);
    const FiniteGroup group = enumerate_group(t.presentation, Limits());
    const MapFigures f = map_figures(group);
    EXPECT_EQ(f.vertices, t.vertices);
    EXPECT_EQ(f.edges, t.edges);
    EXPECT_EQ(f.faces, t.faces);
    EXPECT_TRUE(f.orientable);
    ++checked;
  }
  EXPECT_GT(checked, 20u);  // Platonic, hosohedra, torus maps
}

TEST(RegmapTargets, EveryTargetOfAGenusHasThatSurfaceGenus) {
  for (const TargetMap& t : all_targets(catalog(), 7)) {
    EXPECT_GE(t.surface_genus(), 2) << t.name;
    EXPECT_LE(t.surface_genus(), 7) << t.name;
    EXPECT_GE(t.valence(), 3) << t.name;
  }
  EXPECT_EQ(find_target(catalog(), "Cube").surface_genus(), 5);
  EXPECT_EQ(find_target(catalog(), "{4,4}_(2,0)").surface_genus(), 5);
  EXPECT_EQ(find_target(catalog(), "R2.1'").surface_genus(), 9);
  EXPECT_THROW(find_target(catalog(), "Cubeoctahedron"), InputError);
}

struct Drawn {
  FiniteGroup source;
  MapFigures figures;
  PairingSearch search;
};

Drawn search(const std::string& source, const std::string& target) {
  Drawn d;
  d.source = enumerate_group(presentation_of(find_map(catalog(), source)), Limits());
  d.figures = map_figures(d.source);
  const ElementWords words(d.source);
  const TargetMap t = find_target(catalog(), target);
  d.search = find_pairings(d.source, words, t.presentation, 4 * t.edges);
  return d;
}

// The pairing's images satisfy the target's relators under R = b c, S = c a, T = c, and the
// images of all of Sym(T) are distinct: phi is an isomorphism onto its image.
void expect_isomorphism(const Drawn& d, const std::string& target) {
  const ElementWords words(d.source);
  const TargetMap t = find_target(catalog(), target);
  const FiniteGroup tg = enumerate_group(t.presentation, Limits());
  for (const Pairing& p : d.search.pairings) {
    const std::vector<Element> phi = pairing_images(tg, words, p);
    EXPECT_EQ(std::set<Element>(phi.begin(), phi.end()).size(), tg.order());
    // phi(g x) = phi(g) image(x): R -> b c, R^-1 -> c b, S -> c a, S^-1 -> a c, T -> c.
    const std::array<std::pair<Element, Element>, kLetterCount> image = {
        {{p.b, p.c}, {p.c, p.b}, {p.c, p.a}, {p.a, p.c}, {p.c, 0}}};
    for (std::size_t g = 0; g < tg.order(); ++g) {
      for (int x = 0; x < kLetterCount; ++x) {
        const Element h = tg.times(static_cast<Element>(g), static_cast<Letter>(x));
        const auto [first, second] = image[static_cast<std::size_t>(x)];
        const Element expected = words.multiply(words.multiply(phi[g], first), second);
        EXPECT_EQ(phi[static_cast<std::size_t>(h)], expected);
      }
    }
    EXPECT_EQ(p.flags.size(), d.source.order() / tg.order());
  }
}

TEST(RegmapPairing, FindsReflectionPairingsThatAreIsomorphisms) {
  for (const auto& [source, target] :
       std::vector<std::pair<std::string, std::string>>{{"R3.4", "{4,4}_(1,1)"},
                                                        {"R5.3", "{4,4}_(2,0)"},
                                                        {"R2.2", "{2,3}"},
                                                        {"R3.6'", "{2,4}"}}) {
    SCOPED_TRACE(source + " on " + target);
    const Drawn d = search(source, target);
    ASSERT_FALSE(d.search.pairings.empty());
    EXPECT_FALSE(d.search.stopped);
    expect_isomorphism(d, target);
  }
}

// No three reflections of Sym(R9.3') realize the 2-Cube's quarter tube as a geodesic
// quadrilateral of its tiling (checked independently by enumerating all 16 algebraic triples
// with c fixed and every mirror line within distance 6); the search must not invent one.
TEST(RegmapPairing, ReportsNoReflectionPairingWhereNoneExists) {
  EXPECT_TRUE(search("R9.3'", "R2.1'").search.pairings.empty());
  EXPECT_TRUE(search("R3.1", "Tetrahedron").search.pairings.empty());
}

TEST(RegmapPairing, AWorkLimitStopsTheSearch) {
  const FiniteGroup source =
      enumerate_group(presentation_of(find_map(catalog(), "R5.3")), Limits());
  const ElementWords words(source);
  const TargetMap t = find_target(catalog(), "{4,4}_(2,0)");
  PairingLimits limits;
  limits.max_steps = 3;
  const PairingSearch s = find_pairings(source, words, t.presentation, 4 * t.edges, limits);
  EXPECT_TRUE(s.stopped);
  EXPECT_LE(s.steps, 3u + 64u);
}

void expect_drawn(const std::string& source, const std::string& target) {
  SCOPED_TRACE(source + " on " + target);
  const Drawn d = search(source, target);
  ASSERT_FALSE(d.search.pairings.empty());
  const ElementWords words(d.source);
  const TargetMap t = find_target(catalog(), target);
  const FiniteGroup tg = enumerate_group(t.presentation, Limits());
  const RegularSurface surface = build_regular_surface(t.presentation, tg);
  MappedMapOptions options;
  options.find_self_intersections = false;
  const MappedMap m = map_onto_surface(d.source, words, d.search.pairings[0], surface, options);
  const MappedMapStats& s = m.stats;
  EXPECT_EQ(s.vertices, d.figures.vertices);
  EXPECT_EQ(s.edges, d.figures.edges);
  EXPECT_EQ(s.faces, d.figures.faces);
  EXPECT_TRUE(s.faces_are_disks);
  EXPECT_TRUE(s.covers_once);
  EXPECT_TRUE(s.closed);
  EXPECT_TRUE(s.oriented);
  EXPECT_EQ(s.genus, d.figures.genus);
  EXPECT_EQ(m.mesh.face_attributes.at(kFaceAttribute).size(), m.mesh.face_count());
  EXPECT_FALSE(m.edge_segments.empty());
}

TEST(RegmapMappedMap, DrawsTheSourceWithItsFiguresOnTheTarget) {
  expect_drawn("R3.4", "{4,4}_(1,1)");
  expect_drawn("R5.3", "{4,4}_(2,0)");
  expect_drawn("R2.2", "{2,3}");
  expect_drawn("R3.6'", "{2,4}");
}

// A pairing found for one target does not glue on another target's surface of another size.
TEST(RegmapMappedMap, RefusesAPairingForAnotherSurface) {
  const Drawn d = search("R3.4", "{4,4}_(1,1)");
  ASSERT_FALSE(d.search.pairings.empty());
  const ElementWords words(d.source);
  const TargetMap other = find_target(catalog(), "Tetrahedron");
  const FiniteGroup tg = enumerate_group(other.presentation, Limits());
  const RegularSurface surface = build_regular_surface(other.presentation, tg);
  EXPECT_THROW(map_onto_surface(d.source, words, d.search.pairings[0], surface), Error);
}

}  // namespace
}  // namespace tessera::regmap
