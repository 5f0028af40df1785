// nav_msgs/OccupancyGrid conversion, checked against hand-made values and
// map_saver's rule written out cell by cell.
#include "linemap/occupancy_grid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "linemap/map_io.h"
#include "tests/testing/test_support.h"

namespace linemap {
namespace {

OccupancyGridMessage Message(std::uint32_t width, std::uint32_t height,
                             std::vector<std::int8_t> data) {
  OccupancyGridMessage m;
  m.width = width;
  m.height = height;
  m.data = std::move(data);
  return m;
}

TEST(OccupancyGridTest, ReadsValuesAsMapSaverDoes) {
  // map_saver: v <= 25 free, v >= 65 occupied, else (and -1, > 100) unknown.
  OccupancyGridMessage m = Message(8, 1, {-1, 0, 25, 26, 64, 65, 100, 101 - 128});
  StatusOr<Grid> grid = GridFromOccupancyGrid(m);
  ASSERT_TRUE(grid.ok()) << grid.status().message();
  const std::vector<Cell> expected = {Cell::kUnknown,  Cell::kFree,    Cell::kFree,
                                      Cell::kUnknown,  Cell::kUnknown, Cell::kOccupied,
                                      Cell::kOccupied, Cell::kUnknown};
  EXPECT_EQ(grid->cells(), expected);
}

TEST(OccupancyGridTest, RowZeroIsTheOriginRow) {
  OccupancyGridMessage m = Message(2, 2, {100, 0, -1, 0});
  StatusOr<Grid> grid = GridFromOccupancyGrid(m);
  ASSERT_TRUE(grid.ok());
  EXPECT_EQ(grid->at(0, 0), Cell::kOccupied);
  EXPECT_EQ(grid->at(1, 0), Cell::kFree);
  EXPECT_EQ(grid->at(0, 1), Cell::kUnknown);
}

TEST(OccupancyGridTest, CustomThresholds) {
  OccupancyGridMessage m = Message(3, 1, {10, 50, 90});
  StatusOr<Grid> grid = GridFromOccupancyGrid(m, {.occupied = 0.5, .free = 0.05});
  ASSERT_TRUE(grid.ok());
  EXPECT_EQ(grid->cells(), (std::vector<Cell>{Cell::kUnknown, Cell::kOccupied, Cell::kOccupied}));
}

// map_saver compares whole percents, std::rint(thresh * 100): with free
// 0.29 a value of 29 is free, though 0.29 * 100.0 is 28.999999999999996 in
// doubles; likewise occupied 0.07, 0.14, 0.28, 0.55, 0.56 and free 0.57,
// 0.58 (every such threshold of 0.01 .. 0.99 is checked against the rule
// written with integers).
TEST(OccupancyGridTest, ThresholdsAreWholePercentsAsMapSaverRoundsThem) {
  std::vector<std::int8_t> all;
  for (int v = 0; v <= 100; ++v) all.push_back(static_cast<std::int8_t>(v));
  const OccupancyGridMessage m = Message(101, 1, all);
  for (int free = 1; free < 99; ++free) {
    for (int occupied : {free + 1, 99}) {
      const OccupancyThresholds t{.occupied = occupied / 100.0, .free = free / 100.0};
      StatusOr<Grid> grid = GridFromOccupancyGrid(m, t);
      ASSERT_TRUE(grid.ok());
      for (int v = 0; v <= 100; ++v) {
        const Cell want = v <= free       ? Cell::kFree
                          : v >= occupied ? Cell::kOccupied
                                          : Cell::kUnknown;
        ASSERT_EQ(grid->at(v, 0), want)
            << "free " << free << " occupied " << occupied << " value " << v;
      }
    }
  }
}

// A free threshold at or above the occupied one (in whole percents), or
// thresholds outside 0..1, are refused rather than read with one of the two
// rules winning.
TEST(OccupancyGridTest, ThresholdsOutOfOrderAreRefused) {
  const OccupancyGridMessage m = Message(2, 1, {10, 70});
  for (const OccupancyThresholds t : {OccupancyThresholds{.occupied = 0.1, .free = 0.9},
                                      OccupancyThresholds{.occupied = 0.5, .free = 0.5},
                                      OccupancyThresholds{.occupied = 0.501, .free = 0.499},
                                      OccupancyThresholds{.occupied = 1.5, .free = 0.25},
                                      OccupancyThresholds{.occupied = 0.65, .free = -0.1}}) {
    const StatusOr<Grid> grid = GridFromOccupancyGrid(m, t);
    ASSERT_FALSE(grid.ok()) << t.free << " " << t.occupied;
    EXPECT_EQ(grid.status().code(), StatusCode::kInvalidArgument);
    EXPECT_NE(grid.status().message().find("thresholds"), std::string::npos);
  }
  EXPECT_TRUE(GridFromOccupancyGrid(m, {.occupied = 0.51, .free = 0.5}).ok());
}

TEST(OccupancyGridTest, OriginYawFromQuaternion) {
  OccupancyGridMessage m = Message(1, 1, {0});
  m.origin_x = -12.5;
  m.origin_y = 3.25;
  // A quarter turn about +z: (0, 0, sin(pi/4), cos(pi/4)).
  m.origin_orientation = {0.0, 0.0, std::sqrt(0.5), std::sqrt(0.5)};
  m.resolution = 0.1f;
  StatusOr<Grid> grid = GridFromOccupancyGrid(m);
  ASSERT_TRUE(grid.ok());
  EXPECT_DOUBLE_EQ(grid->meta.origin.x, -12.5);
  EXPECT_DOUBLE_EQ(grid->meta.origin.y, 3.25);
  EXPECT_NEAR(grid->meta.origin.yaw, M_PI / 2, 1e-12);
  EXPECT_EQ(grid->meta.resolution, 0.1);  // the shortest decimal of 0.1f
}

TEST(OccupancyGridTest, QuaternionOfYawRoundTrips) {
  for (double yaw : {0.0, 0.3, -1.2, 3.0, -3.0}) {
    const Quaternion q = QuaternionFromYaw(yaw);
    EXPECT_NEAR(q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w, 1.0, 1e-12);
    EXPECT_NEAR(YawFromQuaternion(q), yaw, 1e-12);
  }
}

TEST(OccupancyGridTest, WritesTrinaryValues) {
  Grid grid(3, 1);
  grid.set(0, 0, Cell::kFree);
  grid.set(1, 0, Cell::kOccupied);
  grid.meta.origin = {1.0, 2.0, 0.0};
  const OccupancyGridMessage m = OccupancyGridFromGrid(grid, "odom");
  EXPECT_EQ(m.data, (std::vector<std::int8_t>{0, 100, -1}));
  EXPECT_EQ(m.frame_id, "odom");
  EXPECT_EQ(m.width, 3u);
  EXPECT_EQ(m.height, 1u);
  EXPECT_EQ(m.origin_orientation.w, 1.0);
}

TEST(OccupancyGridTest, BundledMapRoundTripsExactly) {
  StatusOr<Grid> map = LoadRosMap(testing::BundledMapsDir() + "/nav2/depot.yaml");
  ASSERT_TRUE(map.ok()) << map.status().message();
  StatusOr<Grid> back = GridFromOccupancyGrid(OccupancyGridFromGrid(*map));
  ASSERT_TRUE(back.ok());
  EXPECT_EQ(back->cells(), map->cells());
  EXPECT_EQ(back->meta.origin, map->meta.origin);
}

TEST(OccupancyGridTest, RefusesInconsistentMessages) {
  EXPECT_FALSE(GridFromOccupancyGrid(Message(2, 2, {0, 0, 0})).ok());
  OccupancyGridMessage zero_res = Message(1, 1, {0});
  zero_res.resolution = 0.0f;
  EXPECT_FALSE(GridFromOccupancyGrid(zero_res).ok());
  OccupancyGridMessage nan_origin = Message(1, 1, {0});
  nan_origin.origin_x = std::nan("");
  EXPECT_FALSE(GridFromOccupancyGrid(nan_origin).ok());
  StatusOr<Grid> big = GridFromOccupancyGrid(Message(4, 4, std::vector<std::int8_t>(16)), {}, 15);
  ASSERT_FALSE(big.ok());
  EXPECT_EQ(big.status().code(), StatusCode::kResourceExhausted);
}

}  // namespace
}  // namespace linemap
