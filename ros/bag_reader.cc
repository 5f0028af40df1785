// liblinemap_rosbag.so: the bag reader `linemap encode RECORDING.bag` loads
// (bag_reader.h).
#include "ros/bag_reader.h"

#include <rosbag/bag.h>
#include <rosbag/view.h>

#include <cstdio>
#include <exception>
#include <set>
#include <string>

#include "ros/ros_conversion.h"
#include "ros/ros_messages.h"

namespace linemap::ros_bridge {
namespace {

constexpr const char* kMapType = "nav_msgs/OccupancyGrid";

// The topics a bag holds with their types and counts, for the message when
// the asked topic is missing.
std::string DescribeTopics(const rosbag::Bag& bag) {
  rosbag::View view(bag);
  std::string text;
  std::set<std::string> seen;
  for (const rosbag::ConnectionInfo* connection : view.getConnections()) {
    if (!seen.insert(connection->topic).second) continue;
    rosbag::View topic_view(bag, rosbag::TopicQuery(connection->topic));
    if (!text.empty()) text += ", ";
    const std::size_t n = topic_view.size();
    text += connection->topic + " (" + connection->datatype + ", " + std::to_string(n) +
            (n == 1 ? " message)" : " messages)");
  }
  return text.empty() ? "no messages" : text;
}

// An empty string when the topic is in the bag and carries maps only.
std::string CheckTopic(const rosbag::Bag& bag, const BagMapRequest& request) {
  rosbag::View view(bag, rosbag::TopicQuery(request.topic));
  if (view.size() == 0) {
    return "'" + request.bag_path + "' has no messages on topic '" + request.topic +
           "'; it holds " + DescribeTopics(bag);
  }
  for (const rosbag::ConnectionInfo* connection : view.getConnections()) {
    if (connection->datatype != kMapType) {
      return "'" + request.bag_path + "': topic '" + request.topic + "' holds " +
             connection->datatype + ", not " + kMapType;
    }
  }
  return "";
}

std::string StampName(const OccupancyGridMsg& map, const ros::Time& recorded) {
  const ros::Time stamp = map.header.stamp.isZero() ? recorded : map.header.stamp;
  char text[32];
  std::snprintf(text, sizeof(text), "%u_%09u", stamp.sec, stamp.nsec);
  return text;
}

// rosbag reports errors as exceptions; the caller catches them.
BagReadOutcome ReadMaps(BagMapRequest* request) {
  rosbag::Bag bag;
  bag.open(request->bag_path, rosbag::bagmode::Read);
  request->error = CheckTopic(bag, *request);
  if (!request->error.empty()) return BagReadOutcome::kBadInput;
  rosbag::View view(bag, rosbag::TopicQuery(request->topic));
  const std::uint64_t count = view.size();
  if (request->index >= 0 && static_cast<std::uint64_t>(request->index) >= count) {
    request->error = "'" + request->bag_path + "': --index " + std::to_string(request->index) +
                     " but topic '" + request->topic + "' holds " + std::to_string(count) +
                     " maps (0.." + std::to_string(count - 1) + ")";
    return BagReadOutcome::kBadInput;
  }
  const std::uint64_t wanted =
      request->index >= 0 ? static_cast<std::uint64_t>(request->index) : count - 1;
  std::uint64_t index = 0;
  for (const rosbag::MessageInstance& instance : view) {
    const std::uint64_t this_index = index++;
    if (!request->all && this_index != wanted) continue;
    OccupancyGridMsg::ConstPtr map = instance.instantiate<OccupancyGridMsg>();
    if (map == nullptr) {
      request->error = "'" + request->bag_path + "' " + request->topic + " message " +
                       std::to_string(this_index) + " is not a " + kMapType;
      return BagReadOutcome::kBadInput;
    }
    if (!request->visit(request->context, this_index, count, StampName(*map, instance.getTime()),
                        FromRosMessage(*map))) {
      return BagReadOutcome::kStopped;
    }
    if (!request->all) break;
  }
  return BagReadOutcome::kOk;
}

}  // namespace
}  // namespace linemap::ros_bridge

extern "C" __attribute__((visibility("default"))) linemap::ros_bridge::BagReadOutcome
linemap_rosbag_read_maps(linemap::ros_bridge::BagMapRequest* request) {
  using linemap::ros_bridge::BagReadOutcome;
  if (request->api_version != linemap::ros_bridge::kBagReaderApiVersion) {
    request->error = "liblinemap_rosbag.so is from another linemap build (interface version " +
                     std::to_string(linemap::ros_bridge::kBagReaderApiVersion) + ", asked " +
                     std::to_string(request->api_version) + ")";
    return BagReadOutcome::kBadInput;
  }
  try {
    return linemap::ros_bridge::ReadMaps(request);
  } catch (const std::exception& error) {
    // rosbag::BagException for a missing or malformed bag, and
    // deserialisation errors from a truncated message.
    request->error = "'" + request->bag_path + "': cannot read it as a ROS 1 bag: " + error.what();
    return BagReadOutcome::kBadInput;
  }
}
