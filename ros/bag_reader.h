// Reading nav_msgs/OccupancyGrid messages from a ROS 1 bag, in a module of
// its own (liblinemap_rosbag.so) that `linemap` loads with dlopen() only for
// a bag input. Linking rosbag into `linemap` itself would load about twenty
// ROS and Boost libraries at every start (`linemap info` on a small map took
// 10.4 ms instead of 2.4), for a feature few runs use.
//
// The module exports one C function; the request below is the whole
// interface, versioned so that a module from another build is refused.
#ifndef LINEMAP_ROS_BAG_READER_H_
#define LINEMAP_ROS_BAG_READER_H_

#include <cstdint>
#include <string>

#include "linemap/occupancy_grid.h"

namespace linemap::ros_bridge {

inline constexpr int kBagReaderApiVersion = 1;
inline constexpr const char* kBagReaderSymbol = "linemap_rosbag_read_maps";

// How a read ended. kBadInput: the bag cannot be read, lacks the topic, the
// topic holds another type, or the index is out of range (exit 2);
// kStopped: the visitor returned false.
enum class BagReadOutcome : int { kOk = 0, kBadInput = 1, kStopped = 2 };

struct BagMapRequest {
  int api_version = kBagReaderApiVersion;
  std::string bag_path;
  std::string topic;  // as stored, with its leading slash: "/map"
  // Which messages of the topic, counted from 0: one (index), the last
  // (index < 0), or every one (all).
  std::int64_t index = -1;
  bool all = false;
  // Receives each chosen message with its position on the topic, the
  // number of messages there, and its stamp as "SEC_NSEC" (the header
  // stamp, or the recording time when the header's is zero). Returns false
  // to stop reading.
  bool (*visit)(void* context, std::uint64_t index, std::uint64_t count, const std::string& stamp,
                const OccupancyGridMessage& message) = nullptr;
  void* context = nullptr;
  // Set by the module when the outcome is not kOk: a message naming the bag
  // and the topic.
  std::string error;
};

// The exported function's type: reads as `request` says and returns the
// outcome; never throws.
using BagMapReaderFn = BagReadOutcome (*)(BagMapRequest* request);

}  // namespace linemap::ros_bridge

#endif  // LINEMAP_ROS_BAG_READER_H_
