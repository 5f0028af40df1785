// RM-Line (Liu & Zhang 2022) on hand-made maps with answers worked out by hand.
#include "codec/lines/rmline.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "linemap/grid.h"
#include "linemap/lines.h"
#include "tests/codec/lines/test_maps.h"

namespace linemap {
namespace {

using lines_internal::CellOffset;
using testing::DrawRoom;
using testing::FillBox;

LineExtractionOptions RmLineOptions() {
  LineExtractionOptions options;
  options.method = LineMethod::kRmLine;
  return options;
}

std::vector<LineSegment> RmLine(const Grid& grid) {
  StatusOr<LineExtraction> result = ExtractLines(grid, RmLineOptions());
  EXPECT_TRUE(result.ok()) << result.status().message();
  return result.ok() ? result->segments : std::vector<LineSegment>();
}

// True when `segments` holds a segment from (x1,y1) to (x2,y2) in either direction.
bool HasSegment(const std::vector<LineSegment>& segments, double x1, double y1, double x2,
                double y2) {
  const double tol = 1e-6;
  for (const LineSegment& s : segments) {
    const bool same = std::abs(s.x1 - x1) < tol && std::abs(s.y1 - y1) < tol &&
                      std::abs(s.x2 - x2) < tol && std::abs(s.y2 - y2) < tol;
    const bool swapped = std::abs(s.x1 - x2) < tol && std::abs(s.y1 - y2) < tol &&
                         std::abs(s.x2 - x1) < tol && std::abs(s.y2 - y1) < tol;
    if (same || swapped) return true;
  }
  return false;
}

EdgeMap EdgeMapOf(int width, int height, const std::vector<CellOffset>& cells) {
  EdgeMap edges;
  edges.width = width;
  edges.height = height;
  edges.is_edge.assign(static_cast<std::size_t>(width) * height, 0);
  for (const CellOffset& c : cells) edges.is_edge[c.drow * width + c.dcol] = 1;
  edges.edge_count = cells.size();
  return edges;
}

TEST(RmLineScreeningTest, TailPointsAreTheThreeCellsBeyondEachNeighbour) {
  // Written out from Figure 2 (offsets from the target p_t, row up): the
  // three cells of the 5x5 ring touching the neighbour, middle one straight on.
  const std::vector<std::vector<CellOffset>> expected = {
      {{2, -1}, {2, 0}, {2, 1}},       // p0 east
      {{2, 1}, {2, 2}, {1, 2}},        // p1 north-east
      {{1, 2}, {0, 2}, {-1, 2}},       // p2 north
      {{-1, 2}, {-2, 2}, {-2, 1}},     // p3 north-west
      {{-2, 1}, {-2, 0}, {-2, -1}},    // p4 west
      {{-2, -1}, {-2, -2}, {-1, -2}},  // p5 south-west
      {{-1, -2}, {0, -2}, {1, -2}},    // p6 south
      {{1, -2}, {2, -2}, {2, -1}},     // p7 south-east
  };
  const auto& neighbours = lines_internal::ScreeningNeighbours();
  const std::vector<CellOffset> expected_neighbours = {{1, 0},  {1, 1},   {0, 1},  {-1, 1},
                                                       {-1, 0}, {-1, -1}, {0, -1}, {1, -1}};
  for (int i = 0; i < 8; ++i) {
    EXPECT_EQ(neighbours[i], expected_neighbours[i]) << "p" << i;
    const auto tails = lines_internal::TailPoints(neighbours[i]);
    for (int j = 0; j < 3; ++j) {
      EXPECT_EQ(tails[j], expected[i][j]) << "tail p" << i << j;
    }
  }
}

TEST(RmLineScreeningTest, IsolatedPointAndContourEndAreInactive) {
  // Figure 3's cases on a 9 x 7 edge map:
  //  - (1,5) isolated;
  //  - (5,5)-(6,5): a two-cell contour, both ends without a tail;
  //  - (1,1)..(5,1): a straight contour; every cell has an edge neighbour with
  //    an edge tail (e.g. (1,1): p0 = (2,1), tail p01 = (3,1)), so all are active;
  //  - (7,2): touches (6,1) diagonally (p5), whose tails (5,1) is an edge: active.
  const EdgeMap edges = EdgeMapOf(
      9, 7, {{1, 5}, {5, 5}, {6, 5}, {1, 1}, {2, 1}, {3, 1}, {4, 1}, {5, 1}, {6, 1}, {7, 2}});
  const std::vector<std::uint8_t> active = lines_internal::ScreenActivePoints(edges);
  auto is_active = [&](int col, int row) { return active[row * 9 + col] != 0; };
  EXPECT_FALSE(is_active(1, 5));
  EXPECT_FALSE(is_active(5, 5));
  EXPECT_FALSE(is_active(6, 5));
  for (int col = 1; col <= 6; ++col) EXPECT_TRUE(is_active(col, 1)) << col;
  EXPECT_TRUE(is_active(7, 2));
  EXPECT_FALSE(is_active(0, 0));  // not an edge point at all
}

TEST(RmLineScreeningTest, NeighbourWithoutTailDoesNotActivate) {
  // An L-shaped stub: (2,2) with (3,2) east; (3,2)'s tails (4,1),(4,2),(4,3)
  // are empty, and (3,2)'s own neighbour (2,2) lies behind it, not beyond.
  const EdgeMap edges = EdgeMapOf(6, 5, {{2, 2}, {3, 2}});
  const std::vector<std::uint8_t> active = lines_internal::ScreenActivePoints(edges);
  EXPECT_EQ(std::count(active.begin(), active.end(), 1), 0);
}

TEST(RmLineRayTest, ScoresScoringPointsUntilTheStopPoint) {
  // Edge cells (0..4, 0). From (2,0) with ds 0.4 (0.4 keeps the scoring
  // points off the cell borders) along n = 0:
  //   forward x = 2, 2.4, 2.8, 3.2, 3.6, 4.0, 4.4 on edges, 4.8 -> cell 5 stops: 7;
  //   backward x = 2, 1.6, ..., -0.4 on edges, -0.8 -> cell -1 stops: 7.
  // Rays up to 12 degrees score 14 too (at 6 * 0.4 * sin 12 = 0.499 they are
  // still in row 0); ties keep the smallest n.
  const EdgeMap edges = EdgeMapOf(7, 3, {{0, 0}, {1, 0}, {2, 0}, {3, 0}, {4, 0}});
  const lines_internal::RayPair pair = lines_internal::CastBestRayPair(edges, 2, 0, 1.0, 0.4);
  EXPECT_EQ(pair.score, 14);
  EXPECT_EQ(pair.direction_index, 0);
  EXPECT_EQ(pair.cells, (std::vector<std::uint32_t>{0, 1, 2, 3, 4}));
}

TEST(RmLineRayTest, FindsTheDiagonal) {
  // Edge cells (k, k) for k = 0..5 and a decoy (3,2). From (2,2): the 45-degree
  // rays (n = 45) cover all six diagonal cells.
  const EdgeMap edges = EdgeMapOf(8, 8, {{0, 0}, {1, 1}, {2, 2}, {3, 3}, {4, 4}, {5, 5}, {3, 2}});
  const lines_internal::RayPair pair = lines_internal::CastBestRayPair(edges, 2, 2, 1.0, 0.5);
  EXPECT_EQ(pair.direction_index, 45);
  EXPECT_EQ(pair.cells, (std::vector<std::uint32_t>{0, 9, 18, 27, 36, 45}));
}

TEST(RmLineTest, StraightWallGivesOneSegmentThroughItsCells) {
  Grid grid(20, 7, Cell::kFree);
  FillBox(&grid, 2, 3, 17, 3, Cell::kOccupied);
  const std::vector<LineSegment> segments = RmLine(grid);
  ASSERT_EQ(segments.size(), 1u);
  EXPECT_TRUE(HasSegment(segments, 2, 3, 17, 3));
}

TEST(RmLineTest, RectangleRoomGivesFourWalls) {
  // Walls on the border of [1,20] x [1,14]; unknown outside. The corner cells
  // touch the free inside only diagonally, so they are not edge points.
  Grid grid(22, 16, Cell::kUnknown);
  DrawRoom(&grid, 1, 1, 20, 14);
  const std::vector<LineSegment> segments = RmLine(grid);
  ASSERT_EQ(segments.size(), 4u);
  EXPECT_TRUE(HasSegment(segments, 2, 1, 19, 1));
  EXPECT_TRUE(HasSegment(segments, 2, 14, 19, 14));
  EXPECT_TRUE(HasSegment(segments, 1, 2, 1, 13));
  EXPECT_TRUE(HasSegment(segments, 20, 2, 20, 13));
}

TEST(RmLineTest, ThirtyDegreeWallGivesOneSegmentAtThirtyDegrees) {
  // A digital 30-degree wall: the cells nearest to the points (4,3) + k*0.5*u,
  // u = (cos 30, sin 30), k = 0..80 (a 40-cell wall), free around. Some of
  // these points fall exactly on a cell border (y = 3.5, 4.5, ...), so the
  // step is computed in the same floating-point form as the ray's.
  Grid grid(48, 30, Cell::kFree);
  const double theta = 30 * 1.0 * std::numbers::pi / 180.0;
  const double step_col = 0.5 * std::cos(theta), step_row = 0.5 * std::sin(theta);
  for (int k = 0; k <= 80; ++k) {
    grid.set(static_cast<int>(std::floor(4 + k * step_col + 0.5)),
             static_cast<int>(std::floor(3 + k * step_row + 0.5)), Cell::kOccupied);
  }
  const std::vector<LineSegment> segments = RmLine(grid);
  ASSERT_EQ(segments.size(), 1u);
  EXPECT_NEAR(testing::SegmentAngleDeg(segments[0]), 30.0, 1.0);
  EXPECT_NEAR(testing::SegmentLength(segments[0]), 40.0, 1.5);
}

TEST(RmLineTest, SimulatedMapLikeFigure5) {
  // A simulated map in the spirit of the paper's Figure 5 (20 cm cells; the
  // figure's pixels are not in the text we have, so the map is drawn here):
  // a 30 x 20 room with one-cell walls and unknown outside, an L-shaped
  // one-cell partition (row 6, cols 8-16, and col 8, rows 7-12), a free-
  // standing partition (row 14, cols 18-26), an isolated speckle at (22,10)
  // and a two-cell stub (5,15)-(6,15). Expected by hand:
  //  - 4 room walls between the non-corner wall cells;
  //  - the L: raster order starts at its corner (8,6), whose longest ray runs
  //    along row 6 (9 cells against 7), then (8,7) takes column 8 down to the
  //    shared corner: 2 segments;
  //  - the free-standing partition: 1 segment;
  //  - speckle and stub are inactive (no tail points): no segment.
  Grid grid(32, 22, Cell::kUnknown);
  grid.meta.resolution = 0.2;
  DrawRoom(&grid, 1, 1, 30, 20);
  FillBox(&grid, 8, 6, 16, 6, Cell::kOccupied);
  FillBox(&grid, 8, 7, 8, 12, Cell::kOccupied);
  FillBox(&grid, 18, 14, 26, 14, Cell::kOccupied);
  grid.set(22, 10, Cell::kOccupied);
  grid.set(5, 15, Cell::kOccupied);
  grid.set(6, 15, Cell::kOccupied);
  LineExtractionOptions options = RmLineOptions();
  options.robot = CellPoint{5, 5};
  StatusOr<LineExtraction> result = ExtractLines(grid, options);
  ASSERT_TRUE(result.ok());
  const std::vector<LineSegment>& segments = result->segments;
  EXPECT_EQ(segments.size(), 7u);
  EXPECT_TRUE(HasSegment(segments, 2, 1, 29, 1));
  EXPECT_TRUE(HasSegment(segments, 2, 20, 29, 20));
  EXPECT_TRUE(HasSegment(segments, 1, 2, 1, 19));
  EXPECT_TRUE(HasSegment(segments, 30, 2, 30, 19));
  EXPECT_TRUE(HasSegment(segments, 8, 6, 16, 6));
  EXPECT_TRUE(HasSegment(segments, 8, 6, 8, 12));
  EXPECT_TRUE(HasSegment(segments, 18, 14, 26, 14));
  // Edge points counted by hand: room walls without corners 2*28 + 2*18 =
  // 92, the L 9 + 6, the partition 9, speckle 1, stub 2.
  EXPECT_EQ(result->edges.edge_count, 119u);
}

TEST(RmLineTest, RejectsBadParametersAndRobot) {
  Grid grid(10, 10, Cell::kFree);
  LineExtractionOptions options = RmLineOptions();
  options.rmline_dtheta_deg = 0;
  EXPECT_FALSE(ExtractLines(grid, options).ok());
  options = RmLineOptions();
  options.rmline_ds_cells = 2;
  EXPECT_FALSE(ExtractLines(grid, options).ok());
  options = RmLineOptions();
  options.robot = CellPoint{20, 3};
  EXPECT_EQ(ExtractLines(grid, options).status().code(), StatusCode::kInvalidArgument);
}

}  // namespace
}  // namespace linemap
