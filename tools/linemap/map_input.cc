#include "tools/linemap/map_input.h"

#include <initializer_list>
#include <string>

#include "linemap/codec.h"
#include "tools/linemap/lmap_cli_util.h"

namespace linemap::cli {

std::vector<OptionSpec> MapLoadOptionSpecs() {
  std::vector<OptionSpec> options = {
      {"--resolution", "M", "metres per cell; overrides the YAML (bare images: 0.05)"},
      {"--origin", "X,Y[,YAW]",
       "map origin in metres and radians; overrides the YAML (bare: 0,0,0)"},
      {"--negate", "", "treat dark pixels as free (the YAML's negate: 1)"},
      {"--occupied-thresh", "P", "occupancy above which a pixel is occupied (default 0.65)"},
      {"--free-thresh", "P", "occupancy below which a pixel is free (default 0.196)"},
      {"--mode", "MODE", "pixel mode: trinary (default), scale or raw"},
      {"--max-cells", "N", "refuse maps with more cells than N (default 1073741824 = 2^30)"},
  };
  for (OptionSpec& o : LayerLimitOptionSpecs()) options.push_back(std::move(o));
  return options;
}

std::vector<OptionSpec> WithMapLoadOptions(std::vector<OptionSpec> options) {
  for (OptionSpec& spec : MapLoadOptionSpecs()) options.push_back(std::move(spec));
  return options;
}

StatusOr<MapReadOptions> MapReadOptionsFrom(const ParsedArgs& args) {
  MapReadOptions read;
  MapLoadOptions& options = read.image;
  if (args.Get("--resolution")) {
    LINEMAP_ASSIGN_OR_RETURN(double resolution, args.GetDouble("--resolution", 0.0));
    if (resolution <= 0.0) return InvalidArgumentError("--resolution must be positive");
    options.resolution = resolution;
  }
  if (args.Get("--origin")) {
    LINEMAP_ASSIGN_OR_RETURN(std::vector<double> origin, args.GetDoubleList("--origin", 2, 3));
    options.origin = Pose2D{origin[0], origin[1], origin.size() > 2 ? origin[2] : 0.0};
  }
  if (args.Has("--negate")) options.negate = true;
  if (args.Get("--occupied-thresh")) {
    LINEMAP_ASSIGN_OR_RETURN(double v, args.GetDouble("--occupied-thresh", 0.0));
    options.occupied_thresh = v;
  }
  if (args.Get("--free-thresh")) {
    LINEMAP_ASSIGN_OR_RETURN(double v, args.GetDouble("--free-thresh", 0.0));
    options.free_thresh = v;
  }
  if (std::optional<std::string> mode = args.Get("--mode")) {
    options.mode = MapModeFromName(*mode);
    if (!options.mode) {
      return InvalidArgumentError("--mode must be trinary, scale or raw, not '" + *mode + "'");
    }
  }
  LINEMAP_ASSIGN_OR_RETURN(options.max_cells,
                           args.GetUint64("--max-cells", options.max_cells, /*min=*/1));
  read.lmap.max_cells = options.max_cells;
  LINEMAP_RETURN_IF_ERROR(LayerLimitsFrom(args, &read.lmap));
  return read;
}

namespace {

// Invalid argument naming the first of `options` that `args` hold, with
// `why` after it.
Status RefuseOptions(const ParsedArgs& args, std::initializer_list<const char*> options,
                     const std::string& why) {
  for (const char* option : options) {
    if (args.Has(option)) return InvalidArgumentError(std::string(option) + why);
  }
  return Status::Ok();
}

}  // namespace

Status CheckMapOptionsApplyTo(const std::string& path, const ParsedArgs& args) {
  if (!IsLmapPath(path)) return Status::Ok();
  return RefuseOptions(
      args,
      {"--resolution", "--origin", "--negate", "--occupied-thresh", "--free-thresh", "--mode"},
      " reads map images and YAMLs; the .lmap file '" + path +
          "' keeps its own resolution, origin and cells");
}

Status CheckImageOptionsApplyToBag(const std::string& path, const ParsedArgs& args) {
  // The thresholds do apply: they read the messages' occupancies (0..100).
  return RefuseOptions(args, {"--resolution", "--origin", "--negate", "--mode"},
                       " reads map images and YAMLs; the maps of the bag '" + path +
                           "' are nav_msgs/OccupancyGrid messages, which carry their own "
                           "resolution, origin and occupancies");
}

StatusOr<Grid> LoadMapArgument(const std::string& path, const ParsedArgs& args) {
  LINEMAP_RETURN_IF_ERROR(CheckMapOptionsApplyTo(path, args));
  LINEMAP_RETURN_IF_ERROR(CheckLayerLimitsApplyTo({path}, args));
  LINEMAP_ASSIGN_OR_RETURN(MapReadOptions options, MapReadOptionsFrom(args));
  return LoadMapWithOptions(path, options);
}

StatusOr<Grid> LoadMapWithOptions(const std::string& path, const MapReadOptions& options) {
  if (IsLmapPath(path)) return LoadLmap(path, options.lmap);  // an .lmap file is decoded
  return LoadRosMap(path, options.image);
}

}  // namespace linemap::cli
