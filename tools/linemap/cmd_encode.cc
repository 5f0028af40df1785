// linemap encode MAP -o OUT.lmap [--raster-only] [--tolerance T] [--threads N]
//                 [--method linemap|rmline] [--epsilon E] [--pose X,Y[,YAW]] [--json]
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <future>
#include <memory>
#include <optional>
#include <string_view>
#include <system_error>

#include "format/file_io.h"
#include "format/iso_time.h"
#include "linemap/codec.h"
#include "linemap/lmap_vectors.h"
#include "linemap/map_io.h"
#include "tools/bench/progress.h"
#include "tools/linemap/bag_input.h"
#include "tools/linemap/commands.h"
#include "tools/linemap/json.h"
#include "tools/linemap/lmap_cli_util.h"
#include "tools/linemap/map_input.h"

namespace linemap::cli {

const CommandSpec kEncodeSpec = {
    "encode",
    "MAP -o OUT.lmap [--tolerance T] [--raster-only] [--compact] [--threads N] "
    "[--method linemap|rmline] [--epsilon E] [--pose X,Y[,YAW]]",
    "save a map as an .lmap file (exact, with walls, rooms and furniture)",
    "By default writes a version 2.x file that decodes to the input cell for\n"
    "cell and carries the vector layers: walls as polylines, one border chain\n"
    "per room, furniture outlines. Prints the input cells, the output bytes,\n"
    "the ratio to the smallest PNG (zlib level 9, grey or palette) of the same\n"
    "trinary map, and the time.\n"
    "Without that PNG (--no-png-ratio, or above 2^26 cells) an exact file of a\n"
    "map over 4096 cells a side is coded as the image is read, a row of 2048-\n"
    "cell blocks at a time, without holding the map: the same bytes (0.8-0.9\n"
    "bytes of memory per cell on a 282-Mcell map, whose grid alone is 1).\n"
    "A progress bar is drawn on stderr when it is a terminal (not with --json).\n"
    "The output is written atomically: an existing OUT.lmap is replaced only\n"
    "by a complete new file. OUT.lmap must end in .lmap and may not be the input\n"
    "map or the image its YAML names.\n"
    "An .lmap as MAP is saved again with its metadata; one saved within a\n"
    "tolerance stays marked with its T (its cells are not the robot's map) and\n"
    "cannot take --tolerance again; one that does not name its T (written\n"
    "before files named it, or a lossy 1.0 file) is refused.",
    WithBagOptions(WithMapLoadOptions({
        {"-o", "OUT.lmap", "output file (required; ends in .lmap)"},
        {"--tolerance", "T",
         "largest distance (cells, 0..4) by which the decode may differ: 0 exact (the default); "
         "1..4 draw the map in blocks of T + 1 cells a side (a version 2.3 file), keeping cells "
         "exact where obstacles or free space would move more than T, two free regions would "
         "join or split, or a plan would change by more than 3 %"},
        {"--lossless", "", "the same as --tolerance 0 (the default)"},
        {"--max-tolerance-cells", "N",
         "refuse to save a map of more than N cells within a tolerance (default 67108864 = "
         "2^26; 0: no limit): the checks hold about 25 bytes a cell"},
        {"--raster-only", "",
         "leave the vector layers out (with --compact: the smallest exact file)"},
        {"--straight-walls", "",
         "one wall segment per straight wall: exact files up to 13 % smaller (1.3 % over "
         "../shared/maps), walls up to twice as "
         "far from the wall cells (by default they follow the pixel steps of slanted walls; "
         "files saved with --tolerance always draw straight walls)"},
        {"--follow-steps", "", "walls that follow the pixel steps: the default (kept for scripts)"},
        {"--compact", "",
         "code the cells for size (a version 2.3 file): about 4.5 % smaller (8.5 % with "
         "--raster-only), about 3x the decode time at the median (a median 4.8x per map, up "
         "to 9.2x) and 1.3x the encode time (files saved with --tolerance code their blocks "
         "that way already)"},
        {"--threads", "N",
         "threads to use, 0..4096 (default 0: one per core); the bytes do not depend on it"},
        {"--tile-size", "CELLS",
         "side of the independently decodable tiles, 16..65536 (default 0: 1024 up to 4096 "
         "cells a side, 512 beyond); smaller tiles make windows cheaper and files larger"},
        {"--section-size", "CELLS",
         "side of the sections the vector layers are stored in, at least 16 (default 0: one "
         "section up to 4096 cells a side, 2048 beyond); a window reads only the sections "
         "reaching its tiles"},
        {"--method", "NAME", "wall-line extractor: linemap (default) or rmline"},
        {"--epsilon", "E",
         "linemap extractor tolerance in cells, at least 0.5 (default 1.0; not with rmline)"},
        {"--pose", "X,Y[,YAW]",
         "robot pose in map-frame metres (on the map), stored as metadata (the layers are the "
         "whole map's whatever the pose)"},
        {"--time", "TEXT",
         "creation time stored as metadata: an ISO 8601 date or date-time as the format's `time` "
         "key is, e.g. 2024-05-01T12:00:00Z (default: none, for reproducible output); other "
         "text is refused"},
        {"--metadata", "",
         "also store creator (linemap and its version) and the frame id: 'map', or a bag "
         "message's own; for a bag also the time, the message's stamp in ISO 8601 UTC (its "
         "recording time when the stamp is zero), unless --time gives one"},
        {"--no-png-ratio", "",
         "skip making the PNG-9 the ratio is printed against (skipped anyway above 2^26 "
         "cells, where it costs as much time and memory as the save)"},
        {"--png-ratio", "", "make the PNG-9 of the ratio whatever the map's size"},
        {"--no-sync", "",
         "skip flushing the file to disk (fsync); it is still replaced atomically, but a "
         "power cut right after may lose it"},
        {"--json", "",
         "print one JSON object instead of text (a bag: one per map written, a line each: "
         "topic, index, count, width, height, output, bytes)"},
    })),
    1,
    1,
};

namespace {

StatusOr<EncodeOptions> EncodeOptionsFrom(const ParsedArgs& args) {
  EncodeOptions options;
  options.vector_layers = !args.Has("--raster-only");
  if (args.Has("--straight-walls") && args.Has("--follow-steps")) {
    return InvalidArgumentError("--straight-walls and --follow-steps exclude each other");
  }
  options.straight_walls = args.Has("--straight-walls");
  options.compact = args.Has("--compact");
  LINEMAP_ASSIGN_OR_RETURN(options.tolerance_cells, args.GetInt("--tolerance", 0));
  if (options.tolerance_cells < 0 || options.tolerance_cells > 4) {
    return InvalidArgumentError("--tolerance must be a whole number of cells from 0 to 4");
  }
  if (args.Has("--lossless") && options.tolerance_cells != 0) {
    return InvalidArgumentError("--lossless is --tolerance 0; give one of them");
  }
  LINEMAP_ASSIGN_OR_RETURN(options.max_tolerance_cells,
                           args.GetUint64("--max-tolerance-cells", options.max_tolerance_cells,
                                          /*min=*/0));
  if (args.Has("--png-ratio") && args.Has("--no-png-ratio")) {
    return InvalidArgumentError("--png-ratio and --no-png-ratio exclude each other");
  }
  LINEMAP_ASSIGN_OR_RETURN(options.max_threads, ThreadsFrom(args));
  LINEMAP_ASSIGN_OR_RETURN(options.tile_size_cells, args.GetInt("--tile-size", 0));
  if (options.tile_size_cells != 0 &&
      (options.tile_size_cells < 16 || options.tile_size_cells > 65536)) {
    return InvalidArgumentError("--tile-size must be 0 (automatic) or 16..65536 cells");
  }
  LINEMAP_ASSIGN_OR_RETURN(options.layer_section_cells, args.GetInt("--section-size", 0));
  if (options.layer_section_cells != 0 && options.layer_section_cells < 16) {
    return InvalidArgumentError("--section-size must be 0 (automatic) or at least 16 cells");
  }
  if (std::optional<std::string> method = args.Get("--method")) {
    if (*method == "linemap") {
      options.method = LineMethod::kLinemap;
    } else if (*method == "rmline") {
      options.method = LineMethod::kRmLine;
      // Options of the linemap extractor would be ignored without a word.
      for (const char* option : {"--epsilon", "--straight-walls"}) {
        if (args.Has(option)) {
          return InvalidArgumentError(std::string(option) +
                                      " is an option of the linemap extractor, not of rmline");
        }
      }
    } else {
      return InvalidArgumentError("--method must be linemap or rmline, not '" + *method + "'");
    }
  }
  LINEMAP_ASSIGN_OR_RETURN(options.epsilon_cells, args.GetDouble("--epsilon", 1.0));
  if (!(options.epsilon_cells >= 0.5)) {
    return InvalidArgumentError("--epsilon must be at least 0.5 cells");
  }
  if (args.Get("--pose")) {
    LINEMAP_ASSIGN_OR_RETURN(std::vector<double> pose, args.GetDoubleList("--pose", 2, 3));
    options.robot_pose = Pose2D{pose[0], pose[1], pose.size() > 2 ? pose[2] : 0.0};
  }
  if (std::optional<std::string> time = args.Get("--time")) {
    LINEMAP_RETURN_IF_ERROR(CheckIso8601Time("--time", *time));
    options.time = *time;
  }
  if (args.Has("--metadata")) {
    options.creator = std::string("linemap ") + LINEMAP_VERSION_STRING;
    options.frame_id = "map";
  }
  return options;
}

// A copy of an .lmap saved within a tolerance says so, with the T whose
// guarantees hold against the original map (its cells are not the robot's
// map); saving it within a tolerance again, or copying a file that does not
// name its T, is refused: the guarantees would not add up.
Status KeepToleranceOf(const std::string& map_path, const LmapHeader& header,
                       EncodeOptions* options) {
  if (header.lossless) return Status::Ok();
  const std::optional<int> t = ToleranceCellsOf(header.major, header.lossless, header.metadata);
  const std::string what = t ? "within a tolerance of " + std::to_string(*t) + " cells"
                           : header.major < 2 ? "lossy (version 1.0)"
                                              : "within a tolerance it does not name (written "
                                                "before files named their T)";
  if (options->tolerance_cells > 0) {
    return InvalidArgumentError("'" + map_path + "' was saved " + what +
                                ": saving it within another tolerance would not keep the "
                                "guarantees against the original map; save the original map "
                                "with --tolerance");
  }
  if (!t) {
    return InvalidArgumentError("'" + map_path + "' was saved " + what +
                                ": a copy could not say which guarantees hold against the "
                                "original map; save the original map");
  }
  options->simplified_within_cells = *t;
  return Status::Ok();
}

// The input's creator, time, frame and robot pose, each where the command
// line gave none; of a repeated key the last entry, as readers take it.
void CarryMetadataOf(const LmapHeader& header, EncodeOptions* options) {
  const struct {
    bool creator, time, frame_id, robot_pose;
  } given{!options->creator.empty(), !options->time.empty(), !options->frame_id.empty(),
          options->robot_pose.has_value()};
  for (const auto& [key, value] : header.metadata) {
    if (key == "creator" && !given.creator) options->creator = value;
    if (key == "time" && !given.time) options->time = value;
    if (key == "frame_id" && !given.frame_id) options->frame_id = value;
    double x = 0, y = 0, yaw = 0;
    if (key == "robot_pose" && !given.robot_pose &&
        std::sscanf(value.c_str(), "%lf %lf %lf", &x, &y, &yaw) == 3) {
      options->robot_pose = Pose2D{x, y, yaw};
    }
  }
}

// An .lmap input saved again keeps what its header says of it.
Status InheritFromLmap(const std::string& map_path, const ParsedArgs& parsed,
                       EncodeOptions* options) {
  if (!IsLmapPath(map_path)) return Status::Ok();
  LINEMAP_ASSIGN_OR_RETURN(MapReadOptions read, MapReadOptionsFrom(parsed));
  LINEMAP_ASSIGN_OR_RETURN(LmapHeader header, LoadLmapHeader(map_path, read.lmap));
  LINEMAP_RETURN_IF_ERROR(KeepToleranceOf(map_path, header, options));
  CarryMetadataOf(header, options);
  return Status::Ok();
}

// Refuses an output that would destroy the input: the map file itself or the
// image its YAML names (same file by device and inode, so links count too).
// Then refuses an output the save at the end could not write (a missing or
// read-only folder, a read-only file, a directory) before the encode,
// which takes minutes on a large map within a tolerance.
Status CheckOutput(const std::string& out, const std::string& map_path) {
  if (IsDirectory(out)) return InvalidArgumentError("'" + out + "' is a directory");
  LINEMAP_RETURN_IF_ERROR(CheckOutputExtension(out, {".lmap"}, "an .lmap file"));
  if (IsSameFile(out, map_path)) {
    return InvalidArgumentError("output '" + out + "' is the input map '" + map_path +
                                "'; give another output name");
  }
  // A YAML that cannot be read is reported by the load that follows.
  StatusOr<std::string> image = RosMapImagePath(map_path);
  if (image.ok() && IsSameFile(out, *image)) {
    return InvalidArgumentError("output '" + out + "' is the image '" + *image +
                                "' of the input map '" + map_path + "'; give another output name");
  }
  return CheckOutputWritable(out);
}

// The pose must fall in a cell of the map (the cell whose square holds it).
Status CheckPoseOnMap(const Grid& grid, const Pose2D& pose, const std::string& map_path) {
  if (grid.CellHolding(pose.x, pose.y)) return Status::Ok();
  char text[160];
  std::snprintf(text, sizeof(text), ": --pose %.3f,%.3f is outside the map (%d x %d cells)", pose.x,
                pose.y, grid.width(), grid.height());
  return InvalidArgumentError("'" + map_path + "'" + text);
}

// The PNG the ratio is reported against is made beside the encoding (it
// is only a report; the .lmap does not depend on it). On a robot saving a
// huge map it doubles the work and the memory (the 282-Mcell office map:
// 5 s and 290 MB more), so above kPngRatioMaxCells it takes --png-ratio.
constexpr std::uint64_t kPngRatioMaxCells = std::uint64_t{1} << 26;

bool WantsPngRatio(std::uint64_t cells, const ParsedArgs& parsed) {
  return !parsed.Has("--no-png-ratio") && (cells <= kPngRatioMaxCells || parsed.Has("--png-ratio"));
}

// What `linemap encode` prints of a saved file.
struct EncodeReport {
  int width = 0, height = 0;
  std::uint64_t bytes = 0;
  std::optional<std::size_t> png_bytes;  // when the PNG-9 was made
  bool exact = true;
  double seconds = 0;
};

// "2.2x smaller" / "1.1x larger" / "the same size" for a size ratio. Within
// half a percent of 1 the factor would print as "1.00x" whichever way it
// goes, so a percentage with two significant digits says it instead
// ("0.22 % smaller").
std::string SmallerOrLarger(double ratio) {
  char text[48];
  if (!(ratio > 0) || ratio == 1) return "the same size";
  const double factor = ratio < 1 ? 1.0 / ratio : ratio;
  const char* direction = ratio < 1 ? "smaller" : "larger";
  if (factor < 1.005) {
    const double percent = ratio < 1 ? (1 - ratio) * 100 : (ratio - 1) * 100;
    const int decimals = std::clamp(1 - static_cast<int>(std::floor(std::log10(percent))), 1, 9);
    std::snprintf(text, sizeof(text), "%.*f %% %s", decimals, percent, direction);
    return text;
  }
  // Two decimals near 1, where one would round 0.97 to "1.0x smaller".
  const bool near_one = ratio < 1 ? ratio > 0.8 : ratio < 1.25;
  std::snprintf(text, sizeof(text), near_one ? "%.2fx %s" : "%.1fx %s", factor, direction);
  return text;
}

int PrintReport(const EncodeReport& report, const std::string& out, const ParsedArgs& parsed,
                const EncodeOptions& options) {
  const std::uint64_t cells =
      std::uint64_t{static_cast<std::uint64_t>(report.width)} * report.height;
  const double ratio = report.png_bytes && *report.png_bytes > 0
                           ? static_cast<double>(report.bytes) / *report.png_bytes
                           : 0.0;
  if (parsed.Has("--json")) {
    JsonObject json;
    json.Add("cells", cells).Add("bytes", report.bytes);
    if (report.png_bytes) {
      json.Add("png_bytes", std::uint64_t{*report.png_bytes}).Add("ratio_to_png", ratio);
    }
    // The T the file names: the save's, or the input's when an .lmap saved
    // within a tolerance was saved again exactly.
    const int named = !report.exact ? options.tolerance_cells : options.simplified_within_cells;
    json.Add("exact", report.exact)
        .AddRaw("tolerance_cells", named > 0 ? std::to_string(named) : "null")
        .Add("vector_layers", options.vector_layers)
        .Add("seconds", report.seconds);
    std::printf("%s\n", json.str().c_str());
    return kExitOk;
  }
  std::printf("input:   %d x %d = %llu cells\n", report.width, report.height,
              static_cast<unsigned long long>(cells));
  char within[96];
  std::snprintf(within, sizeof(within), "within a tolerance of %d cell%s, %s",
                options.tolerance_cells, options.tolerance_cells == 1 ? "" : "s",
                options.vector_layers ? "with walls, rooms and furniture" : "cells only");
  char copy[128];
  std::snprintf(copy, sizeof(copy),
                "exact copy of a map saved within a tolerance of %d cell%s, which it names, %s",
                options.simplified_within_cells, options.simplified_within_cells == 1 ? "" : "s",
                options.vector_layers ? "with walls, rooms and furniture" : "cells only");
  std::printf("output:  %s, %llu bytes (%s)\n", out.c_str(),
              static_cast<unsigned long long>(report.bytes),
              !report.exact                         ? within
              : options.simplified_within_cells > 0 ? copy
              : options.vector_layers               ? "exact, with walls, rooms and furniture"
                                                    : "exact, cells only");
  if (report.png_bytes) {
    std::printf("png-9:   %zu bytes; lmap / png = %.4f (%s)\n", *report.png_bytes, ratio,
                SmallerOrLarger(ratio).c_str());
  } else if (!parsed.Has("--no-png-ratio")) {
    std::printf("png-9:   not made above 2^26 cells (--png-ratio makes it)\n");
  }
  std::printf("time:    %.3f s\n", report.seconds);
  return kExitOk;
}

// Saves an exact file of a map image without loading its grid
// (SaveRosMapAsLmap) when nothing needs the grid: no PNG to compare with,
// no pose to check on it. Returns the exit code, or nothing when the map
// is to be loaded.
std::optional<int> SaveAsRead(const std::string& map_path, const std::string& out,
                              const ParsedArgs& parsed, const EncodeOptions& options, double start,
                              bench::ProgressBar* bar) {
  if (IsLmapPath(map_path) || options.tolerance_cells != 0 || options.robot_pose) {
    return std::nullopt;
  }
  StatusOr<MapReadOptions> read = MapReadOptionsFrom(parsed);
  if (!read.ok()) return ReportError("encode", read.status());
  const MapLoadOptions& load = read->image;
  StatusOr<std::unique_ptr<MapRowReader>> reader = MapRowReader::Open(map_path, load);
  if (!reader.ok()) return ReportError("encode", reader.status());
  const std::uint64_t cells =
      std::uint64_t{static_cast<std::uint64_t>((*reader)->width())} * (*reader)->height();
  reader->reset();
  if (WantsPngRatio(cells, parsed)) return std::nullopt;
  StatusOr<LmapSaveSummary> saved =
      SaveRosMapAsLmap(map_path, out, options, load,
                       parsed.Has("--no-sync") ? Durability::kUnsynced : Durability::kSynced);
  if (!saved.ok()) {
    bar->Finish();
    return ReportError("encode", saved.status());
  }
  EncodeReport report;
  report.width = saved->width;
  report.height = saved->height;
  report.bytes = saved->bytes;
  report.seconds = NowSeconds() - start;
  return PrintReport(report, out, parsed, options);
}

}  // namespace

int RunEncode(const std::vector<std::string>& args) {
  // Scripts written for the former lossy 1.0 file learn what replaced it.
  if (std::find(args.begin(), args.end(), "--lossy") != args.end()) {
    return ReportError("encode",
                       InvalidArgumentError("--lossy (the former lossy 1.0 file) was removed; use "
                                            "--tolerance T (1..4 cells) for a smaller file"));
  }
  int exit_code = kExitOk;
  std::optional<ParsedArgs> parsed = ParseArgs(kEncodeSpec, args, &exit_code);
  if (!parsed) return exit_code;
  const std::optional<std::string> out = parsed->Get("-o");
  if (!out) return ReportError("encode", InvalidArgumentError("missing -o OUT.lmap"));
  const std::string& map_path = parsed->positional[0];
  // Checked here: a bag and a map image saved as it is read (SaveAsRead)
  // never reach LoadMapArgument, which checks it too.
  const Status limits_apply = CheckLayerLimitsApplyTo({map_path}, *parsed);
  if (!limits_apply.ok()) return ReportError("encode", limits_apply);
  // A ROS 1 bag of nav_msgs/OccupancyGrid messages: tools/linemap/bag_input.cc.
  const Status bag_options_apply = CheckBagOptionsApplyTo(map_path, *parsed);
  if (!bag_options_apply.ok()) return ReportError("encode", bag_options_apply);
  if (IsBagInput(map_path, *parsed)) {
    const Status image_options = CheckImageOptionsApplyToBag(map_path, *parsed);
    if (!image_options.ok()) return ReportError("encode", image_options);
    StatusOr<EncodeOptions> bag_options = EncodeOptionsFrom(*parsed);
    if (!bag_options.ok()) return ReportError("encode", bag_options.status());
    return EncodeBag(map_path, *parsed, *bag_options);
  }
  const Status output_ok = CheckOutput(*out, map_path);
  if (!output_ok.ok()) return ReportError("encode", output_ok);
  StatusOr<EncodeOptions> options = EncodeOptionsFrom(*parsed);
  if (!options.ok()) return ReportError("encode", options.status());
  const Status inherited = InheritFromLmap(map_path, *parsed, &*options);
  if (!inherited.ok()) return ReportError("encode", inherited);
  // A bar on stderr when it is a terminal (not with --json): a huge map
  // takes seconds.
  bench::ProgressBar bar(100, stderr, !parsed->Has("--json") && isatty(fileno(stderr)) != 0);
  options->progress = [&bar](double done) {
    bar.Update(static_cast<std::size_t>(done * 100), "encoding");
    if (done >= 1.0) bar.Finish();  // before the report
  };
  const double start = NowSeconds();
  if (std::optional<int> code = SaveAsRead(map_path, *out, *parsed, *options, start, &bar)) {
    return *code;
  }
  StatusOr<Grid> grid = LoadMapArgument(map_path, *parsed);
  if (!grid.ok()) return ReportError("encode", grid.status());
  if (options->robot_pose) {
    const Status pose_ok = CheckPoseOnMap(*grid, *options->robot_pose, map_path);
    if (!pose_ok.ok()) return ReportError("encode", pose_ok);
  }
  const bool with_png = WantsPngRatio(grid->size(), *parsed);
  const auto make_png = [&grid, with_png]() -> StatusOr<std::size_t> {
    if (!with_png) return std::size_t{0};
    return SmallestTrinaryPngBytes(*grid);
  };
  std::future<StatusOr<std::size_t>> png_task;
  try {
    png_task = std::async(with_png ? std::launch::async : std::launch::deferred, make_png);
  } catch (const std::system_error&) {
    png_task = std::async(std::launch::deferred, make_png);
  }
  StatusOr<std::vector<std::uint8_t>> bytes = EncodeLmap(*grid, *options);
  bar.Finish();
  if (!bytes.ok()) return ReportError("encode", bytes.status().WithContext("'" + map_path + "'"));
  Status written = WriteFileAtomic(
      *out, std::string_view(reinterpret_cast<const char*>(bytes->data()), bytes->size()),
      parsed->Has("--no-sync") ? Durability::kUnsynced : Durability::kSynced);
  if (!written.ok()) return ReportError("encode", written);
  const double seconds = NowSeconds() - start;
  StatusOr<std::size_t> png = png_task.get();
  if (!png.ok()) return ReportError("encode", png.status());
  // Within a tolerance the file is exact where nothing could be simplified
  // (or the exact file was the smaller): which one, its decode says.
  bool exact = true;
  if (options->tolerance_cells > 0) {
    DecodeLimits limits;
    limits.max_cells = std::max<std::uint64_t>(limits.max_cells, grid->size());
    StatusOr<Grid> decoded = DecodeLmap(*bytes, limits);
    exact = decoded.ok() && decoded->cells() == grid->cells();
  }
  EncodeReport report;
  report.width = grid->width();
  report.height = grid->height();
  report.bytes = bytes->size();
  if (with_png) report.png_bytes = *png;
  report.exact = exact;
  report.seconds = seconds;
  return PrintReport(report, *out, *parsed, *options);
}

}  // namespace linemap::cli
