// Loading the MAP argument of a command: a ROS map YAML, a bare PGM/PNG
// image, with the shared command-line overrides of the YAML's values.
#ifndef LINEMAP_TOOLS_LINEMAP_MAP_INPUT_H_
#define LINEMAP_TOOLS_LINEMAP_MAP_INPUT_H_

#include <string>
#include <vector>

#include "linemap/grid.h"
#include "linemap/map_io.h"
#include "linemap/status.h"
#include "tools/linemap/cli.h"

namespace linemap::cli {

// --resolution, --origin, --negate, --occupied-thresh, --free-thresh, --mode,
// --max-cells: appended to the options of every command that reads a map.
std::vector<OptionSpec> MapLoadOptionSpecs();

StatusOr<MapLoadOptions> MapLoadOptionsFrom(const ParsedArgs& args);

// Invalid argument when `path` is an .lmap file and `args` hold an option
// that only reading an image gives a meaning (all but --max-cells): the
// file's own values stand, and silently ignoring the option would hide it.
Status CheckMapOptionsApplyTo(const std::string& path, const ParsedArgs& args);

// Loads `path` as a map (.lmap, YAML or image) with the overrides in `args`
// (CheckMapOptionsApplyTo first).
StatusOr<Grid> LoadMapArgument(const std::string& path, const ParsedArgs& args);

// Loads `path` (.lmap, YAML or image) with `options`; for an .lmap file only
// options.max_cells applies.
StatusOr<Grid> LoadMapWithOptions(const std::string& path, const MapLoadOptions& options);

// Options of `spec` followed by MapLoadOptionSpecs().
std::vector<OptionSpec> WithMapLoadOptions(std::vector<OptionSpec> options);

}  // namespace linemap::cli

#endif  // LINEMAP_TOOLS_LINEMAP_MAP_INPUT_H_
