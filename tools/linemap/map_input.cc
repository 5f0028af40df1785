#include "tools/linemap/map_input.h"

#include "linemap/codec.h"
#include "tools/linemap/lmap_cli_util.h"

namespace linemap::cli {

std::vector<OptionSpec> MapLoadOptionSpecs() {
  return {
      {"--resolution", "M", "metres per cell; overrides the YAML (bare images: 0.05)"},
      {"--origin", "X,Y[,YAW]",
       "map origin in metres and radians; overrides the YAML (bare: 0,0,0)"},
      {"--negate", "", "treat dark pixels as free (the YAML's negate: 1)"},
      {"--occupied-thresh", "P", "occupancy above which a pixel is occupied (default 0.65)"},
      {"--free-thresh", "P", "occupancy below which a pixel is free (default 0.196)"},
      {"--mode", "MODE", "pixel mode: trinary (default), scale or raw"},
      {"--max-cells", "N", "refuse maps with more cells than N (default 1073741824 = 2^30)"},
  };
}

std::vector<OptionSpec> WithMapLoadOptions(std::vector<OptionSpec> options) {
  for (OptionSpec& spec : MapLoadOptionSpecs()) options.push_back(std::move(spec));
  return options;
}

StatusOr<MapLoadOptions> MapLoadOptionsFrom(const ParsedArgs& args) {
  MapLoadOptions options;
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
    if (*mode == "trinary") {
      options.mode = MapMode::kTrinary;
    } else if (*mode == "scale") {
      options.mode = MapMode::kScale;
    } else if (*mode == "raw") {
      options.mode = MapMode::kRaw;
    } else {
      return InvalidArgumentError("--mode must be trinary, scale or raw, not '" + *mode + "'");
    }
  }
  LINEMAP_ASSIGN_OR_RETURN(options.max_cells,
                           args.GetUint64("--max-cells", options.max_cells, /*min=*/1));
  return options;
}

Status CheckMapOptionsApplyTo(const std::string& path, const ParsedArgs& args) {
  if (!IsLmapPath(path)) return Status::Ok();
  for (const char* option :
       {"--resolution", "--origin", "--negate", "--occupied-thresh", "--free-thresh", "--mode"}) {
    if (args.Has(option)) {
      return InvalidArgumentError(std::string(option) +
                                  " reads map images and YAMLs; the .lmap file '" + path +
                                  "' keeps its own resolution, origin and cells");
    }
  }
  return Status::Ok();
}

StatusOr<Grid> LoadMapArgument(const std::string& path, const ParsedArgs& args) {
  LINEMAP_RETURN_IF_ERROR(CheckMapOptionsApplyTo(path, args));
  LINEMAP_ASSIGN_OR_RETURN(MapLoadOptions options, MapLoadOptionsFrom(args));
  return LoadMapWithOptions(path, options);
}

StatusOr<Grid> LoadMapWithOptions(const std::string& path, const MapLoadOptions& options) {
  if (IsLmapPath(path)) {  // an .lmap file is decoded
    DecodeLimits limits;
    limits.max_cells = options.max_cells;
    return LoadLmap(path, limits);
  }
  return LoadRosMap(path, options);
}

}  // namespace linemap::cli
