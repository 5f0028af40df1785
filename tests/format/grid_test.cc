#include "linemap/grid.h"

#include <gtest/gtest.h>

#include <cmath>

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
