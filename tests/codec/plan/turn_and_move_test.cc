#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <tuple>
#include <utility>
#include <vector>

#include "linemap/plan.h"
#include "tests/codec/plan/plan_test_util.h"

namespace linemap {
namespace {

using plan_test::GridFromText;
using plan_test::Pairs;
using plan_test::SampledSegmentSafe;

struct Planned {
  SafeZone zone;
  std::vector<CellTrajectory> trajectories;
};

Planned Generate(const Grid& grid, CellIndex start, CellIndex goal, double radius = 0.0,
                 double d_min = 0.0, double d_max = 20.0) {
  Planned p;
  p.zone = ComputeSafeZone(grid, ImpassableAreaMask::Build(radius));
  const LeeWave wave = RunLeeWave(p.zone, start, goal);
  const TrajectoryRegion region = MarkTrajectoryRegion(p.zone, wave, goal);
  GenerationOptions options;
  options.d_min_cells = d_min;
  p.trajectories =
      GenerateTrajectories(p.zone, wave, region, MoveTemplate::Build(d_max), start, goal, options);
  return p;
}

void ExpectAllSafe(const Planned& p, CellIndex start, CellIndex goal) {
  for (const CellTrajectory& t : p.trajectories) {
    ASSERT_GE(t.waypoints.size(), 1u);
    EXPECT_EQ(t.waypoints.front(), start);
    EXPECT_EQ(t.waypoints.back(), goal);
    double length = 0;
    for (std::size_t i = 1; i < t.waypoints.size(); ++i) {
      EXPECT_TRUE(SampledSegmentSafe(p.zone, t.waypoints[i - 1], t.waypoints[i]));
      length += std::hypot(t.waypoints[i].col - t.waypoints[i - 1].col,
                           t.waypoints[i].row - t.waypoints[i - 1].row);
    }
    EXPECT_NEAR(t.length_cells, length, 1e-9);
  }
  // Best first: fewest moves, then shortest, among those within
  // max_length_excess of the shortest; the longer ones after them, in the
  // same order.
  double shortest = 1e300;
  for (const CellTrajectory& t : p.trajectories) shortest = std::min(shortest, t.length_cells);
  const double too_long = (1.0 + GenerationOptions{}.max_length_excess) * shortest + 1e-9;
  const auto rank = [&](const CellTrajectory& t) {
    return std::make_tuple(t.length_cells > too_long, t.waypoints.size(), t.length_cells);
  };
  for (std::size_t i = 1; i < p.trajectories.size(); ++i) {
    EXPECT_LE(rank(p.trajectories[i - 1]), rank(p.trajectories[i]));
  }
}

TEST(GenerateTrajectoriesTest, StraightCorridorIsOneMove) {
  const Grid grid = GridFromText({
      "############",
      "#..........#",
      "############",
  });
  const Planned p = Generate(grid, {1, 1}, {10, 1});
  ASSERT_FALSE(p.trajectories.empty());
  EXPECT_EQ(Pairs(p.trajectories[0].waypoints),
            (std::vector<std::pair<int, int>>{{1, 1}, {10, 1}}));
  ExpectAllSafe(p, {1, 1}, {10, 1});
}

TEST(GenerateTrajectoriesTest, LShapedCorridorTurnsOnceAtTheCorner) {
  const Grid grid = GridFromText({
      "##########",
      "########.#",
      "########.#",
      "########.#",
      "########.#",
      "########.#",
      "########.#",
      "########.#",
      "#........#",
      "##########",
  });
  const Planned p = Generate(grid, {1, 1}, {8, 8});
  ASSERT_FALSE(p.trajectories.empty());
  EXPECT_EQ(Pairs(p.trajectories[0].waypoints),
            (std::vector<std::pair<int, int>>{{1, 1}, {8, 1}, {8, 8}}));
  EXPECT_DOUBLE_EQ(p.trajectories[0].length_cells, 14.0);
  EXPECT_FALSE(p.trajectories[0].straightened);
  ExpectAllSafe(p, {1, 1}, {8, 8});
}

// A square pillar straight between start and goal: going over it and going
// under it are equally short, and both must be returned.
TEST(GenerateTrajectoriesTest, ReturnsEquallyShortAlternatives) {
  const Grid grid = GridFromText({
      "...........",
      "...........",
      "....###....",
      "....###....",
      "....###....",
      "....###....",
      "....###....",
      "...........",
      "...........",
  });
  const CellIndex start{1, 4}, goal{9, 4};
  const Planned p = Generate(grid, start, goal);
  ASSERT_GE(p.trajectories.size(), 2u);
  ExpectAllSafe(p, start, goal);
  const std::size_t best_nodes = p.trajectories[0].waypoints.size();
  const double best_length = p.trajectories[0].length_cells;
  bool above = false, below = false;
  for (const CellTrajectory& t : p.trajectories) {
    if (t.waypoints.size() != best_nodes || std::abs(t.length_cells - best_length) > 1e-9) continue;
    for (const CellIndex& c : t.waypoints) {
      above = above || c.row > 6;
      below = below || c.row < 2;
    }
  }
  EXPECT_TRUE(above);
  EXPECT_TRUE(below);
  // The node queue itself (not only the straightened shortest paths) goes
  // both ways: Node_Max keeps mirror-image ties.
  bool queue_above = false, queue_below = false;
  for (const CellTrajectory& t : p.trajectories) {
    if (t.straightened) continue;
    for (const CellIndex& c : t.waypoints) {
      queue_above = queue_above || c.row > 6;
      queue_below = queue_below || c.row < 2;
    }
  }
  EXPECT_TRUE(queue_above);
  EXPECT_TRUE(queue_below);
}

TEST(GenerateTrajectoriesTest, NoTrajectoryWhenNoneExists) {
  const Grid grid = GridFromText({
      "....#....",
      "....#....",
      "....#....",
  });
  EXPECT_TRUE(Generate(grid, {0, 1}, {8, 1}).trajectories.empty());
  // Reachable only through a gap narrower than the safety radius.
  const Grid narrow = GridFromText({
      "...........",
      "...........",
      ".....#.....",
      "...........",
      "...........",
  });
  EXPECT_TRUE(Generate(narrow, {0, 2}, {10, 2}, 1.5).trajectories.empty());
}

TEST(GenerateTrajectoriesTest, StartEqualsGoal) {
  const Grid grid(4, 4, Cell::kFree);
  const Planned p = Generate(grid, {1, 1}, {1, 1});
  ASSERT_EQ(p.trajectories.size(), 1u);
  EXPECT_EQ(p.trajectories[0].waypoints.size(), 1u);
}

// With D_min longer than the corridor's legs no move can be generated; the
// fallback still returns a safe trajectory because the goal is reachable.
TEST(GenerateTrajectoriesTest, FallbackWhenDMinForbidsEveryMove) {
  const Grid grid = GridFromText({
      "######",
      "####.#",
      "####.#",
      "#....#",
      "######",
  });
  const Planned p = Generate(grid, {1, 1}, {4, 3}, 0.0, /*d_min=*/6.0);
  ASSERT_EQ(p.trajectories.size(), 1u);
  EXPECT_TRUE(p.trajectories[0].straightened);
  EXPECT_EQ(Pairs(p.trajectories[0].waypoints),
            (std::vector<std::pair<int, int>>{{1, 1}, {4, 1}, {4, 3}}));
  ExpectAllSafe(p, {1, 1}, {4, 3});
}

}  // namespace
}  // namespace linemap
