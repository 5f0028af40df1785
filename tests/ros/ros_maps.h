// Maps for the ROS tests, and the reference conversions they are checked
// against, written out here independently of the library's.
#ifndef LINEMAP_TESTS_ROS_ROS_MAPS_H_
#define LINEMAP_TESTS_ROS_ROS_MAPS_H_

#include <cstdint>
#include <string>
#include <vector>

#include "linemap/grid.h"
#include "ros/ros_messages.h"

namespace linemap::testing {

// A bundled map (tests/data/maps/<relative>), loaded; fails the test if not.
Grid LoadBundledMap(const std::string& relative);

// The message map_server publishes for `grid`: free 0, occupied 100,
// unknown -1, origin yaw as a quaternion about +z.
ros_bridge::OccupancyGridMsg ReferenceMessage(const Grid& grid, const std::string& frame_id);

// map_saver's reading of one value: free at or below `free_percent`,
// occupied at or above `occupied_percent`, else (and outside 0..100) unknown.
Cell ReferenceCell(std::int8_t value, int occupied_percent = 65, int free_percent = 25);

// Expects `message` to be `grid` cell for cell, metadata included.
void ExpectMessageIsGrid(const ros_bridge::OccupancyGridMsg& message, const Grid& grid,
                         const std::string& frame_id);

// Expects `decoded` (a saved .lmap read back) to be the grid `message`
// carries: cells by ReferenceCell, origin and yaw, and `resolution` (that of
// the map YAML the message was made from: the saver reads the message's
// float32 back as that decimal).
void ExpectGridIsMessage(const Grid& decoded, const ros_bridge::OccupancyGridMsg& message,
                         double resolution);

// A width x height map of pseudo-random cells (all three states), which
// encodes to a large file; `seed` varies it.
Grid NoiseMap(int width, int height, std::uint32_t seed);

}  // namespace linemap::testing

#endif  // LINEMAP_TESTS_ROS_ROS_MAPS_H_
