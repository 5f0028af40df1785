#include "tools/linemap/bag_input.h"

#include <dlfcn.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <optional>
#include <set>
#include <string_view>

#include "format/file_io.h"
#include "format/iso_time.h"
#include "linemap/map_io.h"
#include "linemap/occupancy_grid.h"
#include "ros/bag_reader.h"
#include "tools/linemap/json.h"

namespace linemap::cli {

std::vector<OptionSpec> WithBagOptions(std::vector<OptionSpec> options) {
  options.push_back({"--topic", "TOPIC",
                     "MAP is a ROS 1 bag: read nav_msgs/OccupancyGrid messages on TOPIC "
                     "(default /map); the last one unless --index or --all"});
  options.push_back({"--index", "K", "bag: encode the K-th map on the topic (0 = first)"});
  options.push_back({"--all", "",
                     "bag: encode every map on the topic into the folder -o names (made when "
                     "missing), as SEC_NSEC.lmap by the header stamps"});
  return options;
}

namespace {

bool HasBagOption(const ParsedArgs& args) {
  return args.Get("--topic") || args.Get("--index") || args.Has("--all");
}

}  // namespace

bool IsBagInput(const std::string& input, const ParsedArgs& args) {
  return HasExtension(input, ".bag") || HasBagOption(args);
}

Status CheckBagOptionsApplyTo(const std::string& input, const ParsedArgs& args) {
  if (!HasBagOption(args)) return Status::Ok();
  for (const char* ext : {".yaml", ".yml", ".pgm", ".png", ".lmap"}) {
    if (HasExtension(input, ext)) {
      return InvalidArgumentError("--topic, --index and --all read a ROS 1 bag; '" + input +
                                  "' is a map or an .lmap file");
    }
  }
  return Status::Ok();
}

namespace {

// What selects the messages and where they go, read from the arguments.
struct BagSelection {
  std::string topic = "/map";
  std::optional<std::uint64_t> index;  // nullopt: the last (or all)
  bool all = false;
  std::string out;  // OUT.lmap, or the folder with --all
  OccupancyThresholds thresholds;
  std::uint64_t max_cells = MapLoadOptions{}.max_cells;  // as for a map image
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
    LINEMAP_ASSIGN_OR_RETURN(selection.index, args.GetUint64("--index", 0, /*min=*/0));
    if (*selection.index > static_cast<std::uint64_t>(INT64_MAX)) {
      return InvalidArgumentError("--index is too large");
    }
  }
  std::optional<std::string> out = args.Get("-o");
  if (!out) {
    return InvalidArgumentError(selection.all ? "missing -o DIR (the folder for the .lmap files)"
                                              : "missing -o OUT.lmap");
  }
  selection.out = *out;
  if (!selection.all && !HasExtension(selection.out, ".lmap")) {
    return InvalidArgumentError("output '" + selection.out + "' must end in .lmap");
  }
  if (!selection.all && IsDirectory(selection.out)) {
    return InvalidArgumentError("'" + selection.out + "' is a directory");
  }
  // Before the bag is read: an output that cannot be written is refused
  // now, not after every map on the topic has been encoded.
  LINEMAP_RETURN_IF_ERROR(selection.all
                              ? CheckOutputFolderWritable(selection.out, /*make_parents=*/false)
                              : CheckOutputWritable(selection.out));
  // The int8 occupancies are read with map_saver's thresholds (0.65 / 0.25)
  // unless these are given.
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

// The folder for --all: made when missing (one level, as `mkdir`). True
// when it was made here.
StatusOr<bool> EnsureFolder(const std::string& dir) {
  if (IsDirectory(dir)) return false;
  if (::mkdir(dir.c_str(), 0777) != 0) {
    const int err = errno;
    return IoError("cannot make the folder '" + dir + "': " + std::strerror(err)).WithErrno(err);
  }
  return true;
}

#ifdef LINEMAP_ROSBAG_MODULE_NAME
// The folder of the running program, with its trailing slash ("" if unknown).
std::string ProgramFolder() {
  char path[PATH_MAX];
  const ssize_t n = ::readlink("/proc/self/exe", path, sizeof(path) - 1);
  if (n <= 0) return "";
  const std::string program(path, static_cast<std::size_t>(n));
  return program.substr(0, program.rfind('/') + 1);
}
#endif

// Loads the bag reader module: $LINEMAP_ROSBAG_MODULE when set, else
// liblinemap_rosbag.so beside the program (the build tree), else in the
// installed module folder relative to it.
StatusOr<ros_bridge::BagMapReaderFn> LoadBagReader() {
#ifdef LINEMAP_ROSBAG_MODULE_NAME
  std::vector<std::string> candidates;
  if (const char* env = std::getenv("LINEMAP_ROSBAG_MODULE"); env != nullptr && env[0] != '\0') {
    candidates.push_back(env);
  } else {
    const std::string folder = ProgramFolder();
    candidates.push_back(folder + LINEMAP_ROSBAG_MODULE_NAME);
    candidates.push_back(folder + LINEMAP_ROSBAG_MODULE_INSTALL_FOLDER
                         "/" LINEMAP_ROSBAG_MODULE_NAME);
  }
  std::string errors;
  for (const std::string& candidate : candidates) {
    if (::access(candidate.c_str(), F_OK) != 0) continue;
    // The module stays loaded until the program exits (ROS libraries do
    // not support being unloaded).
    void* handle = ::dlopen(candidate.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (handle == nullptr) {
      errors += std::string("; ") + ::dlerror();
      continue;
    }
    void* symbol = ::dlsym(handle, ros_bridge::kBagReaderSymbol);
    if (symbol != nullptr) return reinterpret_cast<ros_bridge::BagMapReaderFn>(symbol);
    errors += "; " + candidate + " has no " + ros_bridge::kBagReaderSymbol;
  }
  return IoError("cannot load the ROS 1 bag reader " LINEMAP_ROSBAG_MODULE_NAME " (looked in " +
                 candidates.front() + (candidates.size() > 1 ? " and " + candidates.back() : "") +
                 ")" + errors);
#else
  return UnsupportedError(
      "this linemap was built without ROS 1 bag support (CMake found no rosbag, or "
      "LINEMAP_BUILD_ROS was off; install librosbag-dev libnav-msgs-dev and rebuild)");
#endif
}

// Encodes each map the reader hands over; the first failure stops the read.
struct EncodeVisit {
  const BagSelection* selection;
  const EncodeOptions* options;
  std::string bag_path;
  bool json = false;              // one JSON object per map written, a line each
  std::set<std::string> names{};  // --all: file names given so far
  bool made_folder = false;       // --all: the folder was made for this run
  std::size_t written = 0;        // files written
  Status status{};
};

// With --all, the folder is made when its first map is written, so that a
// bag that cannot be read, or holds no map, leaves nothing behind (and
// EncodeBag takes it back when that first write fails).
StatusOr<std::string> OutputPath(EncodeVisit* visit, const std::string& stamp) {
  if (!visit->selection->all) return visit->selection->out;
  if (visit->names.empty()) {
    LINEMAP_ASSIGN_OR_RETURN(visit->made_folder, EnsureFolder(visit->selection->out));
  }
  // Two maps with one stamp get _1, _2, ... after the first.
  std::string name = stamp;
  for (int n = 1; visit->names.count(name) > 0; ++n) name = stamp + "_" + std::to_string(n);
  visit->names.insert(name);
  const std::string& dir = visit->selection->out;
  return dir + (dir.ends_with("/") ? "" : "/") + name + ".lmap";
}

Status EncodeOne(EncodeVisit* visit, std::uint64_t index, std::uint64_t count,
                 const std::string& stamp, const OccupancyGridMessage& message) {
  const BagSelection& selection = *visit->selection;
  const std::string where =
      "'" + visit->bag_path + "' " + selection.topic + " message " + std::to_string(index);
  StatusOr<Grid> grid = GridFromOccupancyGrid(message, selection.thresholds, selection.max_cells);
  if (!grid.ok()) return grid.status().WithContext(where);
  // A map of no cells is no map a robot saved, and its file would decode
  // to nothing a map server can serve.
  if (grid->size() == 0) {
    const std::string what = where + ": a map of " + std::to_string(grid->width()) + " x " +
                             std::to_string(grid->height()) + " cells: nothing to save";
    // With --all the other maps are still saved; the empty one is named.
    if (selection.all) {
      std::fprintf(stderr, "linemap encode: %s (skipped)\n", what.c_str());
      return Status::Ok();
    }
    return InvalidArgumentError(what);
  }
  if (const std::optional<Pose2D>& pose = visit->options->robot_pose) {
    // As for a map file, the pose must fall in a cell (the one whose square
    // holds it) of every map it is stored with.
    if (!grid->CellHolding(pose->x, pose->y)) {
      return InvalidArgumentError(where + ": --pose is outside the map (" +
                                  std::to_string(grid->width()) + " x " +
                                  std::to_string(grid->height()) + " cells)");
    }
  }
  // --metadata names the map's frame and time: a message says its own (its
  // stamp, "SEC_NSEC", as ISO 8601 UTC, unless --time gave one).
  EncodeOptions options = *visit->options;
  if (!options.frame_id.empty() && !message.frame_id.empty()) options.frame_id = message.frame_id;
  std::uint32_t sec = 0, nsec = 0;
  if (!options.creator.empty() && options.time.empty() &&
      std::sscanf(stamp.c_str(), "%u_%u", &sec, &nsec) == 2) {
    options.time = Iso8601FromStamp(sec, nsec);
  }
  StatusOr<std::vector<std::uint8_t>> bytes = EncodeLmap(*grid, options);
  if (!bytes.ok()) return bytes.status().WithContext(where);
  LINEMAP_ASSIGN_OR_RETURN(std::string out, OutputPath(visit, stamp));
  LINEMAP_RETURN_IF_ERROR(WriteFileAtomic(
      out, std::string_view(reinterpret_cast<const char*>(bytes->data()), bytes->size()),
      selection.durability));
  ++visit->written;
  if (visit->json) {
    JsonObject json;
    json.Add("topic", selection.topic)
        .Add("index", std::uint64_t{index})
        .Add("count", std::uint64_t{count})
        .Add("width", grid->width())
        .Add("height", grid->height())
        .Add("output", out)
        .Add("bytes", std::uint64_t{bytes->size()});
    std::printf("%s\n", json.str().c_str());
    return Status::Ok();
  }
  std::printf("%s message %llu of %llu: %d x %d cells -> %s, %zu bytes\n", selection.topic.c_str(),
              static_cast<unsigned long long>(index), static_cast<unsigned long long>(count),
              grid->width(), grid->height(), out.c_str(), bytes->size());
  return Status::Ok();
}

bool VisitMap(void* context, std::uint64_t index, std::uint64_t count, const std::string& stamp,
              const OccupancyGridMessage& message) {
  auto* visit = static_cast<EncodeVisit*>(context);
  visit->status = EncodeOne(visit, index, count, stamp, message);
  return visit->status.ok();
}

}  // namespace

int EncodeBag(const std::string& bag_path, const ParsedArgs& args, const EncodeOptions& options) {
  StatusOr<ros_bridge::BagMapReaderFn> reader = LoadBagReader();
  if (!reader.ok()) return ReportError("encode", reader.status().WithContext("'" + bag_path + "'"));
  StatusOr<BagSelection> selection = BagSelectionFrom(args);
  if (!selection.ok()) return ReportError("encode", selection.status());
  EncodeVisit visit{.selection = &*selection,
                    .options = &options,
                    .bag_path = bag_path,
                    .json = args.Has("--json")};
  ros_bridge::BagMapRequest request;
  request.bag_path = bag_path;
  request.topic = selection->topic;
  request.index = selection->index ? static_cast<std::int64_t>(*selection->index) : -1;
  request.all = selection->all;
  request.visit = &VisitMap;
  request.context = &visit;
  const ros_bridge::BagReadOutcome outcome = (*reader)(&request);
  if (outcome == ros_bridge::BagReadOutcome::kOk) return kExitOk;
  // A folder made for --all whose first file could not be written (a full
  // disk, a name too long) is taken back, whatever stopped the read:
  // nothing half-made is left. rmdir removes only an empty folder, and a
  // folder that was there before is kept.
  if (visit.made_folder && visit.written == 0) (void)::rmdir(selection->out.c_str());
  switch (outcome) {
    case ros_bridge::BagReadOutcome::kOk:
      return kExitOk;
    case ros_bridge::BagReadOutcome::kStopped:
      return ReportError("encode", visit.status);
    case ros_bridge::BagReadOutcome::kBadInput:
      break;
  }
  return ReportError("encode", InvalidArgumentError(request.error));
}

}  // namespace linemap::cli
