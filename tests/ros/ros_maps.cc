#include "tests/ros/ros_maps.h"

#include <gtest/gtest.h>

#include <cmath>

#include "linemap/map_io.h"
#include "tests/testing/test_support.h"

namespace linemap::testing {

Grid LoadBundledMap(const std::string& relative) {
  StatusOr<Grid> grid = LoadRosMap(BundledMapsDir() + "/" + relative);
  EXPECT_TRUE(grid.ok()) << grid.status().message();
  return grid.ok() ? *grid : Grid();
}

ros_bridge::OccupancyGridMsg ReferenceMessage(const Grid& grid, const std::string& frame_id) {
  ros_bridge::OccupancyGridMsg message;
  message.header.frame_id = frame_id.c_str();
  message.info.width = grid.width();
  message.info.height = grid.height();
  message.info.resolution = static_cast<float>(grid.meta.resolution);
  message.info.origin.position.x = grid.meta.origin.x;
  message.info.origin.position.y = grid.meta.origin.y;
  message.info.origin.orientation.z = std::sin(grid.meta.origin.yaw / 2);
  message.info.origin.orientation.w = std::cos(grid.meta.origin.yaw / 2);
  for (int row = 0; row < grid.height(); ++row) {
    for (int col = 0; col < grid.width(); ++col) {
      const Cell cell = grid.at(col, row);
      message.data.push_back(cell == Cell::kFree ? 0 : cell == Cell::kOccupied ? 100 : -1);
    }
  }
  return message;
}

Cell ReferenceCell(std::int8_t value, int occupied_percent, int free_percent) {
  if (value < 0 || value > 100) return Cell::kUnknown;
  if (value <= free_percent) return Cell::kFree;
  if (value >= occupied_percent) return Cell::kOccupied;
  return Cell::kUnknown;
}

void ExpectMessageIsGrid(const ros_bridge::OccupancyGridMsg& message, const Grid& grid,
                         const std::string& frame_id) {
  const ros_bridge::OccupancyGridMsg expected = ReferenceMessage(grid, frame_id);
  EXPECT_EQ(std::string(message.header.frame_id.c_str()), frame_id);
  EXPECT_EQ(message.info.width, expected.info.width);
  EXPECT_EQ(message.info.height, expected.info.height);
  EXPECT_EQ(message.info.resolution, expected.info.resolution);
  EXPECT_DOUBLE_EQ(message.info.origin.position.x, expected.info.origin.position.x);
  EXPECT_DOUBLE_EQ(message.info.origin.position.y, expected.info.origin.position.y);
  EXPECT_EQ(message.info.origin.position.z, 0.0);
  EXPECT_EQ(message.info.origin.orientation.x, 0.0);
  EXPECT_EQ(message.info.origin.orientation.y, 0.0);
  EXPECT_NEAR(message.info.origin.orientation.z, expected.info.origin.orientation.z, 1e-12);
  EXPECT_NEAR(message.info.origin.orientation.w, expected.info.origin.orientation.w, 1e-12);
  ASSERT_EQ(message.data.size(), expected.data.size());
  std::size_t differing = 0;
  for (std::size_t i = 0; i < expected.data.size(); ++i) {
    differing += message.data[i] != expected.data[i];
  }
  EXPECT_EQ(differing, 0u) << "of " << expected.data.size() << " cells";
}

void ExpectGridIsMessage(const Grid& decoded, const ros_bridge::OccupancyGridMsg& message,
                         double resolution) {
  ASSERT_EQ(decoded.width(), static_cast<int>(message.info.width));
  ASSERT_EQ(decoded.height(), static_cast<int>(message.info.height));
  EXPECT_EQ(decoded.meta.resolution, resolution);
  EXPECT_DOUBLE_EQ(decoded.meta.origin.x, message.info.origin.position.x);
  EXPECT_DOUBLE_EQ(decoded.meta.origin.y, message.info.origin.position.y);
  const auto& q = message.info.origin.orientation;
  EXPECT_NEAR(decoded.meta.origin.yaw, 2 * std::atan2(q.z, q.w), 1e-12);
  std::size_t differing = 0;
  for (int row = 0; row < decoded.height(); ++row) {
    for (int col = 0; col < decoded.width(); ++col) {
      const std::int8_t value = message.data[static_cast<std::size_t>(row) * decoded.width() + col];
      differing += decoded.at(col, row) != ReferenceCell(value);
    }
  }
  EXPECT_EQ(differing, 0u) << "of " << decoded.size() << " cells";
}

Grid NoiseMap(int width, int height, std::uint32_t seed) {
  Grid grid(width, height);
  std::uint32_t state = seed * 2654435761u + 1;
  for (Cell& cell : grid.mutable_cells()) {
    state = state * 1664525u + 1013904223u;  // a linear congruential generator
    cell = static_cast<Cell>((state >> 16) % 3);
  }
  return grid;
}

}  // namespace linemap::testing
