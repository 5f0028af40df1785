#include "linemap/grid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace linemap {
namespace {

TEST(GridTest, CountsEachState) {
  Grid grid(3, 2, Cell::kUnknown);
  grid.set(0, 0, Cell::kFree);
  grid.set(1, 0, Cell::kFree);
  grid.set(2, 1, Cell::kOccupied);
  const CellCounts counts = grid.Count();
  EXPECT_EQ(counts.free, 2u);
  EXPECT_EQ(counts.occupied, 1u);
  EXPECT_EQ(counts.unknown, 3u);
}

TEST(GridTest, RowZeroIsAtTheOrigin) {
  Grid grid(4, 3);
  grid.meta.resolution = 0.5;
  grid.meta.origin = {10.0, -2.0, 0.0};
  double x = 0, y = 0;
  grid.CellToWorld(0, 0, &x, &y);
  EXPECT_DOUBLE_EQ(x, 10.25);
  EXPECT_DOUBLE_EQ(y, -1.75);
  grid.CellToWorld(3, 2, &x, &y);
  EXPECT_DOUBLE_EQ(x, 11.75);
  EXPECT_DOUBLE_EQ(y, -0.75);
}

TEST(GridTest, WorldToCellInvertsCellToWorldWithYaw) {
  Grid grid(10, 10);
  grid.meta.resolution = 0.1;
  grid.meta.origin = {1.0, 2.0, 0.7};
  double x = 0, y = 0, col = 0, row = 0;
  grid.CellToWorld(3.25, 7.5, &x, &y);
  grid.WorldToCell(x, y, &col, &row);
  EXPECT_NEAR(col, 3.25, 1e-12);
  EXPECT_NEAR(row, 7.5, 1e-12);
}

// The decimal text of (hundredths / 100) metres: "-6.90", "0.05".
std::string Hundredths(int hundredths) {
  char text[32];
  const int magnitude = hundredths < 0 ? -hundredths : hundredths;
  std::snprintf(text, sizeof(text), "%s%d.%02d", hundredths < 0 ? "-" : "", magnitude / 100,
                magnitude % 100);
  return text;
}

// A point on a cell's left or lower edge is in that cell, as typed in
// decimal: kth's frame (origin -7, -17.5, 0.05 m/cell), where the left edge
// of column k is -7 + 0.05 k m, written here from whole hundredths and read
// as a user's text is. Plain division put 24 of these 60 edges in column
// k - 1 (-6.90 m at 1.4999999999999929 cells). Rows alike, from -17.5 m.
// A point a micrometre left of (below) an edge is in the cell before.
TEST(GridTest, PointOnACellsLeftOrLowerEdgeTypedInDecimalIsInThatCell) {
  MapMetadata meta;
  meta.resolution = 0.05;
  meta.origin = {-7.0, -17.5, 0.0};
  int were_off = 0;
  for (int k = 0; k < 60; ++k) {
    const std::string x_text = Hundredths(-700 + 5 * k), y_text = Hundredths(-1750 + 5 * k);
    const double x = std::strtod(x_text.c_str(), nullptr);
    const double y = std::strtod(y_text.c_str(), nullptr);
    SCOPED_TRACE(x_text + "," + y_text);
    const std::optional<CellIndex> cell = CellHoldingPoint(meta, 260, 781, x, y);
    ASSERT_TRUE(cell.has_value());
    EXPECT_EQ(cell->col, k);
    EXPECT_EQ(cell->row, k);
    were_off += std::floor((x - meta.origin.x) / meta.resolution) != k;
    if (k > 0) {
      const std::optional<CellIndex> before = CellHoldingPoint(meta, 260, 781, x - 1e-6, y - 1e-6);
      ASSERT_TRUE(before.has_value());
      EXPECT_EQ(before->col, k - 1);
      EXPECT_EQ(before->row, k - 1);
    }
  }
  EXPECT_EQ(were_off, 24) << "plain division no longer shows the case";
  // -6.9 m, -17.175 m: column 2's left edge, row 6's middle (a point on kth's map).
  const std::optional<CellIndex> audit = CellHoldingPoint(meta, 260, 781, -6.9, -17.175);
  ASSERT_TRUE(audit.has_value());
  EXPECT_EQ(audit->col, 2);
  EXPECT_EQ(audit->row, 6);
  // The right edge is the next cell's left one; the map's own right edge is
  // off the map.
  EXPECT_EQ(CellHoldingPoint(meta, 260, 781, -6.95, -17.5)->col, 1);
  EXPECT_FALSE(CellHoldingPoint(meta, 260, 781, 6.0, -17.5).has_value());
  EXPECT_EQ(CellHoldingPoint(meta, 260, 781, 5.99, -17.5)->col, 259);
}

// map_server's YAML spells the modes "trinary", "scale" and "raw"; the name
// and the parse are inverses, and nothing else (no other case) parses.
TEST(GridTest, ModeNamesParseBackAndNothingElseDoes) {
  EXPECT_EQ(MapModeFromName("trinary"), MapMode::kTrinary);
  EXPECT_EQ(MapModeFromName("scale"), MapMode::kScale);
  EXPECT_EQ(MapModeFromName("raw"), MapMode::kRaw);
  for (const MapMode mode : {MapMode::kTrinary, MapMode::kScale, MapMode::kRaw}) {
    EXPECT_EQ(MapModeFromName(MapModeName(mode)), mode);
  }
  for (const char* other : {"", "Trinary", "RAW", "scale ", "binary"}) {
    EXPECT_FALSE(MapModeFromName(other).has_value()) << other;
  }
}

TEST(GridTest, NegativeSizeGivesEmptyGrid) {
  Grid grid(-1, 5);
  EXPECT_TRUE(grid.empty());
  EXPECT_EQ(grid.width(), 0);
}

}  // namespace
}  // namespace linemap
