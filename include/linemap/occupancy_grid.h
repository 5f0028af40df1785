// nav_msgs/OccupancyGrid semantics without ROS types, so that a ROS 1 node,
// a ROS 2 node (nav2 uses the same message) and the Python module share one
// conversion.
//
// The message: `data` is int8 in row-major order, row 0 at the origin (as
// Grid), -1 unknown and 0..100 the occupancy probability in percent;
// `info.origin` is a 3-D pose whose yaw is read from the quaternion.
// Reading it as a trinary grid follows nav2's and ROS 1's map_saver: a value
// v in 0..100 is free when v <= rint(free_thresh * 100), occupied when
// v >= rint(occupied_thresh * 100) (whole percents), else unknown; -1 and
// anything outside 0..100 is unknown. Writing a grid follows map_server in trinary mode: free 0,
// occupied 100, unknown -1.
#ifndef LINEMAP_OCCUPANCY_GRID_H_
#define LINEMAP_OCCUPANCY_GRID_H_

#include <cstdint>
#include <string>
#include <vector>

#include "linemap/grid.h"
#include "linemap/status.h"

namespace linemap {

// A quaternion (x, y, z, w), as geometry_msgs/Quaternion.
struct Quaternion {
  double x = 0.0;
  double y = 0.0;
  double z = 0.0;
  double w = 1.0;
};

// The fields of nav_msgs/OccupancyGrid that a map needs.
struct OccupancyGridMessage {
  std::string frame_id = "map";
  std::uint32_t width = 0;   // cells
  std::uint32_t height = 0;  // cells
  float resolution = 0.05f;  // metres per cell (float32 in the message)
  double origin_x = 0.0;     // metres, pose of the lower-left corner of cell (0, 0)
  double origin_y = 0.0;
  double origin_z = 0.0;
  Quaternion origin_orientation;
  std::vector<std::int8_t> data;  // width * height, row 0 at the origin
};

// The thresholds map_saver reads a message with (probabilities, 0..1).
// map_saver's defaults are 0.65 and 0.25 (ROS 1 map_saver and nav2 alike).
struct OccupancyThresholds {
  double occupied = 0.65;
  double free = 0.25;
};

// Yaw (radians, about +z) of a quaternion; exact for planar rotations.
double YawFromQuaternion(const Quaternion& q);
// The planar rotation by `yaw` radians about +z.
Quaternion QuaternionFromYaw(double yaw);

// The resolution of a message's float32 as the shortest decimal that
// rounds to the same float: a map YAML's 0.05 arrives as 0.0500000007450581,
// and saved as it is a map served and saved back would come back with
// another resolution; map_saver's YAML ("resolution: 0.050000") gives it
// back as 0.05, and publishing it again gives the same float.
double ResolutionFromFloat32(float resolution);

// Invalid argument unless 0 <= free < occupied <= 1 with the two in whole
// percents as map_saver rounds them (std::rint(thresh * 100)): at or above
// the occupied percent a value is occupied, at or below the free one free,
// so equal percents would make one value both. The message names both
// percents.
Status CheckOccupancyThresholds(const OccupancyThresholds& thresholds);

// The message as a trinary grid: cells by `thresholds`, resolution and
// origin (x, y, yaw) from `info` (the resolution as ResolutionFromFloat32
// reads it); the grid's YAML fields get map_saver's trinary defaults.
// Fails (invalid argument) when the thresholds fail CheckOccupancyThresholds,
// data.size() is not width * height, the size exceeds `max_cells`
// (resource exhausted), the resolution is not positive and finite, or the
// origin is not finite.
StatusOr<Grid> GridFromOccupancyGrid(const OccupancyGridMessage& message,
                                     const OccupancyThresholds& thresholds = {},
                                     std::uint64_t max_cells = std::uint64_t{1} << 30);

// The grid as a message: free 0, occupied 100, unknown -1; the origin's yaw
// as a quaternion about +z; `frame_id` as given.
OccupancyGridMessage OccupancyGridFromGrid(const Grid& grid, const std::string& frame_id = "map");

}  // namespace linemap

#endif  // LINEMAP_OCCUPANCY_GRID_H_
