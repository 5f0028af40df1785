#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "linemap/map_io.h"
#include "linemap/plan.h"
#include "tests/codec/plan/plan_test_util.h"
#include "tests/testing/test_support.h"

namespace linemap {
namespace {

using plan_test::BruteForceSafe;
using plan_test::GridFromText;

TEST(SafeDistanceTest, IsHalfTheLargerSidePlusMargin) {
  EXPECT_DOUBLE_EQ(SafeDistanceMetres({0.4, 0.6, 0.05}), 0.35);
  EXPECT_DOUBLE_EQ(SafeDistanceMetres({0.8, 0.2, 0.0}), 0.4);
}

TEST(ImpassableAreaMaskTest, HoldsTheIntegerDisk) {
  EXPECT_EQ(ImpassableAreaMask::Build(0.0).offsets.size(), 1u);
  EXPECT_EQ(ImpassableAreaMask::Build(1.0).offsets.size(), 5u);
  EXPECT_EQ(ImpassableAreaMask::Build(2.0).offsets.size(), 13u);
  // 0.15 m / 0.05 m is 2.9999999999999996 in floating point; the cells at
  // exactly 3 cells must still be inside. Counted by hand: 7 + 10 + 10 + 2.
  const ImpassableAreaMask mask = ImpassableAreaMask::Build(0.15 / 0.05);
  EXPECT_EQ(mask.offsets.size(), 29u);
  const auto has = [&](int dx, int dy) {
    return std::find(mask.offsets.begin(), mask.offsets.end(), CellOffset{dx, dy}) !=
           mask.offsets.end();
  };
  EXPECT_TRUE(has(3, 0));
  EXPECT_TRUE(has(0, -3));
  EXPECT_TRUE(has(2, 2));
  EXPECT_FALSE(has(3, 1));
}

// One obstacle in the middle of a 21 x 21 free map, radius 3 cells: the
// rule at its boundary, by hand.
TEST(SafeZoneTest, BoundaryOfTheRule) {
  Grid grid(21, 21, Cell::kFree);
  grid.set(10, 10, Cell::kOccupied);
  const SafeZone zone = ComputeSafeZone(grid, ImpassableAreaMask::Build(3.0));
  EXPECT_FALSE(zone.IsSafe(10, 10));
  EXPECT_FALSE(zone.IsSafe(13, 10));  // distance 3: within the circle
  EXPECT_TRUE(zone.IsSafe(14, 10));   // distance 4
  EXPECT_FALSE(zone.IsSafe(12, 12));  // distance^2 8
  EXPECT_TRUE(zone.IsSafe(13, 11));   // distance^2 10
  EXPECT_TRUE(zone.IsSafe(13, 12));   // distance^2 13
  // The map border counts as an obstacle just outside the map.
  EXPECT_FALSE(zone.IsSafe(2, 5));   // 3 cells from column -1
  EXPECT_TRUE(zone.IsSafe(3, 5));    // 4 cells
  EXPECT_FALSE(zone.IsSafe(18, 5));  // 3 cells from column 21
  EXPECT_TRUE(zone.IsSafe(17, 5));
  EXPECT_FALSE(zone.IsSafe(5, 20));
  EXPECT_FALSE(zone.IsSafe(-1, 5));  // outside the map is never safe
}

TEST(SafeZoneTest, UnknownCellsAreObstacles) {
  const Grid grid = GridFromText({
      ".......",
      ".......",
      "...?...",
      ".......",
      ".......",
  });
  const SafeZone zone = ComputeSafeZone(grid, ImpassableAreaMask::Build(1.0));
  EXPECT_FALSE(zone.IsSafe(3, 2));
  EXPECT_FALSE(zone.IsSafe(2, 2));
  EXPECT_FALSE(zone.IsSafe(3, 3));
  EXPECT_TRUE(zone.IsSafe(2, 3));  // diagonal: distance sqrt(2) > 1
}

TEST(SafeZoneTest, MatchesBruteForceOnABundledMap) {
  StatusOr<Grid> grid = LoadRosMap(testing::BundledMapsDir() + "/navtut/lse_arena.yaml");
  ASSERT_TRUE(grid.ok()) << grid.status().ToString();
  for (double radius : {0.0, 1.5, 2.0, 3.7}) {
    const SafeZone zone = ComputeSafeZone(*grid, ImpassableAreaMask::Build(radius));
    const std::vector<std::uint8_t> expected = BruteForceSafe(*grid, radius);
    ASSERT_EQ(zone.safe.size(), expected.size());
    std::size_t safe = 0;
    for (std::size_t i = 0; i < expected.size(); ++i) {
      ASSERT_EQ(zone.safe[i], expected[i]) << "radius " << radius << " cell " << i;
      safe += expected[i];
    }
    EXPECT_GT(safe, 0u) << "radius " << radius;
  }
}

}  // namespace
}  // namespace linemap
