// lmap_server: map_server for .lmap files (and map YAMLs / images).
//
//   lmap_server [MAP] [--wait-master S] [__name:=...] [_frame_id:=map] [_window:=x0,y0,x1,y1]
//
// Publishes the map latched on `map` (nav_msgs/OccupancyGrid) and its
// metadata on `map_metadata` (nav_msgs/MapMetaData), and serves it on
// `static_map` (nav_msgs/GetMap), as map_server does. MAP is the argument or
// the private parameter ~map. A ~window that reaches past the map is
// refused. Exit codes: 1 no master or a ROS failure, 2 bad usage, a map that
// cannot be read or a window past it.
#include <ros/ros.h>

#include <cstdio>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "linemap/lmap_vectors.h"
#include "ros/node_support.h"
#include "ros/ros_conversion.h"
#include "ros/served_map.h"

namespace linemap::ros_bridge {
namespace {

constexpr const char* kUsage =
    "usage: lmap_server [MAP] [--wait-master S]\n"
    "  MAP               .lmap file, map YAML or PGM/PNG image (or the parameter ~map)\n"
    "  --wait-master S   seconds to wait for the ROS master (default 10)\n"
    "parameters: ~map, ~frame_id (default map), ~window x0,y0,x1,y1 (metres, optional;\n"
    "            the cells whose squares overlap it, refused when it reaches past the map)\n"
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
  // The map and window the command line names (MAP or `_map:=`,
  // `_window:=`) are read before the master is waited for: a map that
  // cannot be read, or a window past it, is refused at once (exit 2), not
  // after the wait. roscpp puts `_name:=` arguments on the parameter server
  // over what a launch file set, so ~map and ~window would hold these.
  std::optional<std::string> map_path = args->map_path;
  if (!map_path) map_path = PrivateParameterArgument(argc, argv, "map");
  const std::optional<std::string> window_text = PrivateParameterArgument(argc, argv, "window");
  std::optional<Window> window;
  if (window_text) {
    StatusOr<Window> parsed = ParseWindow(*window_text);
    if (!parsed.ok()) {
      std::fprintf(stderr, "lmap_server: %s\n", parsed.status().message().c_str());
      return kExitBadInput;
    }
    window = *parsed;
  }
  std::optional<Grid> grid;
  if (map_path && !window_text && IsLmapPath(*map_path)) {
    // A window may still come from the parameter server (a launch file's
    // <param>): the file is checked now (its header and every chunk's CRC)
    // and decoded once the window is known, so that only the window's tiles
    // are (on the 282-Mcell office map 17 MB rather than 300).
    const StatusOr<LmapHeader> header = LoadLmapHeader(*map_path);
    if (!header.ok()) {
      std::fprintf(stderr, "lmap_server: %s\n", header.status().message().c_str());
      return ExitCodeFor(header.status());
    }
  } else if (map_path) {
    StatusOr<Grid> loaded = LoadServedMap(*map_path, window);
    if (!loaded.ok()) {
      std::fprintf(stderr, "lmap_server: %s\n", loaded.status().message().c_str());
      return ExitCodeFor(loaded.status());
    }
    grid = std::move(*loaded);
  }

  const Status master =
      InitNodeAndWaitForMaster(argc, argv, "lmap_server", /*options=*/0, args->wait_master_seconds);
  if (!master.ok()) {
    std::fprintf(stderr, "lmap_server: %s\n", master.message().c_str());
    return kExitFailure;
  }
  ros::NodeHandle private_nh("~");
  if (!map_path) {
    std::string param;
    if (!private_nh.getParam("map", param)) {
      std::fprintf(stderr, "lmap_server: no map given (argument MAP or parameter ~map)\n%s",
                   kUsage);
      return kExitBadInput;
    }
    map_path = param;
  }
  const std::string frame_id = private_nh.param<std::string>("frame_id", "map");
  if (!window_text) {
    // Only the parameter server (a launch file's <param>) can hold one now.
    StatusOr<std::optional<Window>> parameter = WindowParameter(private_nh);
    if (!parameter.ok()) {
      std::fprintf(stderr, "lmap_server: %s\n", parameter.status().message().c_str());
      return kExitBadInput;
    }
    window = *parameter;
    if (grid && window) {
      // The map was read whole before the master answered: crop it to the
      // same cells LoadServedMap would have decoded.
      StatusOr<Grid> cropped = CropToWindow(*grid, *window);
      if (!cropped.ok()) {
        std::fprintf(stderr, "lmap_server: '%s': %s\n", map_path->c_str(),
                     cropped.status().message().c_str());
        return ExitCodeFor(cropped.status());
      }
      grid = std::move(*cropped);
    }
  }
  if (!grid) {
    StatusOr<Grid> loaded = LoadServedMap(*map_path, window);
    if (!loaded.ok()) {
      std::fprintf(stderr, "lmap_server: %s\n", loaded.status().message().c_str());
      return ExitCodeFor(loaded.status());
    }
    grid = std::move(*loaded);
  }
  MapServer server(RosMessageFromGrid(*grid, frame_id, ros::Time::now()));
  ROS_INFO("lmap_server: serving %s: %d x %d cells at %.3f m/cell, frame '%s'", map_path->c_str(),
           grid->width(), grid->height(), grid->meta.resolution, frame_id.c_str());
  ros::spin();
  return kExitOk;
}

}  // namespace
}  // namespace linemap::ros_bridge

int main(int argc, char** argv) { return linemap::ros_bridge::Run(argc, argv); }
