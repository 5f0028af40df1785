// The ~window of lmap_server (ros/served_map.cc) without ROS: parsing, and
// the crop of a rotated map checked against the map's own cell geometry.
#include "ros/served_map.h"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/ros/ros_maps.h"

namespace linemap::ros_bridge {
namespace {

TEST(ServedMapTest, ParsesWindowTextAndRefusesBadOnes) {
  StatusOr<Window> window = ParseWindow("[-5.0, -2.32, 3.01, 8.93]");
  ASSERT_TRUE(window.ok()) << window.status().message();
  EXPECT_EQ(window->x0, -5.0);
  EXPECT_EQ(window->y0, -2.32);
  EXPECT_EQ(window->x1, 3.01);
  EXPECT_EQ(window->y1, 8.93);
  EXPECT_TRUE(ParseWindow("1,2,3,4").ok());
  EXPECT_FALSE(ParseWindow("1,2,3").ok());
  EXPECT_FALSE(ParseWindow("1,2,3,4,5").ok());
  EXPECT_FALSE(ParseWindow("3,2,1,4").ok());  // x0 > x1
  EXPECT_FALSE(ParseWindow("1,2,3,2").ok());  // y0 = y1
  EXPECT_FALSE(ParseWindow("1,2,x,4").ok());
  EXPECT_FALSE(ParseWindow("1,2,nan,4").ok());
}

TEST(ServedMapTest, WindowOutsideTheMapIsRefused) {
  Grid grid = testing::NoiseMap(20, 10, 1);
  EXPECT_FALSE(CropToWindow(grid, {5.0, 5.0, 6.0, 6.0}).ok());  // map is 1 x 0.5 m
}

TEST(ServedMapTest, CropOfARotatedMapKeepsEveryCellWhereItWas) {
  Grid grid = testing::NoiseMap(120, 90, 7);
  grid.meta.resolution = 0.05;
  grid.meta.origin = {-1.3, 2.1, 0.4};
  const Window window{0.0, 3.5, 1.5, 4.5};  // inside the rotated map
  StatusOr<Grid> crop = CropToWindow(grid, window);
  ASSERT_TRUE(crop.ok()) << crop.status().message();
  EXPECT_EQ(crop->meta.resolution, grid.meta.resolution);
  EXPECT_EQ(crop->meta.origin.yaw, grid.meta.origin.yaw);
  // Cell (0, 0) of the crop lies on a cell centre of the map: that cell is
  // the crop's offset, and every cell keeps its state and its place.
  double x = 0, y = 0, col = 0, row = 0;
  crop->CellToWorld(0, 0, &x, &y);
  grid.WorldToCell(x, y, &col, &row);
  EXPECT_NEAR(col, std::round(col), 1e-9);
  EXPECT_NEAR(row, std::round(row), 1e-9);
  const int col0 = static_cast<int>(std::round(col)), row0 = static_cast<int>(std::round(row));
  for (int r = 0; r < crop->height(); ++r) {
    for (int c = 0; c < crop->width(); ++c) {
      ASSERT_TRUE(grid.Contains(col0 + c, row0 + r));
      ASSERT_EQ(crop->at(c, r), grid.at(col0 + c, row0 + r)) << c << "," << r;
    }
  }
  // The window's corners fall inside the crop's cells.
  for (const double wx : {window.x0, window.x1}) {
    for (const double wy : {window.y0, window.y1}) {
      crop->WorldToCell(wx, wy, &col, &row);
      EXPECT_GE(col, -0.5);
      EXPECT_GE(row, -0.5);
      EXPECT_LE(col, crop->width() - 0.5);
      EXPECT_LE(row, crop->height() - 0.5);
    }
  }
}

}  // namespace
}  // namespace linemap::ros_bridge
