// lmap_saver: map_saver writing .lmap files.
//
//   lmap_saver [-f NAME] [-t TOPIC] [--every] [--occ P] [--free P]
//              [--tolerance T] [--raster-only] [--compact] [--metadata]
//              [--wait-master S]
//
// Subscribes to `map` (nav_msgs/OccupancyGrid; remap it with map:=/other or
// name it with -t), writes NAME.lmap atomically when a map arrives and exits;
// with --every it keeps running and rewrites the file on every new map. Each
// save goes to an unnamed temporary file that is flushed and renamed over
// NAME.lmap (SaveLmap), so a saver killed at any moment leaves the previous
// file whole. Exit codes: 0 saved (or stopped before any map came), 1 no
// master or a failed write, 2 bad
// usage, an output that cannot be written (checked at startup) or a map
// message that is not a map (sizes that do not agree). With --every a map
// that cannot be saved is reported and the saver waits for the next one;
// its exit code is then that of the last map's save.
#include <ros/ros.h>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "format/file_io.h"
#include "format/iso_time.h"
#include "linemap/codec.h"
#include "linemap/tolerance.h"
#include "ros/node_support.h"
#include "ros/ros_conversion.h"

namespace linemap::ros_bridge {
namespace {

constexpr const char* kUsage =
    "usage: lmap_saver [-f NAME] [-t TOPIC] [--every] [--occ P] [--free P]\n"
    "                  [--tolerance T] [--raster-only] [--compact] [--metadata]\n"
    "                  [--wait-master S]\n"
    "  -f NAME          output file NAME.lmap (default map.lmap; .lmap is added when missing)\n"
    "  -t TOPIC         map topic (default map; also remappable as map:=TOPIC)\n"
    "  --every          keep running and rewrite the file on every new map; a map that\n"
    "                   cannot be saved is reported and the last file kept\n"
    "  --occ P          occupancy in percent at or above which a cell is occupied (default 65)\n"
    "  --free P         occupancy in percent at or below which a cell is free (default 25)\n"
    "  --tolerance T    cells (0..4) by which the stored map may differ (default 0: exact)\n"
    "  --raster-only    store the cells only, no vector layers\n"
    "  --compact        code the cells for size: about 4.5 % smaller, 2.7x the decode time\n"
    "                   (3.0 against 1.1 ms at the median; a median 4.8x per map, up to\n"
    "                   9.2x); with --raster-only the smallest exact file\n"
    "  --metadata       store who saved the file (creator \"linemap lmap_saver VERSION\"),\n"
    "                   the map's frame (frame_id) and its header stamp as an ISO 8601\n"
    "                   UTC time (time; none when the stamp is zero), as linemap info shows\n"
    "  --wait-master S  seconds to wait for the ROS master (default 10)\n";

struct SaverArgs {
  std::string path = "map.lmap";
  std::string topic = "map";
  bool every = false;
  OccupancyThresholds thresholds;
  EncodeOptions encode;
  bool metadata = false;
  double wait_master_seconds = kDefaultMasterWaitSeconds;
};

// map_saver's thresholds are whole percentages; the library takes
// probabilities.
StatusOr<double> ParsePercent(const std::string& option, const std::string& text) {
  LINEMAP_ASSIGN_OR_RETURN(double percent, ParseNumber(option, text));
  if (percent < 0 || percent > 100) return InvalidArgumentError(option + " must be in 0..100");
  return percent / 100.0;
}

StatusOr<SaverArgs> ParseSaverArgs(const std::vector<std::string>& args) {
  SaverArgs parsed;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    const bool has_value = i + 1 < args.size();
    const bool takes_value = arg == "-f" || arg == "-t" || arg == "--occ" || arg == "--free" ||
                             arg == "--tolerance" || arg == "--wait-master";
    if (takes_value && !has_value) return InvalidArgumentError(arg + " needs a value");
    if (arg == "-f") {
      parsed.path = args[++i];
      if (!parsed.path.ends_with(".lmap")) parsed.path += ".lmap";
    } else if (arg == "-t") {
      parsed.topic = args[++i];
    } else if (arg == "--every") {
      parsed.every = true;
    } else if (arg == "--occ") {
      LINEMAP_ASSIGN_OR_RETURN(parsed.thresholds.occupied, ParsePercent(arg, args[++i]));
    } else if (arg == "--free") {
      LINEMAP_ASSIGN_OR_RETURN(parsed.thresholds.free, ParsePercent(arg, args[++i]));
    } else if (arg == "--tolerance") {
      // Checked here, not left to the encoder: with --every a tolerance it
      // refuses would surface only when a map arrives. The range is checked
      // on the double, so that only a value an int holds is converted.
      LINEMAP_ASSIGN_OR_RETURN(double cells, ParseNumber(arg, args[++i]));
      if (!(cells >= 0 && cells <= kMaxToleranceCells) || cells != std::floor(cells)) {
        return InvalidArgumentError("--tolerance must be a whole number of cells in 0.." +
                                    std::to_string(kMaxToleranceCells) + ", not '" + args[i] + "'");
      }
      parsed.encode.tolerance_cells = static_cast<int>(cells);
    } else if (arg == "--raster-only") {
      parsed.encode.vector_layers = false;
    } else if (arg == "--compact") {
      parsed.encode.compact = true;
    } else if (arg == "--metadata") {
      parsed.metadata = true;
    } else if (arg == "--wait-master") {
      LINEMAP_ASSIGN_OR_RETURN(parsed.wait_master_seconds, ParseSeconds(arg, args[++i]));
    } else {
      return InvalidArgumentError("unknown argument '" + arg + "'");
    }
  }
  // The library's own check (whole percents), so that a map that arrives
  // later is never refused for thresholds accepted here.
  const Status thresholds = CheckOccupancyThresholds(parsed.thresholds);
  if (!thresholds.ok()) return thresholds.WithContext("--free / --occ");
  return parsed;
}

// A saver with --every encodes map after map. glibc returns the freed
// arrays of one encode to the kernel (memory above its trim threshold, and
// arrays it served by mmap), so the next encode faults them in again page
// by page: repeated in-process encodes on two threads took 24 ms on nav2's
// depot and 98 ms on its warehouse (1.7 Mcells) with glibc's defaults, 11
// and 33 ms with the settings below (this project's 2-core VM, where a
// page's first touch costs about 12 us). Arrays of up to 64 MB (16 Mcells
// of 4 bytes; less where glibc caps the threshold, below) come from the
// heap, freed memory of up to 256 MB stays with the process for the next
// save, and one arena serves both of the encoder's threads (and roscpp's).
// A single save gains too (fewer arrays mapped twice within it). A
// process-wide choice, so the node's, not the library's (the `linemap`
// tool makes it too, with larger bounds: it saves once and exits).
void KeepSaveMemoryForReuse() {
#if defined(__GLIBC__)
  constexpr int kMiB = 1 << 20;
  // Older glibc refuses a threshold over half its heap size (32 MiB on
  // 64-bit machines, 512 KiB on 32-bit ones): the largest it takes, halving
  // down to its default of 128 KiB.
  for (int bytes = 64 * kMiB; bytes >= 128 * 1024 && mallopt(M_MMAP_THRESHOLD, bytes) == 0;) {
    bytes /= 2;
  }
  mallopt(M_TRIM_THRESHOLD, 256 * kMiB);
  mallopt(M_ARENA_MAX, 1);
#endif
}

class MapSaver {
 public:
  explicit MapSaver(const SaverArgs& args) : args_(args) {
    ros::NodeHandle nh;
    subscriber_ = nh.subscribe(args_.topic, 1, &MapSaver::OnMap, this);
    ROS_INFO("lmap_saver: waiting for a map on %s", subscriber_.getTopic().c_str());
  }

  int exit_code() const { return exit_code_; }

 private:
  void OnMap(const OccupancyGridMsg::ConstPtr& message) {
    const Status saved = Save(*message);
    if (!saved.ok()) {
      std::fprintf(stderr, "lmap_saver: %s\n", saved.message().c_str());
      exit_code_ = ExitCodeFor(saved);
      // A robot's periodic save outlives one bad message (a glitched map, a
      // full disk for a while): the last good file stays, the next map is
      // saved, and the exit code says whether the last save failed.
      if (!args_.every) ros::shutdown();
      return;
    }
    exit_code_ = kExitOk;
    ROS_INFO("lmap_saver: wrote %s (%u x %u cells at %.3f m/cell)", args_.path.c_str(),
             message->info.width, message->info.height, message->info.resolution);
    if (!args_.every) ros::shutdown();
  }

  Status Save(const OccupancyGridMsg& message) const {
    const std::string what = "map on " + subscriber_.getTopic();
    StatusOr<Grid> grid = GridFromRosMessage(message, args_.thresholds);
    if (!grid.ok()) return grid.status().WithContext(what);
    const Status saved = SaveLmap(args_.path, *grid, EncodeOptionsFor(message));
    if (!saved.ok()) return saved.WithContext("'" + args_.path + "'");
    return Status::Ok();
  }

  // With --metadata, the saver, the map's frame and its stamp: a robot that
  // keeps the maps of several runs knows which is which.
  EncodeOptions EncodeOptionsFor(const OccupancyGridMsg& message) const {
    EncodeOptions options = args_.encode;
    if (!args_.metadata) return options;
    options.creator = std::string("linemap lmap_saver ") + LINEMAP_VERSION_STRING;
    options.frame_id = message.header.frame_id;
    if (!message.header.stamp.isZero()) {
      options.time = Iso8601FromStamp(message.header.stamp.sec, message.header.stamp.nsec);
    }
    return options;
  }

  SaverArgs args_;
  ros::Subscriber subscriber_;
  int exit_code_ = kExitOk;
};

int Run(int argc, char** argv) {
  if (StartNodeOutput(argc, argv, kUsage)) return kExitOk;
  StatusOr<SaverArgs> args = ParseSaverArgs(NonRosArguments(argc, argv));
  if (!args.ok()) {
    std::fprintf(stderr, "lmap_saver: %s\n%s", args.status().message().c_str(), kUsage);
    return kExitBadInput;
  }
  // An output that cannot be written is refused now, not when the first
  // map arrives (maybe hours later with --every).
  if (const Status target = CheckSaveTarget(args->path); !target.ok()) {
    std::fprintf(stderr, "lmap_saver: %s\n", target.message().c_str());
    return kExitBadInput;
  }
  KeepSaveMemoryForReuse();
  const Status master = InitNodeAndWaitForMaster(
      argc, argv, "lmap_saver", ros::init_options::AnonymousName, args->wait_master_seconds);
  if (!master.ok()) {
    std::fprintf(stderr, "lmap_saver: %s\n", master.message().c_str());
    return kExitFailure;
  }
  MapSaver saver(*args);
  ros::spin();
  return saver.exit_code();
}

}  // namespace
}  // namespace linemap::ros_bridge

int main(int argc, char** argv) { return linemap::ros_bridge::Run(argc, argv); }
