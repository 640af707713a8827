// Every map of the shipped catalog enumerated natively and checked against its row.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>

#include "regmap/catalog.h"
#include "regmap/finite_group.h"

namespace tessera::regmap {
namespace {

const std::string kCatalogPath =
    std::string(TESSERA_SOURCE_DIR) + "/data/regmaps/catalog_g2-101.tsv";

TEST(RegmapCatalog, EveryRowEnumeratesToItsFigures) {
  const Catalog catalog = read_catalog(kCatalogPath);
  ASSERT_EQ(catalog.size(), 3378u);
  const auto start = std::chrono::steady_clock::now();
  std::size_t defined = 0, elements = 0;
  for (const CatalogEntry& entry : catalog) {
    EnumerationStats stats;
    const FiniteGroup group = enumerate_group(presentation_of(entry), Limits(), Progress(), &stats);
    const MapFigures f = map_figures(group);
    defined += stats.cosets_defined;
    elements += f.order;
    ASSERT_EQ(f.order, entry.order) << entry.name;
    EXPECT_EQ(f.vertices, entry.vertices) << entry.name;
    EXPECT_EQ(f.edges, entry.edges) << entry.name;
    EXPECT_EQ(f.faces, entry.faces) << entry.name;
    EXPECT_TRUE(f.orientable) << entry.name;
    EXPECT_EQ(f.genus, entry.genus) << entry.name;
    EXPECT_EQ(f.petrie, static_cast<std::size_t>(entry.petrie)) << entry.name;
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("[ figures  ] %zu catalog groups, %zu elements, %zu cosets defined, %.2f s\n",
              catalog.size(), elements, defined, seconds);
}

}  // namespace
}  // namespace tessera::regmap
