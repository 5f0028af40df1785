#include <gtest/gtest.h>

#include <vector>

#include "linemap/plan.h"
#include "tests/codec/plan/plan_test_util.h"

namespace linemap {
namespace {

using plan_test::FreeStepCounts;
using plan_test::GappedWallsGrid;
using plan_test::GridFromText;

SafeZone ZoneOf(const Grid& grid) { return ComputeSafeZone(grid, ImpassableAreaMask::Build(0.0)); }

TrajectoryRegion RegionOf(const SafeZone& zone, CellIndex start, CellIndex goal) {
  return MarkTrajectoryRegion(zone, RunLeeWave(zone, start, goal), goal);
}

TEST(TrajectoryRegionTest, CorridorBetweenTheEndsOnly) {
  const Grid grid = GridFromText({
      "##########",
      "..........",
      "##########",
  });
  const SafeZone zone = ZoneOf(grid);
  const TrajectoryRegion region = RegionOf(zone, {2, 1}, {7, 1});
  EXPECT_EQ(region.cell_count, 6u);
  for (int c = 0; c < 10; ++c) EXPECT_EQ(region.In(c, 1), c >= 2 && c <= 7) << c;
  // Ends have 7 virgin neighbours, inner corridor cells 6.
  EXPECT_EQ(region.virgin_neighbours[grid.Index(2, 1)], 7);
  EXPECT_EQ(region.virgin_neighbours[grid.Index(4, 1)], 6);
  EXPECT_EQ(region.virgin_neighbours[grid.Index(0, 1)], 0);
}

// On an open floor from (0,2) to (4,2) the cells of some shortest
// 8-connected path form the diamond |row - 2| <= min(col, 4 - col).
TEST(TrajectoryRegionTest, OpenFloorDiamond) {
  const Grid grid(5, 5, Cell::kFree);
  const TrajectoryRegion region = RegionOf(ZoneOf(grid), {0, 2}, {4, 2});
  const char* expected[5] = {
      // row 4 .. row 0
      "..#..", ".###.", "#####", ".###.", "..#..",
  };
  for (int r = 0; r < 5; ++r) {
    for (int c = 0; c < 5; ++c) {
      EXPECT_EQ(region.In(c, r), expected[4 - r][c] == '#') << c << "," << r;
    }
  }
  EXPECT_EQ(region.cell_count, 13u);
  EXPECT_EQ(region.virgin_neighbours[grid.Index(2, 4)], 5);  // the diamond's top corner
}

TEST(TrajectoryRegionTest, EmptyWhenUnreachable) {
  const Grid grid = GridFromText({
      "..#..",
      "..#..",
  });
  const TrajectoryRegion region = RegionOf(ZoneOf(grid), {0, 0}, {4, 0});
  EXPECT_EQ(region.cell_count, 0u);
}

// Against the definition, with two full searches written here: a cell is in
// the region iff dist(start, p) + dist(p, goal) == dist(start, goal).
TEST(TrajectoryRegionTest, MatchesTwoSidedDistanceDefinition) {
  const Grid grid = GappedWallsGrid();
  const SafeZone zone = ZoneOf(grid);
  const CellIndex start{0, 0}, goal{15, 5};
  const std::vector<int> ds = FreeStepCounts(grid, start), dg = FreeStepCounts(grid, goal);
  const int total = ds[grid.Index(goal.col, goal.row)];
  const TrajectoryRegion region = RegionOf(zone, start, goal);
  for (int r = 0; r < grid.height(); ++r) {
    for (int c = 0; c < grid.width(); ++c) {
      const std::size_t i = grid.Index(c, r);
      const bool on_path = ds[i] >= 0 && dg[i] >= 0 && ds[i] + dg[i] == total;
      EXPECT_EQ(region.In(c, r), on_path) << c << "," << r;
    }
  }
}

}  // namespace
}  // namespace linemap
