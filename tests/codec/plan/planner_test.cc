#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <queue>
#include <random>
#include <string>
#include <vector>

#include "linemap/map_io.h"
#include "linemap/plan.h"
#include "tests/codec/plan/plan_test_util.h"
#include "tests/testing/test_support.h"

namespace linemap {
namespace {

using plan_test::GridFromText;
using plan_test::SampledSegmentSafe;

// An L-shaped corridor drawn at 0.1 m per cell: free width 5 cells, so with
// d_save = 0.29 m (2.9 cells, CorridorRobot) only its centre line is safe:
// row 3 from column 3 to 28, and column 28 from row 3 to 23. (At 2.5 cells
// the inner corner would be chamfered: cell (27,4) is sqrt(8) cells from the
// corner obstacle (25,6).)
Grid LCorridor() {
  std::vector<std::string> lines(27, std::string(32, '#'));
  for (int r = 1; r <= 5; ++r) {
    for (int c = 1; c <= 30; ++c) lines[26 - r][c] = '.';
  }
  for (int r = 1; r <= 25; ++r) {
    for (int c = 26; c <= 30; ++c) lines[26 - r][c] = '.';
  }
  return GridFromText(lines, 0.1);
}

PlanOptions DefaultRobot() {
  PlanOptions o;
  o.robot = {0.4, 0.4, 0.05};  // d_save 0.25 m
  o.d_min_m = 0.1;
  o.d_max_m = 5.0;
  return o;
}

PlanOptions CorridorRobot() {
  PlanOptions o = DefaultRobot();
  o.robot.margin_m = 0.09;  // d_save 0.29 m
  return o;
}

PlanResult PlanOn(const Grid& grid, const PlanOptions& options, const PlanRequest& request) {
  StatusOr<Planner> planner = Planner::Create(options, grid.meta.resolution);
  EXPECT_TRUE(planner.ok()) << planner.status().ToString();
  StatusOr<PlanResult> result = planner->Plan(grid, request);
  EXPECT_TRUE(result.ok()) << result.status().ToString();
  return *result;
}

struct Cmd {
  char kind;
  double value;
};

void ExpectCommands(const PlannedTrajectory& t, const std::vector<Cmd>& expected) {
  ASSERT_EQ(t.commands.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(t.commands[i].kind == PlanCommand::Kind::kTurn ? 't' : 'm', expected[i].kind) << i;
    EXPECT_NEAR(t.commands[i].value, expected[i].value, 1e-9) << i;
  }
}

TEST(PlannerTest, LShapedCorridorOneTurn) {
  const Grid grid = LCorridor();
  // Cell (3,3) has its centre at (0.35, 0.35); cell (28,23) at (2.85, 2.35).
  const PlanResult r = PlanOn(grid, CorridorRobot(), {0.35, 0.35, 0.0, 2.85, 2.35});
  ASSERT_TRUE(r.found()) << r.message;
  ExpectCommands(r.trajectories[0], {{'m', 2.5}, {'t', 90.0}, {'m', 2.0}});
  EXPECT_NEAR(r.trajectories[0].length_m, 4.5, 1e-9);
  ASSERT_EQ(r.trajectories[0].waypoints.size(), 3u);
  EXPECT_NEAR(r.trajectories[0].waypoints[1].x, 2.85, 1e-9);
  EXPECT_NEAR(r.trajectories[0].waypoints[1].y, 0.35, 1e-9);
  EXPECT_NEAR(r.trajectories[0].waypoints[2].yaw, std::numbers::pi / 2, 1e-9);

  // Facing +y at the start: first turn right, then the corner turn left.
  const PlanResult up =
      PlanOn(grid, CorridorRobot(), {0.35, 0.35, std::numbers::pi / 2, 2.85, 2.35});
  ASSERT_TRUE(up.found());
  ExpectCommands(up.trajectories[0], {{'t', -90.0}, {'m', 2.5}, {'t', 90.0}, {'m', 2.0}});
  // The way back: facing -y at the goal end, the corner turn is to the right.
  const PlanResult back =
      PlanOn(grid, CorridorRobot(), {2.85, 2.35, -std::numbers::pi / 2, 0.35, 0.35});
  ASSERT_TRUE(back.found());
  ExpectCommands(back.trajectories[0], {{'m', 2.0}, {'t', -90.0}, {'m', 2.5}});
}

TEST(PlannerTest, DMaxSplitsLongMoves) {
  PlanOptions options = CorridorRobot();
  options.d_max_m = 1.0;
  const PlanResult r = PlanOn(LCorridor(), options, {0.35, 0.35, 0.0, 2.85, 2.35});
  ASSERT_TRUE(r.found());
  for (const PlanCommand& c : r.trajectories[0].commands) {
    if (c.kind == PlanCommand::Kind::kMove) {
      EXPECT_LE(c.value, 1.0 + 1e-9);
    }
  }
  EXPECT_NEAR(r.trajectories[0].length_m, 4.5, 1e-9);
}

TEST(PlannerTest, MapOriginIsApplied) {
  Grid grid = LCorridor();
  grid.meta.origin = {-1.0, 2.0, 0.0};
  const PlanResult r = PlanOn(grid, CorridorRobot(), {-0.65, 2.35, 0.0, 1.85, 4.35});
  ASSERT_TRUE(r.found()) << r.message;
  EXPECT_EQ(r.start_cell, (CellIndex{3, 3}));
  EXPECT_EQ(r.goal_cell, (CellIndex{28, 23}));
  EXPECT_NEAR(r.trajectories[0].waypoints[1].x, 1.85, 1e-9);
  EXPECT_NEAR(r.trajectories[0].waypoints[1].y, 2.35, 1e-9);
}

TEST(PlannerTest, ReportsBadStartsAndGoals) {
  Grid grid = LCorridor();
  grid.set(10, 3, Cell::kUnknown);  // blocks the horizontal arm
  const PlanOptions o = DefaultRobot();
  EXPECT_EQ(PlanOn(grid, o, {-0.5, 0.35, 0, 2.85, 2.35}).outcome, PlanOutcome::kStartOutsideMap);
  EXPECT_EQ(PlanOn(grid, o, {0.35, 0.35, 0, 2.85, 9.0}).outcome, PlanOutcome::kGoalOutsideMap);
  EXPECT_EQ(PlanOn(grid, o, {0.05, 0.05, 0, 2.85, 2.35}).outcome, PlanOutcome::kStartInObstacle);
  EXPECT_EQ(PlanOn(grid, o, {0.35, 0.35, 0, 1.05, 0.35}).outcome, PlanOutcome::kGoalInObstacle);
  EXPECT_EQ(PlanOn(grid, o, {0.15, 0.35, 0, 2.85, 2.35}).outcome, PlanOutcome::kStartUnsafe);
  const PlanResult r = PlanOn(grid, o, {0.35, 0.35, 0, 2.85, 2.35});
  EXPECT_EQ(r.outcome, PlanOutcome::kUnreachable);
  EXPECT_TRUE(r.trajectories.empty());
  EXPECT_FALSE(r.message.empty());
}

// A point exactly on the map's lower edge lies in cell 0 (each cell c holds
// [c - 0.5, c + 0.5) in cell units, as the edge map rounds); one on the upper
// edge is outside. Huge and non-finite points are outside, not undefined.
TEST(PlannerTest, MapEdgesBelongToTheCellsInside) {
  const Grid grid = GridFromText({"....", "....", "...."}, 0.5);  // 2 m x 1.5 m
  PlanOptions o;
  o.robot = {0.01, 0.01, 0.0};  // d_save 0.005 m: every free cell is safe
  o.d_min_m = 0.0;
  o.d_max_m = 5.0;
  const PlanResult corner = PlanOn(grid, o, {0.0, 0.0, 0, 1.25, 0.75});
  EXPECT_NE(corner.outcome, PlanOutcome::kStartOutsideMap) << corner.message;
  EXPECT_EQ(corner.start_cell, (CellIndex{0, 0}));
  const PlanResult goal_corner = PlanOn(grid, o, {1.25, 0.75, 0, 0.0, 0.0});
  EXPECT_NE(goal_corner.outcome, PlanOutcome::kGoalOutsideMap) << goal_corner.message;
  EXPECT_EQ(goal_corner.goal_cell, (CellIndex{0, 0}));
  EXPECT_EQ(PlanOn(grid, o, {-0.001, 0.0, 0, 1.25, 0.75}).outcome, PlanOutcome::kStartOutsideMap);
  EXPECT_EQ(PlanOn(grid, o, {2.0, 0.5, 0, 1.25, 0.75}).outcome, PlanOutcome::kStartOutsideMap);
  EXPECT_EQ(PlanOn(grid, o, {1.999, 1.499, 0, 0.25, 0.25}).start_cell, (CellIndex{3, 2}));
  EXPECT_EQ(PlanOn(grid, o, {1e300, 0.5, 0, 1.25, 0.75}).outcome, PlanOutcome::kStartOutsideMap);
  EXPECT_EQ(PlanOn(grid, o, {0.5, -1e300, 0, 1.25, 0.75}).outcome, PlanOutcome::kStartOutsideMap);
  EXPECT_EQ(PlanOn(grid, o, {0.5, 0.5, 0, std::nan(""), 0.75}).outcome,
            PlanOutcome::kGoalOutsideMap);
}

TEST(PlannerTest, RejectsBadOptions) {
  PlanOptions o = DefaultRobot();
  o.robot.width_m = 0;
  EXPECT_FALSE(Planner::Create(o, 0.05).ok());
  o = DefaultRobot();
  o.d_min_m = 6.0;
  EXPECT_FALSE(Planner::Create(o, 0.05).ok());
  o = DefaultRobot();
  EXPECT_FALSE(Planner::Create(o, 0.0).ok());
  EXPECT_FALSE(Planner::Create(o, 0.001).ok());  // D_max 5000 cells
  StatusOr<Planner> planner = Planner::Create(o, 0.05);
  ASSERT_TRUE(planner.ok());
  EXPECT_FALSE(planner->Plan(LCorridor(), {0.35, 0.35, 0, 2.85, 2.35}).ok());  // 0.1 m map
}

// ---------------------------------------------------------------------------
// Against an 8-connected A* on the same safe zone (octile costs, no corner
// cutting), written here from scratch.

struct AStarPath {
  bool found = false;
  double length = 0.0;  // cells
  std::size_t cells = 0;
};

AStarPath AStar(const SafeZone& zone, CellIndex s, CellIndex g) {
  const std::size_t n = zone.safe.size();
  const auto index = [&](int c, int r) { return static_cast<std::size_t>(r) * zone.width + c; };
  const auto h = [&](int c, int r) {
    const double dx = std::abs(c - g.col), dy = std::abs(r - g.row);
    return std::max(dx, dy) + (std::sqrt(2.0) - 1) * std::min(dx, dy);
  };
  std::vector<double> cost(n, 1e300);
  std::vector<int> parent(n, -1);
  std::vector<char> closed(n, 0);
  using Item = std::pair<double, std::size_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> open;
  cost[index(s.col, s.row)] = 0;
  open.push({h(s.col, s.row), index(s.col, s.row)});
  while (!open.empty()) {
    const std::size_t i = open.top().second;
    open.pop();
    if (closed[i]) continue;
    closed[i] = 1;
    const int c = static_cast<int>(i % zone.width), r = static_cast<int>(i / zone.width);
    if (c == g.col && r == g.row) break;
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        if (dx == 0 && dy == 0) continue;
        if (!zone.IsSafe(c + dx, r + dy)) continue;
        if (dx && dy && (!zone.IsSafe(c + dx, r) || !zone.IsSafe(c, r + dy))) continue;
        const std::size_t j = index(c + dx, r + dy);
        const double next = cost[i] + ((dx && dy) ? std::sqrt(2.0) : 1.0);
        if (next < cost[j] - 1e-12) {
          cost[j] = next;
          parent[j] = static_cast<int>(i);
          open.push({next + h(c + dx, r + dy), j});
        }
      }
    }
  }
  AStarPath path;
  const std::size_t goal = index(g.col, g.row);
  if (!closed[goal]) return path;
  path.found = true;
  path.length = cost[goal];
  for (int i = static_cast<int>(goal); i >= 0; i = parent[i]) ++path.cells;
  return path;
}

void CompareWithAStar(const std::string& yaml, int pairs, unsigned seed) {
  StatusOr<Grid> grid = LoadRosMap(yaml);
  ASSERT_TRUE(grid.ok()) << grid.status().ToString();
  const PlanOptions options = DefaultRobot();
  StatusOr<Planner> planner = Planner::Create(options, grid->meta.resolution);
  ASSERT_TRUE(planner.ok());
  const SafeZone zone = ComputeSafeZone(*grid, planner->mask());
  std::vector<CellIndex> safe;
  for (int r = 0; r < zone.height; ++r) {
    for (int c = 0; c < zone.width; ++c) {
      if (zone.IsSafe(c, r)) safe.push_back({c, r});
    }
  }
  ASSERT_FALSE(safe.empty());
  std::mt19937 rng(seed);
  std::uniform_int_distribution<std::size_t> pick(0, safe.size() - 1);
  int done = 0;
  for (int attempt = 0; attempt < 50 * pairs && done < pairs; ++attempt) {
    const CellIndex s = safe[pick(rng)], g = safe[pick(rng)];
    const AStarPath reference = AStar(zone, s, g);
    PlanRequest q;
    grid->CellToWorld(s.col, s.row, &q.start_x, &q.start_y);
    grid->CellToWorld(g.col, g.row, &q.goal_x, &q.goal_y);
    StatusOr<PlanResult> result = planner->Plan(*grid, q);
    ASSERT_TRUE(result.ok());
    ASSERT_EQ(result->found(), reference.found)
        << yaml << " " << s.col << "," << s.row << " -> " << g.col << "," << g.row;
    if (!reference.found || reference.cells < 20) continue;
    ++done;
    const PlannedTrajectory& best = result->trajectories.front();
    const double best_cells = best.length_m / grid->meta.resolution;
    EXPECT_LE(best_cells, 1.10 * reference.length)
        << yaml << " " << s.col << "," << s.row << " -> " << g.col << "," << g.row;
    const std::size_t moves = best.cells.size() - 1;
    EXPECT_LE(3 * moves, reference.cells) << yaml;
    for (const PlannedTrajectory& t : result->trajectories) {
      ASSERT_EQ(t.cells.front(), s);
      ASSERT_EQ(t.cells.back(), g);
      for (std::size_t i = 1; i < t.cells.size(); ++i) {
        ASSERT_TRUE(SampledSegmentSafe(zone, t.cells[i - 1], t.cells[i])) << yaml;
      }
    }
  }
  EXPECT_EQ(done, pairs) << yaml << ": not enough reachable pairs";
}

TEST(PlannerAgainstAStarTest, BundledMaps) {
  const std::string dir = testing::BundledMapsDir();
  CompareWithAStar(dir + "/navtut/lse_arena.yaml", 10, 1);
  CompareWithAStar(dir + "/nav2/depot.yaml", 10, 2);
  CompareWithAStar(dir + "/turtlebot_apps/willow-2010-02-18-0.10.yaml", 10, 3);
  CompareWithAStar(dir + "/strands/kth/map.yaml", 10, 4);
}

// Every map of ../shared/maps (skipped when absent): a few random pairs each.
TEST(PlannerAgainstAStarTest, SharedMaps) {
  const std::string dir = testing::SharedMapsDir();
  if (dir.empty()) GTEST_SKIP() << "../shared/maps is absent";
  unsigned seed = 100;
  for (const std::string& yaml : testing::FindYamlFiles(dir)) {
    if (!LoadRosMap(yaml).ok()) continue;  // a YAML naming a missing image
    CompareWithAStar(yaml, 3, seed++);
  }
}

}  // namespace
}  // namespace linemap
