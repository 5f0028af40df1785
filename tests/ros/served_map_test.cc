// The ~window of lmap_server (ros/served_map.cc) without ROS: parsing, and
// the crop of a rotated map checked against the map's own cell geometry.
#include "ros/served_map.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "tests/ros/ros_maps.h"
#include "tests/testing/test_support.h"

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

// A window holds the cells whose squares overlap it; one that reaches past
// the map's border is refused, not clipped, naming the window and the map's
// extent, while one whose edges lie on the border holds the whole map.
TEST(ServedMapTest, WindowPastTheMapsBorderIsRefused) {
  const Grid grid = testing::NoiseMap(20, 10, 1);  // 1 x 0.5 m from 0,0
  StatusOr<Grid> whole = CropToWindow(grid, {0.0, 0.0, 1.0, 0.5});
  ASSERT_TRUE(whole.ok()) << whole.status().message();
  EXPECT_EQ(whole->width(), 20);
  EXPECT_EQ(whole->height(), 10);
  EXPECT_EQ(whole->cells(), grid.cells());
  for (const Window& past :
       {Window{-0.01, 0.0, 0.5, 0.25}, Window{0.5, 0.25, 1.01, 0.4}, Window{0.1, -1e6, 0.2, 0.1},
        Window{0.1, 0.1, 0.2, 0.6}, Window{-1e300, -1e300, 1e300, 1e300}}) {
    const StatusOr<Grid> crop = CropToWindow(grid, past);
    ASSERT_FALSE(crop.ok()) << past.x0 << "," << past.y0 << "," << past.x1 << "," << past.y1;
    EXPECT_EQ(crop.status().code(), StatusCode::kInvalidArgument);
    EXPECT_NE(crop.status().message().find("past the map"), std::string::npos)
        << crop.status().message();
    EXPECT_NE(crop.status().message().find("20 x 10 cells span from 0,0 to 1,0.5 m"),
              std::string::npos)
        << crop.status().message();
  }
  const StatusOr<Grid> crop = CropToWindow(grid, {-5, -5, 1, 1});
  ASSERT_FALSE(crop.ok());
  EXPECT_NE(crop.status().message().find("window -5,-5,1,1 m"), std::string::npos)
      << crop.status().message();
}

// LoadServedMap refuses such a window the same way for an .lmap file, whose
// window is decoded alone, and for a map image, which is cropped; the
// message names the file.
TEST(ServedMapTest, LoadServedMapRefusesAWindowPastTheMap) {
  for (const std::string& path : {testing::SourceDir() + "/tests/data/lmap/depot_lossless.lmap",
                                  testing::BundledMapsDir() + "/nav2/depot.yaml"}) {
    const StatusOr<Grid> grid = LoadServedMap(path, Window{-5, -5, 1, 1});
    ASSERT_FALSE(grid.ok()) << path;
    EXPECT_EQ(grid.status().code(), StatusCode::kInvalidArgument);
    EXPECT_NE(grid.status().message().find(path), std::string::npos) << grid.status().message();
    EXPECT_NE(grid.status().message().find("604 x 307 cells span from 0,0 to 30.2,15.35 m"),
              std::string::npos)
        << grid.status().message();
    EXPECT_TRUE(LoadServedMap(path, Window{0, 0, 30.2, 15.35}).ok()) << path;
  }
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
