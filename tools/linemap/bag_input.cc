#include "tools/linemap/bag_input.h"

#include <sys/stat.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <optional>
#include <set>
#include <string_view>

#include "format/file_io.h"
#include "linemap/occupancy_grid.h"

#ifdef LINEMAP_HAVE_ROSBAG
#include <rosbag/bag.h>
#include <rosbag/view.h>

#include "ros/ros_conversion.h"
#endif

namespace linemap::cli {

std::vector<OptionSpec> WithBagOptions(std::vector<OptionSpec> options) {
  options.push_back({"--topic", "TOPIC",
                     "MAP is a ROS 1 bag: read nav_msgs/OccupancyGrid messages on TOPIC "
                     "(default /map); the last one unless --index or --all"});
  options.push_back({"--index", "K", "bag: encode the K-th map on the topic (0 = first)"});
  options.push_back({"--all", "",
                     "bag: encode every map on the topic into the folder -o names, as "
                     "SEC_NSEC.lmap by the header stamps"});
  return options;
}

bool IsBagInput(const std::string& input, const ParsedArgs& args) {
  return input.ends_with(".bag") || args.Get("--topic") || args.Get("--index") ||
         args.Has("--all");
}

#ifdef LINEMAP_HAVE_ROSBAG
namespace {

// What selects the messages, read from the arguments.
struct BagSelection {
  std::string topic = "/map";
  std::optional<std::uint64_t> index;  // nullopt: the last (or all)
  bool all = false;
  std::string out;  // OUT.lmap, or the folder with --all
  OccupancyThresholds thresholds;
  std::uint64_t max_cells = std::uint64_t{1} << 28;
  Durability durability = Durability::kSynced;
};

StatusOr<BagSelection> BagSelectionFrom(const ParsedArgs& args) {
  BagSelection selection;
  if (std::optional<std::string> topic = args.Get("--topic")) selection.topic = *topic;
  if (selection.topic.empty()) return InvalidArgumentError("--topic must not be empty");
  // Bags store topics with their leading slash; `--topic map` means /map.
  if (selection.topic[0] != '/') selection.topic = "/" + selection.topic;
  selection.all = args.Has("--all");
  if (args.Get("--index")) {
    if (selection.all) return InvalidArgumentError("give --index K or --all, not both");
    LINEMAP_ASSIGN_OR_RETURN(selection.index, args.GetUint64("--index", 0));
  }
  std::optional<std::string> out = args.Get("-o");
  if (!out) {
    return InvalidArgumentError(selection.all ? "missing -o DIR (the folder for the .lmap files)"
                                              : "missing -o OUT.lmap");
  }
  selection.out = *out;
  if (!selection.all && !selection.out.ends_with(".lmap")) {
    return InvalidArgumentError("output '" + selection.out + "' must end in .lmap");
  }
  // map_saver's thresholds read the int8 occupancies unless overridden.
  if (args.Get("--occupied-thresh")) {
    LINEMAP_ASSIGN_OR_RETURN(selection.thresholds.occupied,
                             args.GetDouble("--occupied-thresh", 0.65));
  }
  if (args.Get("--free-thresh")) {
    LINEMAP_ASSIGN_OR_RETURN(selection.thresholds.free, args.GetDouble("--free-thresh", 0.25));
  }
  LINEMAP_ASSIGN_OR_RETURN(selection.max_cells,
                           args.GetUint64("--max-cells", selection.max_cells, /*min=*/1));
  if (args.Has("--no-sync")) selection.durability = Durability::kUnsynced;
  return selection;
}

// The folder for --all: made when missing (one level, as `mkdir`).
Status EnsureFolder(const std::string& dir) {
  if (IsDirectory(dir)) return Status::Ok();
  if (::mkdir(dir.c_str(), 0777) != 0) {
    return IoError("cannot make the folder '" + dir + "': " + std::strerror(errno));
  }
  return Status::Ok();
}

Status EncodeGridTo(const Grid& grid, const std::string& path, const EncodeOptions& options,
                    Durability durability, std::size_t* bytes_written) {
  LINEMAP_ASSIGN_OR_RETURN(std::vector<std::uint8_t> bytes, EncodeLmap(grid, options));
  LINEMAP_RETURN_IF_ERROR(WriteFileAtomic(
      path, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()),
      durability));
  *bytes_written = bytes.size();
  return Status::Ok();
}

constexpr const char* kMapType = "nav_msgs/OccupancyGrid";

// "the topics it holds", for the message when the asked one is missing.
std::string DescribeTopics(const rosbag::Bag& bag) {
  rosbag::View view(bag);
  std::string text;
  std::set<std::string> seen;
  for (const rosbag::ConnectionInfo* connection : view.getConnections()) {
    if (!seen.insert(connection->topic).second) continue;
    rosbag::View topic_view(bag, rosbag::TopicQuery(connection->topic));
    if (!text.empty()) text += ", ";
    text += connection->topic + " (" + connection->datatype + ", " +
            std::to_string(topic_view.size()) + " messages)";
  }
  return text.empty() ? "no messages" : text;
}

// Checks that the topic exists in the bag and carries maps only.
Status CheckTopic(const rosbag::Bag& bag, const std::string& bag_path, const std::string& topic) {
  rosbag::View view(bag, rosbag::TopicQuery(topic));
  if (view.size() == 0) {
    return InvalidArgumentError("'" + bag_path + "' has no messages on topic '" + topic +
                                "'; it holds " + DescribeTopics(bag));
  }
  for (const rosbag::ConnectionInfo* connection : view.getConnections()) {
    if (connection->datatype != kMapType) {
      return InvalidArgumentError("'" + bag_path + "': topic '" + topic + "' holds " +
                                  connection->datatype + ", not " + kMapType);
    }
  }
  return Status::Ok();
}

// "SEC_NSEC" of the header stamp, or of the time the bag recorded the
// message when the publisher left the stamp at zero.
std::string StampName(const ros_bridge::OccupancyGridMsg& map, const ros::Time& recorded) {
  const ros::Time stamp = map.header.stamp.isZero() ? recorded : map.header.stamp;
  char text[32];
  std::snprintf(text, sizeof(text), "%u_%09u", stamp.sec, stamp.nsec);
  return text;
}

// Reads and encodes; rosbag reports errors as exceptions, caught by the caller.
int EncodeBagMessages(const std::string& bag_path, const BagSelection& selection,
                      const EncodeOptions& options) {
  rosbag::Bag bag;
  bag.open(bag_path, rosbag::bagmode::Read);
  if (const Status topic_ok = CheckTopic(bag, bag_path, selection.topic); !topic_ok.ok()) {
    return ReportError("encode", topic_ok);
  }
  rosbag::View view(bag, rosbag::TopicQuery(selection.topic));
  const std::uint64_t count = view.size();
  if (selection.index && *selection.index >= count) {
    return ReportError("encode", InvalidArgumentError(
                                     "'" + bag_path + "': --index " +
                                     std::to_string(*selection.index) + " but topic '" +
                                     selection.topic + "' holds " + std::to_string(count) +
                                     " maps (0.." + std::to_string(count - 1) + ")"));
  }
  const std::uint64_t wanted = selection.index.value_or(count - 1);
  if (selection.all) {
    if (const Status made = EnsureFolder(selection.out); !made.ok()) {
      return ReportError("encode", made);
    }
  }
  std::set<std::string> names;
  std::uint64_t k = 0;
  for (const rosbag::MessageInstance& instance : view) {
    const std::uint64_t this_index = k++;
    if (!selection.all && this_index != wanted) continue;
    ros_bridge::OccupancyGridMsg::ConstPtr map = instance.instantiate<ros_bridge::OccupancyGridMsg>();
    const std::string where = "'" + bag_path + "' " + selection.topic + " message " +
                              std::to_string(this_index);
    if (map == nullptr) {
      return ReportError("encode", CorruptError(where + " is not a " + kMapType));
    }
    StatusOr<Grid> grid = GridFromOccupancyGrid(ros_bridge::FromRosMessage(*map),
                                                selection.thresholds, selection.max_cells);
    if (!grid.ok()) return ReportError("encode", grid.status().WithContext(where));
    std::string out = selection.out;
    if (selection.all) {
      // Two maps with one stamp get _1, _2, ... after the first.
      const std::string stamp = StampName(*map, instance.getTime());
      std::string name = stamp;
      for (int n = 1; names.count(name) > 0; ++n) name = stamp + "_" + std::to_string(n);
      names.insert(name);
      out = selection.out + (selection.out.ends_with("/") ? "" : "/") + name + ".lmap";
    }
    std::size_t bytes = 0;
    if (const Status written = EncodeGridTo(*grid, out, options, selection.durability, &bytes);
        !written.ok()) {
      return ReportError("encode", written.WithContext(where));
    }
    std::printf("%s message %llu of %llu: %d x %d cells -> %s, %zu bytes\n",
                selection.topic.c_str(), static_cast<unsigned long long>(this_index),
                static_cast<unsigned long long>(count), grid->width(), grid->height(),
                out.c_str(), bytes);
    if (!selection.all) break;
  }
  return kExitOk;
}

}  // namespace
#endif  // LINEMAP_HAVE_ROSBAG

int EncodeBag(const std::string& bag_path, const ParsedArgs& args, const EncodeOptions& options) {
#ifdef LINEMAP_HAVE_ROSBAG
  StatusOr<BagSelection> selection = BagSelectionFrom(args);
  if (!selection.ok()) return ReportError("encode", selection.status());
  try {
    return EncodeBagMessages(bag_path, *selection, options);
  } catch (const std::exception& error) {
    // rosbag::BagException for a missing or malformed bag, and
    // deserialisation errors from a truncated message.
    return ReportError("encode", InvalidArgumentError("'" + bag_path + "': cannot read it as a "
                                                      "ROS 1 bag: " + error.what()));
  }
#else
  (void)args;
  (void)options;
  return ReportError("encode",
                     UnsupportedError("'" + bag_path + "': this linemap was built without ROS 1 "
                                      "bag support (rosbag was not found when it was built; "
                                      "install librosbag-dev libnav-msgs-dev and rebuild)"));
#endif
}

}  // namespace linemap::cli
