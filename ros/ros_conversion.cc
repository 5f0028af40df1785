#include "ros/ros_conversion.h"

#include <string>

namespace linemap::ros_bridge {

OccupancyGridMessage FromRosMessage(const OccupancyGridMsg& message) {
  OccupancyGridMessage out;
  out.frame_id.assign(message.header.frame_id.begin(), message.header.frame_id.end());
  out.width = message.info.width;
  out.height = message.info.height;
  out.resolution = message.info.resolution;
  out.origin_x = message.info.origin.position.x;
  out.origin_y = message.info.origin.position.y;
  out.origin_z = message.info.origin.position.z;
  const auto& q = message.info.origin.orientation;
  out.origin_orientation = Quaternion{q.x, q.y, q.z, q.w};
  out.data.assign(message.data.begin(), message.data.end());
  return out;
}

OccupancyGridMsg ToRosMessage(const OccupancyGridMessage& message, const ros::Time& stamp) {
  OccupancyGridMsg out;
  out.header.stamp = stamp;
  out.header.frame_id.assign(message.frame_id.begin(), message.frame_id.end());
  out.info.map_load_time = stamp;
  out.info.width = message.width;
  out.info.height = message.height;
  out.info.resolution = message.resolution;
  out.info.origin.position.x = message.origin_x;
  out.info.origin.position.y = message.origin_y;
  out.info.origin.position.z = message.origin_z;
  out.info.origin.orientation.x = message.origin_orientation.x;
  out.info.origin.orientation.y = message.origin_orientation.y;
  out.info.origin.orientation.z = message.origin_orientation.z;
  out.info.origin.orientation.w = message.origin_orientation.w;
  out.data.assign(message.data.begin(), message.data.end());
  return out;
}

StatusOr<Grid> GridFromRosMessage(const OccupancyGridMsg& message,
                                  const OccupancyThresholds& thresholds) {
  return GridFromOccupancyGrid(FromRosMessage(message), thresholds);
}

OccupancyGridMsg RosMessageFromGrid(const Grid& grid, const std::string& frame_id,
                                    const ros::Time& stamp) {
  return ToRosMessage(OccupancyGridFromGrid(grid, frame_id), stamp);
}

}  // namespace linemap::ros_bridge
