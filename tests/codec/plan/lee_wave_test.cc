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

TEST(LeeWaveTest, OpenFloorIndexIsTheChessboardDistance) {
  const Grid grid(9, 9, Cell::kFree);
  const LeeWave wave = RunLeeWave(ZoneOf(grid), {4, 4}, {8, 8});
  EXPECT_EQ(wave.goal_index, 4);
  EXPECT_EQ(wave.At(4, 4), 0);
  EXPECT_EQ(wave.At(5, 5), 1);
  EXPECT_EQ(wave.At(7, 5), 3);
  EXPECT_EQ(wave.At(0, 1), 4);
}

TEST(LeeWaveTest, GoesThroughTheGapAndDoesNotCutCorners) {
  // A wall with a one-cell gap at column 3; the diagonal squeeze between
  // the two '#' at the top right is forbidden.
  const Grid grid = GridFromText({
      ".....#.",
      "......#",
      "###.###",
      ".......",
  });
  const SafeZone zone = ZoneOf(grid);
  const LeeWave wave = RunLeeWave(zone, {0, 0}, {6, 3});
  // Along row 0 to (3,0) (index 3); the gap (3,1) only straight up from
  // there (index 4: the diagonals into it pass wall corners); then (3,2),
  // (4,2), (5,2); the goal (6,3) only by the forbidden squeeze.
  EXPECT_EQ(wave.At(3, 0), 3);
  EXPECT_EQ(wave.At(3, 1), 4);
  EXPECT_EQ(wave.At(4, 2), 6);
  EXPECT_EQ(wave.At(5, 2), 7);
  EXPECT_EQ(wave.goal_index, -1);
  EXPECT_EQ(wave.At(6, 3), -1);
}

TEST(LeeWaveTest, UnreachableGoalAndUnsafeEnds) {
  const Grid grid = GridFromText({
      "...#...",
      "...#...",
      "...#...",
  });
  const SafeZone zone = ZoneOf(grid);
  EXPECT_EQ(RunLeeWave(zone, {0, 0}, {6, 2}).goal_index, -1);
  EXPECT_EQ(RunLeeWave(zone, {3, 0}, {0, 0}).goal_index, -1);  // start in the wall
  EXPECT_EQ(RunLeeWave(zone, {1, 1}, {1, 1}).goal_index, 0);
}

// Against a full breadth-first search written here: the early stop keeps
// every index below the goal's exact and labels nothing above it.
TEST(LeeWaveTest, EarlyStopAgreesWithFullSearch) {
  const Grid grid = GappedWallsGrid();
  const SafeZone zone = ZoneOf(grid);
  const CellIndex start{0, 0}, goal{15, 5};
  const std::vector<int> full = FreeStepCounts(grid, start);
  const LeeWave wave = RunLeeWave(zone, start, goal);
  ASSERT_EQ(wave.goal_index, full[grid.Index(goal.col, goal.row)]);
  for (int r = 0; r < grid.height(); ++r) {
    for (int c = 0; c < grid.width(); ++c) {
      const int expected = full[grid.Index(c, r)];
      if (expected >= 0 && expected < wave.goal_index) {
        EXPECT_EQ(wave.At(c, r), expected);
      }
      if (expected > wave.goal_index) {
        EXPECT_EQ(wave.At(c, r), -1);
      }
    }
  }
}

}  // namespace
}  // namespace linemap
