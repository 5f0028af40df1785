// linemap's extractor: the epsilon bound as a property (checked by brute
// force here), and hand-made maps with known answers.
#include "codec/lines/linemap_extractor.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "linemap/grid.h"
#include "linemap/lines.h"
#include "linemap/map_io.h"
#include "tests/codec/lines/test_maps.h"
#include "tests/testing/reference_geometry.h"
#include "tests/testing/test_support.h"

namespace linemap {
namespace {

using testing::DrawRoom;
using testing::FillBox;

LineExtractionOptions LinemapOptions(double epsilon) {
  LineExtractionOptions options;
  options.method = LineMethod::kLinemap;
  options.epsilon_cells = epsilon;
  return options;
}

// Sizes of the 8-connected components of the edge map, per cell (an
// independent flood written for the test).
std::vector<int> ComponentSizes(const EdgeMap& edges) {
  const int w = edges.width, h = edges.height;
  std::vector<int> label(w * h, -1), sizes;
  for (int seed = 0; seed < w * h; ++seed) {
    if (!edges.is_edge[seed] || label[seed] >= 0) continue;
    const int id = static_cast<int>(sizes.size());
    std::vector<int> stack = {seed};
    label[seed] = id;
    int size = 0;
    while (!stack.empty()) {
      const int i = stack.back();
      stack.pop_back();
      ++size;
      for (int dr = -1; dr <= 1; ++dr) {
        for (int dc = -1; dc <= 1; ++dc) {
          const int c = i % w + dc, r = i / w + dr;
          if (c < 0 || r < 0 || c >= w || r >= h) continue;
          if (edges.is_edge[r * w + c] && label[r * w + c] < 0) {
            label[r * w + c] = id;
            stack.push_back(r * w + c);
          }
        }
      }
    }
    sizes.push_back(size);
  }
  std::vector<int> per_cell(w * h, 0);
  for (int i = 0; i < w * h; ++i) per_cell[i] = label[i] >= 0 ? sizes[label[i]] : 0;
  return per_cell;
}

// Every edge cell is within epsilon of a segment, except the cells left to
// the furniture layer, which must all belong to small components: speckle
// (fewer than min_component_cells cells) or specks (at most
// speck_max_cells).
void ExpectBoundHolds(const LineExtraction& result, const LineExtractionOptions& options) {
  const EdgeMap& edges = result.edges;
  const std::vector<int> sizes = ComponentSizes(edges);
  ASSERT_EQ(result.left_to_blobs.size(), edges.is_edge.size());
  std::size_t left = 0;
  for (int row = 0; row < edges.height; ++row) {
    for (int col = 0; col < edges.width; ++col) {
      const int i = row * edges.width + col;
      if (!edges.is_edge[i]) {
        EXPECT_FALSE(result.left_to_blobs[i]);
        continue;
      }
      double best = std::numeric_limits<double>::infinity();
      for (const LineSegment& s : result.segments)
        best = std::min(best, testing::ReferencePointSegmentDistance(col, row, s));
      if (result.left_to_blobs[i]) {
        ++left;
        EXPECT_LE(sizes[i], std::max(options.min_component_cells - 1, options.speck_max_cells))
            << col << "," << row;
        EXPECT_GT(best, options.epsilon_cells) << col << "," << row;
      } else {
        EXPECT_LE(best, options.epsilon_cells + 1e-9) << col << "," << row;
      }
    }
  }
  EXPECT_EQ(left, result.cells_left_to_blobs);
}

TEST(LinemapBoundTest, HoldsOnRandomMaps) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 12; ++trial) {
    // Rooms and boxes with speckle: walls, corners, thin and thick parts.
    Grid grid(60 + 7 * trial, 45 + 5 * trial, Cell::kFree);
    std::uniform_int_distribution<int> col(0, grid.width() - 1), row(0, grid.height() - 1);
    for (int k = 0; k < 6; ++k) {
      const int c0 = col(rng), r0 = row(rng);
      FillBox(&grid, c0, r0, std::min(grid.width() - 1, c0 + col(rng) / 3),
              std::min(grid.height() - 1, r0 + 1 + trial % 3), Cell::kOccupied);
    }
    std::bernoulli_distribution speck(0.03);
    for (int r = 0; r < grid.height(); ++r) {
      for (int c = 0; c < grid.width(); ++c) {
        if (speck(rng)) grid.set(c, r, Cell::kOccupied);
      }
    }
    for (double epsilon : {0.5, 1.0, 2.0}) {
      const LineExtractionOptions options = LinemapOptions(epsilon);
      StatusOr<LineExtraction> result = ExtractLines(grid, options);
      ASSERT_TRUE(result.ok()) << result.status().message();
      ExpectBoundHolds(*result, options);
    }
  }
}

TEST(LinemapBoundTest, HoldsOnBundledMaps) {
  for (const char* name : {"/nav2/depot.yaml", "/navtut/lse_arena.yaml", "/strands/kth/map.yaml"}) {
    StatusOr<Grid> grid = LoadRosMap(testing::BundledMapsDir() + name);
    ASSERT_TRUE(grid.ok()) << name;
    const LineExtractionOptions options = LinemapOptions(1.0);
    StatusOr<LineExtraction> result = ExtractLines(*grid, options);
    ASSERT_TRUE(result.ok()) << name;
    ExpectBoundHolds(*result, options);
  }
}

// A room of free cells with a two-cell obstacle (a speck) in its middle,
// and, when `noisy`, lone obstacle cells (speckle) scattered far from the
// walls, as SLAM noise leaves them.
Grid RoomWithASpeck(bool noisy) {
  Grid grid(62, 42, Cell::kUnknown);
  DrawRoom(&grid, 1, 1, 60, 40);
  grid.set(30, 20, Cell::kOccupied);
  grid.set(31, 20, Cell::kOccupied);
  if (noisy) {
    for (int k = 0; k < 12; ++k) grid.set(8 + 4 * k, k % 2 == 0 ? 8 : 33, Cell::kOccupied);
  }
  return grid;
}

// True when a segment lies within 1 cell of the speck's cells.
bool SpeckHasASegment(const LineExtraction& result) {
  return std::any_of(result.segments.begin(), result.segments.end(), [](const LineSegment& s) {
    return testing::ReferencePointSegmentDistance(30, 20, s) <= 1 &&
           testing::ReferencePointSegmentDistance(31, 20, s) <= 1;
  });
}

TEST(LinemapExtractorTest, IsolatedSpeckGoesToTheFurnitureLayerOnANoisyMap) {
  // The speckle leaves a large mean distance (each lone cell ~7-12 cells
  // from the walls), so the distance budget lets the speck go: its two
  // cells are ~19 cells from the nearest wall, 38 cells of summed distance,
  // under speck_max_added_cells (64).
  StatusOr<LineExtraction> result = ExtractLines(RoomWithASpeck(true), LinemapOptions(1.0));
  ASSERT_TRUE(result.ok());
  EXPECT_FALSE(SpeckHasASegment(*result));
  EXPECT_EQ(result->segments.size(), 4u);
  const int width = result->edges.width;
  EXPECT_TRUE(result->left_to_blobs[20 * width + 30]);
  EXPECT_TRUE(result->left_to_blobs[20 * width + 31]);
  EXPECT_EQ(result->cells_left_to_blobs, 12u + 2u);
  ExpectBoundHolds(*result, LinemapOptions(1.0));

  // Off (as in StraightWalls), or with a price below its 38 cells, the
  // speck keeps its segment.
  LineExtractionOptions off = LinemapOptions(1.0);
  off.speck_max_cells = 0;
  result = ExtractLines(RoomWithASpeck(true), off);
  ASSERT_TRUE(result.ok());
  EXPECT_TRUE(SpeckHasASegment(*result));
  EXPECT_EQ(result->cells_left_to_blobs, 12u);
  LineExtractionOptions cheap = LinemapOptions(1.0);
  cheap.speck_max_added_cells = 30;
  result = ExtractLines(RoomWithASpeck(true), cheap);
  ASSERT_TRUE(result.ok());
  EXPECT_TRUE(SpeckHasASegment(*result));
}

TEST(LinemapExtractorTest, IsolatedSpeckKeepsItsSegmentOnACleanMap) {
  // Without speckle the walls are exact and the budget (0.05 cells per
  // edge cell, ~12 cells) is far below the speck's 38: it stays a segment.
  StatusOr<LineExtraction> result = ExtractLines(RoomWithASpeck(false), LinemapOptions(1.0));
  ASSERT_TRUE(result.ok());
  EXPECT_TRUE(SpeckHasASegment(*result));
  EXPECT_EQ(result->segments.size(), 5u);
  EXPECT_EQ(result->cells_left_to_blobs, 0u);
}

TEST(LinemapExtractorTest, SpeckTouchingAWallIsNotAFurnitureSpeck) {
  // A two-cell bump on the inside of a wall belongs to the wall's edge
  // component: never left to the furniture layer, whatever the budget.
  Grid grid = RoomWithASpeck(true);
  grid.set(30, 20, Cell::kFree);
  grid.set(31, 20, Cell::kFree);
  grid.set(30, 2, Cell::kOccupied);
  grid.set(31, 2, Cell::kOccupied);
  StatusOr<LineExtraction> result = ExtractLines(grid, LinemapOptions(1.0));
  ASSERT_TRUE(result.ok());
  const int width = result->edges.width;
  EXPECT_FALSE(result->left_to_blobs[2 * width + 30]);
  EXPECT_FALSE(result->left_to_blobs[2 * width + 31]);
  EXPECT_EQ(result->cells_left_to_blobs, 12u);
  ExpectBoundHolds(*result, LinemapOptions(1.0));
}

TEST(LinemapExtractorTest, RoomWithADoorGivesFourWalls) {
  // Room walls on the border of [1,40] x [1,30], a 10-cell doorway in the
  // bottom wall (cols 15-24), unknown outside. Four walls; the bottom wall
  // may come as its two sides of the door.
  Grid grid(42, 32, Cell::kUnknown);
  DrawRoom(&grid, 1, 1, 40, 30);
  FillBox(&grid, 15, 1, 24, 1, Cell::kFree);
  StatusOr<LineExtraction> result = ExtractLines(grid, LinemapOptions(1.0));
  ASSERT_TRUE(result.ok());
  const std::vector<LineSegment>& segments = result->segments;
  ASSERT_GE(segments.size(), 4u);
  ASSERT_LE(segments.size(), 5u);
  int top = 0, left = 0, right = 0, bottom = 0;
  for (const LineSegment& s : segments) {
    if (std::abs(s.y1 - 30) < 1e-6 && std::abs(s.y2 - 30) < 1e-6) ++top;
    if (std::abs(s.x1 - 1) < 1e-6 && std::abs(s.x2 - 1) < 1e-6) ++left;
    if (std::abs(s.x1 - 40) < 1e-6 && std::abs(s.x2 - 40) < 1e-6) ++right;
    if (std::abs(s.y1 - 1) < 1e-6 && std::abs(s.y2 - 1) < 1e-6) {
      ++bottom;
      // No segment crosses the doorway.
      EXPECT_TRUE(std::max(s.x1, s.x2) <= 14 + 1e-6 || std::min(s.x1, s.x2) >= 25 - 1e-6);
    }
  }
  EXPECT_EQ(top, 1);
  EXPECT_EQ(left, 1);
  EXPECT_EQ(right, 1);
  EXPECT_GE(bottom, 1);
  EXPECT_EQ(top + left + right + bottom, static_cast<int>(segments.size()));
}

TEST(LinemapExtractorTest, RoomWallsAreJoinedAtTheCorners) {
  // Walls on the border of [1,20] x [1,14], unknown outside: the corner cells
  // are not edge points, so the four wall segments end one cell short of
  // each corner; corner joining extends them to the corner cell centres.
  Grid grid(22, 16, Cell::kUnknown);
  DrawRoom(&grid, 1, 1, 20, 14);
  StatusOr<LineExtraction> result = ExtractLines(grid, LinemapOptions(1.0));
  ASSERT_TRUE(result.ok());
  ASSERT_EQ(result->segments.size(), 4u);
  auto has_end_at = [&](double x, double y) {
    int count = 0;
    for (const LineSegment& s : result->segments) {
      count += std::hypot(s.x1 - x, s.y1 - y) < 1e-6;
      count += std::hypot(s.x2 - x, s.y2 - y) < 1e-6;
    }
    return count;
  };
  EXPECT_EQ(has_end_at(1, 1), 2);
  EXPECT_EQ(has_end_at(20, 1), 2);
  EXPECT_EQ(has_end_at(1, 14), 2);
  EXPECT_EQ(has_end_at(20, 14), 2);
  LineExtractionOptions no_join = LinemapOptions(1.0);
  no_join.corner_join_cells = 0;
  StatusOr<LineExtraction> unjoined = ExtractLines(grid, no_join);
  ASSERT_TRUE(unjoined.ok());
  for (const LineSegment& s : unjoined->segments) {
    EXPECT_GT(std::hypot(s.x1 - 1, s.y1 - 1), 0.5);
    EXPECT_GT(std::hypot(s.x2 - 1, s.y2 - 1), 0.5);
  }
}

TEST(LinemapExtractorTest, RaggedWallGivesOneSegmentAtEpsilonOneAndAHalf) {
  // The obstacle fills rows 0..20 + j(col), j random in {-1, 0, 1}, across
  // the whole width; free above. Its edge map is the ragged top boundary,
  // within rows 19..21, so one horizontal segment on row 20 bounds it by 1.5.
  // Default options: the wall's own noise is forgiven (noise_merge_factor).
  std::mt19937 rng(3);
  std::uniform_int_distribution<int> jitter(-1, 1);
  Grid grid(80, 40, Cell::kFree);
  for (int col = 0; col < 80; ++col) FillBox(&grid, col, 0, col, 20 + jitter(rng), Cell::kOccupied);
  StatusOr<LineExtraction> result = ExtractLines(grid, LinemapOptions(1.5));
  ASSERT_TRUE(result.ok());
  ASSERT_EQ(result->segments.size(), 1u);
  const LineSegment& s = result->segments[0];
  const double angle = testing::SegmentAngleDeg(s);
  EXPECT_LT(std::min(angle, 180 - angle), 1.5);
  EXPECT_NEAR(std::min(s.x1, s.x2), 0, 1.0);
  EXPECT_NEAR(std::max(s.x1, s.x2), 79, 1.0);
  EXPECT_NEAR(0.5 * (s.y1 + s.y2), 20, 0.5);
  const double one_segment = MeasureLineFidelity(result->edges, result->segments).displ_ave_cells;

  // Without the noise forgiven, the distance budget keeps a few segments
  // that hug the wall, within the same bound.
  LineExtractionOptions hugging = LinemapOptions(1.5);
  hugging.noise_merge_factor = 0;
  StatusOr<LineExtraction> budgeted = ExtractLines(grid, hugging);
  ASSERT_TRUE(budgeted.ok());
  EXPECT_GE(budgeted->segments.size(), 2u);
  EXPECT_LE(budgeted->segments.size(), 8u);
  ExpectBoundHolds(*budgeted, hugging);
  EXPECT_LT(MeasureLineFidelity(budgeted->edges, budgeted->segments).displ_ave_cells,
            0.5 * one_segment);

  // StraightWalls (no budget) also draws the one centre line.
  StatusOr<LineExtraction> straight = ExtractLines(grid, StraightWalls(LinemapOptions(1.5)));
  ASSERT_TRUE(straight.ok());
  EXPECT_EQ(straight->segments.size(), 1u);
}

TEST(LinemapExtractorTest, RaggedWallsGiveOneSegmentForAlmostEveryJitter) {
  // The wall of RaggedWallGivesOneSegmentAtEpsilonOneAndAHalf under 30
  // jitters: the noise forgiveness must not hang on one lucky seed (29 of 30
  // give one segment, one gives two).
  int one_segment = 0;
  for (unsigned seed = 1; seed <= 30; ++seed) {
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int> jitter(-1, 1);
    Grid grid(80, 40, Cell::kFree);
    for (int col = 0; col < 80; ++col) {
      FillBox(&grid, col, 0, col, 20 + jitter(rng), Cell::kOccupied);
    }
    StatusOr<LineExtraction> result = ExtractLines(grid, LinemapOptions(1.5));
    ASSERT_TRUE(result.ok());
    ExpectBoundHolds(*result, LinemapOptions(1.5));
    EXPECT_LE(result->segments.size(), 2u) << "seed " << seed;
    one_segment += result->segments.size() == 1;
  }
  EXPECT_GE(one_segment, 28);
}

// The obstacle fills rows 0..5 + col / step across the width, free above (at
// least 5 rows): its edge map is a staircase of steps of `step` cells rising
// one row each.
Grid StaircaseGrid(int step) {
  constexpr int kWidth = 80;
  Grid grid(kWidth, 5 + (kWidth - 1) / step + 6, Cell::kFree);
  for (int col = 0; col < kWidth; ++col) {
    FillBox(&grid, col, 0, col, 5 + col / step, Cell::kOccupied);
  }
  return grid;
}

TEST(LinemapExtractorTest, StaircaseOfShortStepsGivesOneSlantedSegment) {
  // Merging steps of two cells costs less than free_merge_cost_cells each:
  // one segment along the slope, with the defaults and with StraightWalls.
  for (const LineExtractionOptions& options :
       {LinemapOptions(1.0), StraightWalls(LinemapOptions(1.0))}) {
    StatusOr<LineExtraction> result = ExtractLines(StaircaseGrid(2), options);
    ASSERT_TRUE(result.ok());
    ASSERT_EQ(result->segments.size(), 1u);
    const double angle = testing::SegmentAngleDeg(result->segments[0]);
    EXPECT_NEAR(std::min(angle, 180 - angle), std::atan(0.5) * 180 / std::acos(-1.0), 2.0);
    ExpectBoundHolds(*result, options);
  }
}

TEST(LinemapExtractorTest, StaircaseOfLongStepsKeepsItsStepsUnderTheDistanceBudget) {
  // Steps of four cells: merging two costs about two cells of summed
  // distance, above free_merge_cost_cells, so the map's distance budget
  // (nearly all of it left: the pieces fit exactly) decides: with the
  // defaults most steps keep their exact segment (a staircase has no noise
  // to forgive); without a budget the cost cap alone merges the staircase
  // into one slanted segment.
  const Grid grid = StaircaseGrid(4);
  const LineExtractionOptions steps = LinemapOptions(1.0);
  StatusOr<LineExtraction> budgeted = ExtractLines(grid, steps);
  ASSERT_TRUE(budgeted.ok());
  EXPECT_GE(budgeted->segments.size(), 10u);
  ExpectBoundHolds(*budgeted, steps);
  const LineFidelity kept = MeasureLineFidelity(budgeted->edges, budgeted->segments);
  EXPECT_LT(kept.displ_ave_cells, 0.1);  // about the 0.05-cell target

  LineExtractionOptions no_budget = steps;
  no_budget.target_mean_distance_cells = 0;
  no_budget.distance_growth_factor = 0;
  StatusOr<LineExtraction> merged = ExtractLines(grid, no_budget);
  ASSERT_TRUE(merged.ok());
  EXPECT_EQ(merged->segments.size(), 1u);
  ExpectBoundHolds(*merged, no_budget);
  EXPECT_GT(MeasureLineFidelity(merged->edges, merged->segments).displ_ave_cells,
            kept.displ_ave_cells);

  // StraightWalls draws the wall as one slanted segment.
  const LineExtractionOptions straight_options = StraightWalls(LinemapOptions(1.0));
  StatusOr<LineExtraction> straight = ExtractLines(grid, straight_options);
  ASSERT_TRUE(straight.ok());
  EXPECT_EQ(straight->segments.size(), 1u);
  ExpectBoundHolds(*straight, straight_options);
}

TEST(LinemapExtractorTest, SpeckleIsLeftToTheFurnitureLayerAndCounted) {
  // A straight wall and two isolated specks far from it: the specks are
  // components of one cell, below min_component_cells = 3.
  Grid grid(40, 20, Cell::kFree);
  FillBox(&grid, 5, 5, 34, 5, Cell::kOccupied);
  grid.set(10, 15, Cell::kOccupied);
  grid.set(30, 16, Cell::kOccupied);
  StatusOr<LineExtraction> result = ExtractLines(grid, LinemapOptions(1.0));
  ASSERT_TRUE(result.ok());
  ASSERT_EQ(result->segments.size(), 1u);
  EXPECT_EQ(result->cells_left_to_blobs, 2u);
  EXPECT_TRUE(result->left_to_blobs[15 * 40 + 10]);
  EXPECT_TRUE(result->left_to_blobs[16 * 40 + 30]);
}

}  // namespace
}  // namespace linemap
