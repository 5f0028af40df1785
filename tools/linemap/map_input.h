// Loading the MAP argument of a command: a ROS map YAML, a bare PGM/PNG
// image, with the shared command-line overrides of the YAML's values.
#ifndef LINEMAP_TOOLS_LINEMAP_MAP_INPUT_H_
#define LINEMAP_TOOLS_LINEMAP_MAP_INPUT_H_

#include <string>
#include <vector>

#include "linemap/codec.h"
#include "linemap/grid.h"
#include "linemap/map_io.h"
#include "linemap/status.h"
#include "tools/linemap/cli.h"

namespace linemap::cli {

// --resolution, --origin, --negate, --occupied-thresh, --free-thresh, --mode,
// --max-cells, --max-segments, --max-objects: appended to the options of
// every command that reads a map.
std::vector<OptionSpec> MapLoadOptionSpecs();

// How a command reads its MAP: an image with `image`, an .lmap file within
// `lmap` (--max-cells sets both).
struct MapReadOptions {
  MapLoadOptions image;
  DecodeLimits lmap;
};

StatusOr<MapReadOptions> MapReadOptionsFrom(const ParsedArgs& args);

// Invalid argument when `path` is an .lmap file and `args` hold an option
// that only reading an image gives a meaning (all but the limits): the
// file's own values stand, and silently ignoring the option would hide it.
Status CheckMapOptionsApplyTo(const std::string& path, const ParsedArgs& args);

// Invalid argument when `args` hold --resolution, --origin, --negate or
// --mode for the ROS 1 bag `path`: an OccupancyGrid message has no pixels
// to negate or scale, and its own resolution and origin.
Status CheckImageOptionsApplyToBag(const std::string& path, const ParsedArgs& args);

// Loads `path` as a map (.lmap, YAML or image) with the overrides in `args`
// (CheckMapOptionsApplyTo and CheckLayerLimitsApplyTo first).
StatusOr<Grid> LoadMapArgument(const std::string& path, const ParsedArgs& args);

// Loads `path` (.lmap, YAML or image) with `options.image`, or an .lmap
// file within `options.lmap`.
StatusOr<Grid> LoadMapWithOptions(const std::string& path, const MapReadOptions& options);

// Options of `spec` followed by MapLoadOptionSpecs().
std::vector<OptionSpec> WithMapLoadOptions(std::vector<OptionSpec> options);

}  // namespace linemap::cli

#endif  // LINEMAP_TOOLS_LINEMAP_MAP_INPUT_H_
