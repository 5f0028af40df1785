// lmap_server: map_server for .lmap files (and map YAMLs / images).
//
//   lmap_server [MAP] [--wait-master S] [__name:=...] [_frame_id:=map] [_window:=x0,y0,x1,y1]
//
// Publishes the map latched on `map` (nav_msgs/OccupancyGrid) and its
// metadata on `map_metadata` (nav_msgs/MapMetaData), and serves it on
// `static_map` (nav_msgs/GetMap), as map_server does. MAP is the argument or
// the private parameter ~map. Exit codes: 1 no master or a ROS failure, 2
// bad usage or a map that cannot be read.
#include <ros/ros.h>

#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "ros/node_support.h"
#include "ros/ros_conversion.h"
#include "ros/served_map.h"

namespace linemap::ros_bridge {
namespace {

constexpr const char* kUsage =
    "usage: lmap_server [MAP] [--wait-master S]\n"
    "  MAP               .lmap file, map YAML or PGM/PNG image (or the parameter ~map)\n"
    "  --wait-master S   seconds to wait for the ROS master (default 10)\n"
    "parameters: ~map, ~frame_id (default map), ~window x0,y0,x1,y1 (metres, optional)\n"
    "publishes map (latched), map_metadata (latched); serves static_map\n";

struct ServerArgs {
  std::optional<std::string> map_path;
  double wait_master_seconds = kDefaultMasterWaitSeconds;
};

StatusOr<ServerArgs> ParseServerArgs(const std::vector<std::string>& args) {
  ServerArgs parsed;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    if (arg == "--wait-master") {
      if (i + 1 >= args.size()) return InvalidArgumentError("--wait-master needs a value");
      LINEMAP_ASSIGN_OR_RETURN(parsed.wait_master_seconds, ParseSeconds(arg, args[++i]));
    } else if (arg.starts_with("-")) {
      return InvalidArgumentError("unknown option '" + arg + "'");
    } else if (parsed.map_path) {
      return InvalidArgumentError("more than one MAP given ('" + *parsed.map_path + "', '" + arg +
                                  "')");
    } else {
      parsed.map_path = arg;
    }
  }
  return parsed;
}

// ~window as a list [x0, y0, x1, y1] or a string "x0,y0,x1,y1"; nullopt when
// it is not set.
StatusOr<std::optional<Window>> WindowParameter(const ros::NodeHandle& private_nh) {
  if (!private_nh.hasParam("window")) return std::optional<Window>();
  std::vector<double> values;
  if (private_nh.getParam("window", values)) {
    LINEMAP_ASSIGN_OR_RETURN(Window window,
                             WindowFromValues(values.data(), static_cast<int>(values.size())));
    return std::optional<Window>(window);
  }
  std::string text;
  if (private_nh.getParam("window", text)) {
    LINEMAP_ASSIGN_OR_RETURN(Window window, ParseWindow(text));
    return std::optional<Window>(window);
  }
  return InvalidArgumentError("~window must be x0,y0,x1,y1 in metres");
}

class MapServer {
 public:
  explicit MapServer(OccupancyGridMsg map) : map_(std::move(map)) {
    ros::NodeHandle nh;
    map_pub_ = nh.advertise<OccupancyGridMsg>("map", 1, /*latch=*/true);
    metadata_pub_ = nh.advertise<MapMetaDataMsg>("map_metadata", 1, /*latch=*/true);
    service_ = nh.advertiseService("static_map", &MapServer::ServeMap, this);
    metadata_pub_.publish(map_.info);
    map_pub_.publish(map_);
  }

 private:
  bool ServeMap(GetMapRequestMsg& /*request*/, GetMapResponseMsg& response) {
    response.map = map_;
    return true;
  }

  OccupancyGridMsg map_;
  ros::Publisher map_pub_;
  ros::Publisher metadata_pub_;
  ros::ServiceServer service_;
};

int Run(int argc, char** argv) {
  if (StartNodeOutput(argc, argv, kUsage)) return kExitOk;
  StatusOr<ServerArgs> args = ParseServerArgs(NonRosArguments(argc, argv));
  if (!args.ok()) {
    std::fprintf(stderr, "lmap_server: %s\n%s", args.status().message().c_str(), kUsage);
    return kExitBadInput;
  }
  UseDefaultMasterUriIfUnset(argc, argv);
  ros::init(argc, argv, "lmap_server");
  const Status master = WaitForMaster(args->wait_master_seconds);
  if (!master.ok()) {
    std::fprintf(stderr, "lmap_server: %s\n", master.message().c_str());
    return kExitFailure;
  }
  ros::NodeHandle private_nh("~");
  std::string map_path;
  if (args->map_path) {
    map_path = *args->map_path;
  } else if (!private_nh.getParam("map", map_path)) {
    std::fprintf(stderr, "lmap_server: no map given (argument MAP or parameter ~map)\n%s", kUsage);
    return kExitBadInput;
  }
  const std::string frame_id = private_nh.param<std::string>("frame_id", "map");
  StatusOr<std::optional<Window>> window = WindowParameter(private_nh);
  if (!window.ok()) {
    std::fprintf(stderr, "lmap_server: %s\n", window.status().message().c_str());
    return kExitBadInput;
  }
  StatusOr<Grid> grid = LoadServedMap(map_path, *window);
  if (!grid.ok()) {
    std::fprintf(stderr, "lmap_server: %s\n", grid.status().message().c_str());
    return ExitCodeFor(grid.status());
  }
  MapServer server(RosMessageFromGrid(*grid, frame_id, ros::Time::now()));
  ROS_INFO("lmap_server: serving %s: %d x %d cells at %.3f m/cell, frame '%s'", map_path.c_str(),
           grid->width(), grid->height(), grid->meta.resolution, frame_id.c_str());
  ros::spin();
  return kExitOk;
}

}  // namespace
}  // namespace linemap::ros_bridge

int main(int argc, char** argv) { return linemap::ros_bridge::Run(argc, argv); }
