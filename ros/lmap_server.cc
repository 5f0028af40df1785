// lmap_server: map_server for .lmap files (and map YAMLs / images).
//
//   lmap_server [MAP] [--wait-master S] [__name:=...] [_frame_id:=map] [_window:=x0,y0,x1,y1]
//               [_max_cells:=N] [_max_segments:=N] [_max_objects:=N]
//
// Publishes the map latched on `map` (nav_msgs/OccupancyGrid) and its
// metadata on `map_metadata` (nav_msgs/MapMetaData), and serves it on
// `static_map` (nav_msgs/GetMap), as map_server does. MAP is the argument or
// the private parameter ~map. A ~window that reaches past the map is
// refused, and so is a map over ~max_cells, ~max_segments or ~max_objects
// (the decoder's limits, DecodeLimits), naming the one it is over. Exit
// codes: 1 no master or a ROS failure, 2 bad usage, a bad parameter, a map
// that cannot be read, one over a limit or a window past it.
#include <ros/ros.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <span>
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
    "parameters: ~map, ~frame_id (default: the frame_id an .lmap file names, else map),\n"
    "            ~window x0,y0,x1,y1 (metres, optional;\n"
    "            the cells whose centres lie in it, as linemap decode --window takes them;\n"
    "            refused when it reaches past the map)\n"
    "  maps over a limit are refused; each a whole number from 1 to 2147483647:\n"
    "  ~max_cells N      cells of the whole map, also of a map image, with a ~window too\n"
    "                    (default 1073741824 = 2^30)\n"
    "  ~max_segments N   wall segments per chunk of an .lmap file, or per band of layer\n"
    "                    sections read together (default 16777216 = 2^24)\n"
    "  ~max_objects N    rooms, and furniture objects, per .lmap file (default 1048576 = 2^20)\n"
    "publishes map (latched), map_metadata (latched); serves static_map\n";
// The defaults kUsage gives.
static_assert(DecodeLimits{}.max_cells == std::uint64_t{1} << 30);
static_assert(DecodeLimits{}.max_segments == std::uint64_t{1} << 24);
static_assert(DecodeLimits{}.max_objects == std::uint64_t{1} << 20);

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

// The values of ~max_cells, ~max_segments and ~max_objects (in the order of
// LimitParameters()) that are known: nullopt for one that is not set (yet).
using LimitValues = std::vector<std::optional<std::uint64_t>>;

// The limits given as `_NAME:=VALUE` arguments.
StatusOr<LimitValues> LimitArguments(int argc, char** argv) {
  LimitValues values;
  for (const LimitParameter& limit : LimitParameters()) {
    const std::optional<std::string> text = PrivateParameterArgument(argc, argv, limit.name());
    if (!text) {
      values.emplace_back();
      continue;
    }
    LINEMAP_ASSIGN_OR_RETURN(const std::uint64_t value, ParseLimit(limit, *text));
    values.emplace_back(value);
  }
  return values;
}

// A limit's value as the parameter server holds it: an int, a whole double
// or their text.
StatusOr<std::uint64_t> LimitFromXmlRpc(const LimitParameter& limit, XmlRpc::XmlRpcValue& value) {
  switch (value.getType()) {
    case XmlRpc::XmlRpcValue::TypeInt:
      return LimitFromNumber(limit, static_cast<int>(value));
    case XmlRpc::XmlRpcValue::TypeDouble:
      return LimitFromNumber(limit, static_cast<double>(value));
    case XmlRpc::XmlRpcValue::TypeString:
      return ParseLimit(limit, static_cast<std::string>(value));
    case XmlRpc::XmlRpcValue::TypeBoolean:
      return LimitRangeError(limit, static_cast<bool>(value) ? "true" : "false");
    default:
      return LimitRangeError(limit, "a list, a dictionary or a date");
  }
}

// ~NAME on the parameter server, or nullopt when it is not set.
StatusOr<std::optional<std::uint64_t>> LimitParameterValue(const ros::NodeHandle& private_nh,
                                                           const LimitParameter& limit) {
  XmlRpc::XmlRpcValue value;
  if (!private_nh.getParam(limit.name(), value)) return std::optional<std::uint64_t>();
  LINEMAP_ASSIGN_OR_RETURN(const std::uint64_t parsed, LimitFromXmlRpc(limit, value));
  return std::optional<std::uint64_t>(parsed);
}

// `known` with the limits it lacks read from the parameter server (a launch
// file's <param>); `_NAME:=` arguments are there too, with the same values.
StatusOr<LimitValues> CompleteLimits(const ros::NodeHandle& private_nh, LimitValues known) {
  const std::span<const LimitParameter> limits = LimitParameters();
  for (std::size_t i = 0; i < limits.size(); ++i) {
    if (known[i]) continue;
    LINEMAP_ASSIGN_OR_RETURN(known[i], LimitParameterValue(private_nh, limits[i]));
  }
  return known;
}

// DecodeLimits with `values`, and `unset` for the limits not known; the
// library's defaults for unset = nullopt.
DecodeLimits LimitsOf(const LimitValues& values, std::optional<std::uint64_t> unset) {
  DecodeLimits limits;
  const std::span<const LimitParameter> parameters = LimitParameters();
  for (std::size_t i = 0; i < parameters.size(); ++i) {
    if (values[i] || unset) limits.*parameters[i].field = values[i] ? *values[i] : *unset;
  }
  return limits;
}

// Whether every limit that applies to the map at `path` is known: it may
// then be loaded before the master answers, as no ~NAME on the parameter
// server can change them.
bool LimitsSettledFor(const std::string& path, const LimitValues& values) {
  // LimitParametersFor(path) is the first of LimitParameters(), the order
  // of `values`.
  const std::size_t applying = LimitParametersFor(path).size();
  return std::all_of(values.begin(), values.begin() + applying,
                     [](const std::optional<std::uint64_t>& value) { return value.has_value(); });
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

// Prints `status` as lmap_server's error; returns its exit code.
int Refuse(const Status& status) {
  std::fprintf(stderr, "lmap_server: %s\n", status.message().c_str());
  return ExitCodeFor(status);
}

// The frame a map is served in without ~frame_id: the one an .lmap file
// names (its `frame_id` metadata, as `lmap_saver --metadata` and `linemap
// encode --metadata` store it; the last entry of a repeated key), else map.
std::string DefaultFrameId(const std::string& path, const DecodeLimits& limits) {
  std::string frame_id = "map";
  if (!IsLmapPath(path)) return frame_id;
  const StatusOr<LmapHeader> header = LoadLmapHeader(path, limits);
  if (!header.ok()) return frame_id;  // the load that follows reports it
  for (const auto& [key, value] : header->metadata) {
    if (key == "frame_id" && !value.empty()) frame_id = value;
  }
  return frame_id;
}

// ", saved within a tolerance of T cells (x m)" for an .lmap file that names
// its T, which tells whoever reads the log what the served map promises;
// "" otherwise (the file is read again, its layers and cells not decoded).
std::string ToleranceNote(const std::string& path, double resolution, const DecodeLimits& limits) {
  if (!IsLmapPath(path)) return "";
  const StatusOr<std::optional<int>> t = LoadLmapToleranceCells(path, limits);
  if (!t.ok() || !*t) return "";
  char text[96];
  std::snprintf(text, sizeof(text), ", saved within a tolerance of %d cell%s (%g m)", **t,
                **t == 1 ? "" : "s", **t * resolution);
  return text;
}

// The map named on the command line, before the master is waited for: a
// map that cannot be read, one over a limit given or a window past it is
// refused at once (exit 2), not after the wait. Loaded when the limits that
// apply are known (a map image whole, cropped to a ~window of the parameter
// server once it is known; an .lmap file for the window given), else nullopt.
StatusOr<std::optional<Grid>> LoadBeforeMaster(const std::string& path,
                                               const std::optional<Window>& window,
                                               const LimitValues& limits) {
  if (LimitsSettledFor(path, limits) && (window || !IsLmapPath(path))) {
    LINEMAP_ASSIGN_OR_RETURN(Grid grid, LoadServedMap(path, window, LimitsOf(limits, {})));
    return std::optional<Grid>(std::move(grid));
  }
  // A window or a limit may still come from the parameter server (a launch
  // file's <param>): the file is checked now (its header, an .lmap file's
  // every chunk's CRC, the window given) within the limits any parameter
  // could set, and decoded once they are known; an .lmap file then only the
  // window's tiles (on the 282-Mcell office map 17 MB rather than 300).
  LINEMAP_RETURN_IF_ERROR(CheckServedMap(path, window, LimitsOf(limits, kMaxLimitValue)));
  return std::optional<Grid>();
}

int Run(int argc, char** argv) {
  if (StartNodeOutput(argc, argv, kUsage)) return kExitOk;
  StatusOr<ServerArgs> args = ParseServerArgs(NonRosArguments(argc, argv));
  if (!args.ok()) {
    std::fprintf(stderr, "lmap_server: %s\n%s", args.status().message().c_str(), kUsage);
    return kExitBadInput;
  }
  // The map, window and limits the command line names (MAP or `_map:=`,
  // `_window:=`, `_max_cells:=` ...) are read before the master is waited
  // for. roscpp puts `_name:=` arguments on the parameter server over what a
  // launch file set, so ~map, ~window and the limits would hold these.
  std::optional<std::string> map_path = args->map_path;
  if (!map_path) map_path = PrivateParameterArgument(argc, argv, "map");
  const std::optional<std::string> window_text = PrivateParameterArgument(argc, argv, "window");
  std::optional<Window> window;
  if (window_text) {
    StatusOr<Window> parsed = ParseWindow(*window_text);
    if (!parsed.ok()) return Refuse(parsed.status());
    window = *parsed;
  }
  StatusOr<LimitValues> limits = LimitArguments(argc, argv);
  if (!limits.ok()) return Refuse(limits.status());
  std::optional<Grid> grid;
  if (map_path) {
    StatusOr<std::optional<Grid>> early = LoadBeforeMaster(*map_path, window, *limits);
    if (!early.ok()) return Refuse(early.status());
    grid = std::move(*early);
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
  // Only the parameter server (a launch file's <param>) can hold the
  // limits not given, and a window when none was.
  limits = CompleteLimits(private_nh, std::move(*limits));
  if (!limits.ok()) return Refuse(limits.status());
  // The file's own frame is read with the limits that apply, and only when
  // no ~frame_id names one.
  std::string frame_id;
  if (!private_nh.getParam("frame_id", frame_id)) {
    frame_id = DefaultFrameId(*map_path, LimitsOf(*limits, {}));
  }
  if (!window_text) {
    StatusOr<std::optional<Window>> parameter = WindowParameter(private_nh);
    if (!parameter.ok()) return Refuse(parameter.status());
    window = *parameter;
    if (grid && window) {
      // The map was read whole before the master answered: crop it to the
      // same cells LoadServedMap would have decoded.
      StatusOr<Grid> cropped = CropToWindow(*grid, *window);
      if (!cropped.ok()) return Refuse(cropped.status().WithContext("'" + *map_path + "'"));
      grid = std::move(*cropped);
    }
  }
  if (!grid) {
    StatusOr<Grid> loaded = LoadServedMap(*map_path, window, LimitsOf(*limits, {}));
    if (!loaded.ok()) return Refuse(loaded.status());
    grid = std::move(*loaded);
  }
  MapServer server(RosMessageFromGrid(*grid, frame_id, ros::Time::now()));
  ROS_INFO("lmap_server: serving %s: %d x %d cells at %.3f m/cell, frame '%s'%s", map_path->c_str(),
           grid->width(), grid->height(), grid->meta.resolution, frame_id.c_str(),
           ToleranceNote(*map_path, grid->meta.resolution, LimitsOf(*limits, {})).c_str());
  ros::spin();
  return kExitOk;
}

}  // namespace
}  // namespace linemap::ros_bridge

int main(int argc, char** argv) { return linemap::ros_bridge::Run(argc, argv); }
