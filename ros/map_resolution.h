// The resolution a received map is saved with. nav_msgs/MapMetaData carries
// it as float32, so a map YAML's 0.05 arrives as 0.0500000007450581; saved
// as it is, a map served by lmap_server and saved back by lmap_saver would
// come back with another resolution. It is read instead as the shortest
// decimal that rounds to the same float (0.05), as map_saver's YAML
// ("resolution: 0.050000") gives it back; publishing the saved map again
// gives the same float. Header-only and free of ROS types: the bag input of
// `linemap encode` uses it too.
#ifndef LINEMAP_ROS_MAP_RESOLUTION_H_
#define LINEMAP_ROS_MAP_RESOLUTION_H_

#include <charconv>
#include <system_error>

namespace linemap::ros_bridge {

inline double ResolutionFromMessage(float resolution) {
  char text[64];
  const std::to_chars_result written = std::to_chars(text, text + sizeof(text), resolution);
  double value = resolution;
  if (written.ec == std::errc()) std::from_chars(text, written.ptr, value);
  return value;
}

}  // namespace linemap::ros_bridge

#endif  // LINEMAP_ROS_MAP_RESOLUTION_H_
