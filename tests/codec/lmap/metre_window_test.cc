// CellWindowOfMetres: the cells a window in map-frame metres covers, the
// rule `linemap decode --window` and lmap_server's ~window share. Expected
// windows are worked out by hand from the cell centres (c + 0.5) * 0.05 m.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "linemap/codec.h"

namespace linemap {
namespace {

MapMetadata Depot(double x = 0, double y = 0, double yaw = 0) {
  MapMetadata meta;
  meta.resolution = 0.05;
  meta.origin = {x, y, yaw};
  return meta;
}

void ExpectWindow(const StatusOr<CellWindow>& w, int col0, int row0, int col1, int row1) {
  ASSERT_TRUE(w.ok()) << w.status().message();
  EXPECT_EQ(w->col0, col0);
  EXPECT_EQ(w->row0, row0);
  EXPECT_EQ(w->col1, col1);
  EXPECT_EQ(w->row1, row1);
}

TEST(CellWindowOfMetresTest, TakesTheCellsWhoseCentresLieInTheBox) {
  // x in [1.01, 5.01]: (c + 0.5) 0.05 from 20.2 to 100.2 cells -> 20..99.
  ExpectWindow(CellWindowOfMetres(Depot(), 604, 307, 1.01, 1.01, 5.01, 4.01), 20, 20, 100, 80);
  // Edges on centres keep them: 0.025 is column 0's, 30.175 column 603's.
  ExpectWindow(CellWindowOfMetres(Depot(), 604, 307, 0.025, 0.025, 30.175, 15.325), 0, 0, 604, 307);
  // The map's border, and a little past it short of the next centre.
  ExpectWindow(CellWindowOfMetres(Depot(), 604, 307, -0.02, 0, 30.22, 15.35), 0, 0, 604, 307);
  // A shifted origin moves the centres with it: -17.5 + (r + 0.5) 0.05 in
  // [-2.32, 8.93] for rows 303.1..528.1, so 304..528.
  ExpectWindow(CellWindowOfMetres(Depot(-7, -17.5), 260, 781, -5.0, -2.32, 3.01, 8.93), 40, 304,
               200, 529);
}

TEST(CellWindowOfMetresTest, RefusesBoxesPastTheMapOrWithoutACentre) {
  const StatusOr<CellWindow> past = CellWindowOfMetres(Depot(), 604, 307, -0.03, 0, 1, 1);
  ASSERT_FALSE(past.ok());
  EXPECT_EQ(past.status().code(), StatusCode::kInvalidArgument);
  const std::string text = past.status().message();
  EXPECT_EQ(text.rfind("window -0.03,0,1,1 m covers cells [-1, 20) x [0, 20)", 0), 0u) << text;
  EXPECT_NE(text.find("the map's 604 x 307 cells have centres from 0.025,0.025 to "
                      "30.175,15.325 m"),
            std::string::npos)
      << text;
  // Between two centres, inverted, not finite, far off.
  EXPECT_FALSE(CellWindowOfMetres(Depot(), 604, 307, 1.0, 1.0, 1.02, 2.0).ok());
  EXPECT_FALSE(CellWindowOfMetres(Depot(), 604, 307, 2, 1, 1, 2).ok());
  EXPECT_FALSE(CellWindowOfMetres(Depot(), 604, 307, NAN, 1, 2, 2).ok());
  EXPECT_FALSE(CellWindowOfMetres(Depot(), 604, 307, -1e300, -1e300, 1e300, 1e300).ok());
  const StatusOr<CellWindow> label = CellWindowOfMetres(Depot(), 604, 307, 2, 1, 1, 2, "--window");
  EXPECT_EQ(label.status().message().rfind("--window 2,1,1,2 m", 0), 0u)
      << label.status().message();
}

// Edges typed in decimal on a centre keep it at a UTM-sized origin too,
// where the doubles' rounding is far above 1e-9 cell: each column alone.
TEST(CellWindowOfMetresTest, EdgesOnCentresHoldAtLargeOrigins) {
  for (const double origin_x : {12.34, 512345.67, 5412345.67}) {
    const MapMetadata meta = Depot(origin_x, 0);
    for (int c = 0; c < 1000; ++c) {
      char typed[64];
      std::snprintf(typed, sizeof(typed), "%.3f", origin_x + (c + 0.5) * 0.05);
      const double x = std::strtod(typed, nullptr);
      const StatusOr<CellWindow> w = CellWindowOfMetres(meta, 1000, 10, x, 0.025, x, 0.025);
      ASSERT_TRUE(w.ok()) << origin_x << " " << typed << ": " << w.status().message();
      ASSERT_EQ(w->col0, c) << origin_x << " " << typed;
      ASSERT_EQ(w->col1, c + 1) << origin_x << " " << typed;
    }
  }
}

// A map wider than 2^29 cells: indices past an int are refused with whole
// numbers in the message, not a cast's garbage: 1e12 / 0.05 = 2e13 cells,
// 2e12 m the centre of column 4e13 - 0.5, so columns [2e13, 4e13).
TEST(CellWindowOfMetresTest, WindowFarRightOfAVeryWideMapIsRefusedPlainly) {
  const StatusOr<CellWindow> far =
      CellWindowOfMetres(Depot(), 600000000, 1, 1e12, 0.01, 2e12, 0.04);
  ASSERT_FALSE(far.ok());
  EXPECT_NE(far.status().message().find("covers cells [20000000000000, 40000000000000) x [0, 1)"),
            std::string::npos)
      << far.status().message();
  ExpectWindow(CellWindowOfMetres(Depot(), 600000000, 1, 29999999.0, 0.0, 29999999.99, 0.05),
               599999980, 0, 600000000, 1);
}

// Huge metres on one axis leave the other's cells as they are: kth's frame
// (origin -7, -17.5; 260 x 781 cells). Rows: y = 0 is row 17.5 / 0.05 - 0.5
// = 349.5, y = 1 row 369.5, so rows [350, 370); columns: x = 0 is column
// 7 / 0.05 - 0.5 = 139.5, so the first is 140. The refusal stands, with the
// true cells: -1e18 m is column -2e19 (to 4 digits: no 64-bit integer holds
// it), 9.3e15 m column 1.86e17. The slack of the rounding used to grow with
// the largest of the four numbers on both axes and moved the rows by up to
// 71,000 cells (they printed as [-3128, 3129), held to four map sizes).
TEST(CellWindowOfMetresTest, HugeMetresOnOneAxisGiveTheTrueCellsInTheRefusal) {
  const MapMetadata kth = Depot(-7, -17.5);
  const StatusOr<CellWindow> left = CellWindowOfMetres(kth, 260, 781, -1e18, 0, 0, 1, "--window");
  ASSERT_FALSE(left.ok());
  EXPECT_EQ(left.status().code(), StatusCode::kInvalidArgument);
  EXPECT_NE(left.status().message().find("covers cells [-2e+19, 140) x [350, 370), past the map"),
            std::string::npos)
      << left.status().message();
  const StatusOr<CellWindow> right = CellWindowOfMetres(kth, 260, 781, 0, 0, 9.3e15, 1);
  ASSERT_FALSE(right.ok());
  EXPECT_NE(
      right.status().message().find("covers cells [140, 1.86e+17) x [350, 370), past the map"),
      std::string::npos)
      << right.status().message();
  const StatusOr<CellWindow> up = CellWindowOfMetres(kth, 260, 781, 0, 0, 1, 4e17);
  ASSERT_FALSE(up.ok());
  EXPECT_NE(up.status().message().find("covers cells [140, 160) x [350, 8e+18)"), std::string::npos)
      << up.status().message();
  // Inside the map the same boxes' parts give those cells.
  ExpectWindow(CellWindowOfMetres(kth, 260, 781, -6.975, 0, 0, 1), 0, 350, 140, 370);
  ExpectWindow(CellWindowOfMetres(kth, 260, 781, 0, 0, 5.975, 1), 140, 350, 260, 370);
}

// A turned map: the cell rectangle around the window's corners, and a
// refusal that says the window is taken into the turned grid.
TEST(CellWindowOfMetresTest, TurnedMapTakesTheRectangleAroundTheCorners) {
  // A quarter turn: the map's columns run along +y, its rows along -x, so
  // the point (x, y) is at column y / 0.05 - 0.5 and row -x / 0.05 - 0.5.
  const MapMetadata turned = Depot(0, 0, M_PI / 2);
  // x in [-1.01, -0.51] -> rows 9.7..19.7 -> 10..19; y in [0.51, 1.01] ->
  // columns 9.7..19.7 -> 10..19.
  ExpectWindow(CellWindowOfMetres(turned, 100, 100, -1.01, 0.51, -0.51, 1.01), 10, 10, 20, 20);
  const StatusOr<CellWindow> past = CellWindowOfMetres(turned, 100, 100, 0.5, 0.5, 1, 1);
  ASSERT_FALSE(past.ok());
  EXPECT_NE(past.status().message().find("turned by its origin's yaw"), std::string::npos)
      << past.status().message();
}

}  // namespace
}  // namespace linemap
