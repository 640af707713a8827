// The layout validity checker (core/layout/layout_check.h) on hand-made patch assignments of a flat
// grid: four quadrants are a valid layout; a T-junction, a ring, a split patch and a missing id are
// each found and named.
#include <gtest/gtest.h>

#include "layout/layout_check.h"
#include "layout_test_util.h"

namespace tessera {
namespace {

constexpr int kGrid = 6;

// The patch of each face of flat_grid(kGrid) from the cell it lies in.
template <typename Rule>
std::vector<std::int32_t> patches_by_cell(Rule rule) {
  std::vector<std::int32_t> patch;
  for (int j = 0; j < kGrid; ++j)
    for (int i = 0; i < kGrid; ++i) patch.insert(patch.end(), 2, rule(i, j));
  return patch;
}

bool mentions(const layout::LayoutCheck& check, const std::string& text) {
  for (const std::string& p : check.problems)
    if (p.find(text) != std::string::npos) return true;
  return false;
}

TEST(LayoutCheck, FourQuadrantsAreAValidLayout) {
  const Mesh grid = test::flat_grid(kGrid);
  const auto check = layout::check_layout(
      grid, patches_by_cell([](int i, int j) { return (i >= 3) + 2 * (j >= 3); }));
  EXPECT_TRUE(check.valid()) << (check.problems.empty() ? "" : check.problems[0]);
  EXPECT_EQ(check.patch_count, 4u);
  EXPECT_EQ(check.nodes.size(), 9u);  // centre, four boundary midpoints, four corners
  EXPECT_EQ(check.arcs.size(), 4u);
  for (const auto& corners : check.corners) EXPECT_EQ(corners.size(), 4u);
  for (const auto& sides : check.neighbours) {
    ASSERT_EQ(sides.size(), 4u);
    EXPECT_EQ(std::count(sides.begin(), sides.end(), -1), 2);
  }
}

TEST(LayoutCheck, TJunctionGivesAFifthCorner) {
  const Mesh grid = test::flat_grid(kGrid);
  const auto check = layout::check_layout(
      grid, patches_by_cell([](int i, int j) { return i < 3 ? 0 : 1 + (j >= 3); }));
  EXPECT_FALSE(check.valid());
  EXPECT_TRUE(mentions(check, "patch 0 has 5 corners"));
}

TEST(LayoutCheck, RingIsNotADisk) {
  const Mesh grid = test::flat_grid(kGrid);
  const auto check = layout::check_layout(grid, patches_by_cell([](int i, int j) {
                                            return (i >= 2 && i < 4 && j >= 2 && j < 4) ? 1 : 0;
                                          }));
  EXPECT_FALSE(check.valid());
  EXPECT_TRUE(mentions(check, "patch 0 is not a disk"));
}

TEST(LayoutCheck, SplitPatchAndMissingIdAreFound) {
  const Mesh grid = test::flat_grid(kGrid);
  const auto split = layout::check_layout(
      grid, patches_by_cell([](int i, int) { return i < 2 || i >= 4 ? 0 : 1; }));
  EXPECT_TRUE(mentions(split, "patch 0 is not a disk (2 pieces"));
  const auto missing =
      layout::check_layout(grid, patches_by_cell([](int i, int) { return i < 3 ? 0 : 2; }));
  EXPECT_TRUE(mentions(missing, "patch id 1 has no face"));
  EXPECT_FALSE(layout::check_layout(grid, std::vector<std::int32_t>(3, 0)).valid());
}

}  // namespace
}  // namespace tessera
