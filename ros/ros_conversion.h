// nav_msgs messages <-> linemap's ROS-free OccupancyGridMessage
// (include/linemap/occupancy_grid.h). Only field copies live here: the
// occupancy thresholds, the row order and the yaw are decided once, in the
// library, so that a ROS 2 node can wrap the same conversion with its own
// message types.
#ifndef LINEMAP_ROS_ROS_CONVERSION_H_
#define LINEMAP_ROS_ROS_CONVERSION_H_

#include <ros/time.h>

#include <string>

#include "linemap/grid.h"
#include "linemap/occupancy_grid.h"
#include "linemap/status.h"
#include "ros/ros_messages.h"

namespace linemap::ros_bridge {

// The fields of a received nav_msgs/OccupancyGrid, copied.
OccupancyGridMessage FromRosMessage(const OccupancyGridMsg& message);

// `message` as nav_msgs/OccupancyGrid with header.stamp and
// info.map_load_time set to `stamp`.
OccupancyGridMsg ToRosMessage(const OccupancyGridMessage& message, const ros::Time& stamp);

// A received map as a trinary grid, with map_saver's thresholds (see
// occupancy_grid.h): GridFromOccupancyGrid(FromRosMessage()), with the
// resolution read as the shortest decimal of its float32 (0.05, not
// 0.0500000007).
StatusOr<Grid> GridFromRosMessage(const OccupancyGridMsg& message,
                                  const OccupancyThresholds& thresholds = {});

// The grid as map_server publishes it: free 0, occupied 100, unknown -1.
OccupancyGridMsg RosMessageFromGrid(const Grid& grid, const std::string& frame_id,
                                    const ros::Time& stamp);

}  // namespace linemap::ros_bridge

#endif  // LINEMAP_ROS_ROS_CONVERSION_H_
