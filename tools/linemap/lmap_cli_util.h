// Helpers shared by the .lmap commands (encode, decode, export, eval, info).
#ifndef LINEMAP_TOOLS_LINEMAP_LMAP_CLI_UTIL_H_
#define LINEMAP_TOOLS_LINEMAP_LMAP_CLI_UTIL_H_

#include <cstdint>
#include <string>
#include <vector>

#include "linemap/codec.h"
#include "linemap/grid.h"
#include "linemap/status.h"
#include "tools/linemap/cli.h"

namespace linemap::cli {

// --max-segments and --max-objects: the decoder's limits on an .lmap file's
// vector layers (DecodeLimits), for every command that reads one. A file
// whose counts pass them is still checked against the bytes it holds.
std::vector<OptionSpec> LayerLimitOptionSpecs();
Status LayerLimitsFrom(const ParsedArgs& args, DecodeLimits* limits);

// Invalid argument when `args` hold a layer limit and neither of `paths`
// (one or two), the inputs it could apply to, is an .lmap file: a map
// image, YAML or bag has no layers, and silently ignoring the option would
// hide that it limits nothing.
Status CheckLayerLimitsApplyTo(const std::vector<std::string>& paths, const ParsedArgs& args);

// --max-cells, --max-file-bytes, the layer limits and --threads of the
// decoder, from the parsed arguments.
std::vector<OptionSpec> DecodeLimitOptionSpecs();
StatusOr<DecodeLimits> DecodeLimitsFrom(const ParsedArgs& args);

// --threads N: 0 (one per core) to 4096, the same for every command.
StatusOr<int> ThreadsFrom(const ParsedArgs& args);

// The 2-bit palette PNG (zlib level 9) of the grid's trinary image, in
// map_saver's grey levels (free 254, occupied 0, unknown 205), north up.
StatusOr<std::vector<std::uint8_t>> TrinaryPng(const Grid& grid);

// Bytes of TrinaryPng(grid).
StatusOr<std::size_t> SmallestTrinaryPngBytes(const Grid& grid);

// Seconds on a monotonic clock.
double NowSeconds();

}  // namespace linemap::cli

#endif  // LINEMAP_TOOLS_LINEMAP_LMAP_CLI_UTIL_H_
