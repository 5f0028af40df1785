#include "tools/linemap/lmap_cli_util.h"

#include <algorithm>
#include <chrono>

#include "format/png_writer.h"
#include "linemap/map_io.h"

namespace linemap::cli {

std::vector<OptionSpec> LayerLimitOptionSpecs() {
  return {
      {"--max-segments", "N",
       "refuse .lmap files with more than N wall segments in a chunk, or in the layer sections "
       "read together (default 16777216 = 2^24; lower it for untrusted files of small maps)"},
      {"--max-objects", "N",
       "refuse .lmap files with more than N rooms, or N furniture objects (default 1048576 = "
       "2^20)"},
  };
}

Status LayerLimitsFrom(const ParsedArgs& args, DecodeLimits* limits) {
  LINEMAP_ASSIGN_OR_RETURN(limits->max_segments,
                           args.GetUint64("--max-segments", limits->max_segments, /*min=*/1));
  LINEMAP_ASSIGN_OR_RETURN(limits->max_objects,
                           args.GetUint64("--max-objects", limits->max_objects, /*min=*/1));
  return Status::Ok();
}

Status CheckLayerLimitsApplyTo(const std::vector<std::string>& paths, const ParsedArgs& args) {
  for (const std::string& path : paths) {
    if (IsLmapPath(path)) return Status::Ok();
  }
  for (const OptionSpec& option : LayerLimitOptionSpecs()) {
    if (!args.Has(option.name)) continue;
    const std::string inputs =
        paths.size() == 1 ? "'" + paths[0] + "' is not an .lmap file"
                          : "neither '" + paths[0] + "' nor '" + paths[1] + "' is an .lmap file";
    return InvalidArgumentError(option.name + " limits the vector layers of .lmap files; " +
                                inputs);
  }
  return Status::Ok();
}

std::vector<OptionSpec> DecodeLimitOptionSpecs() {
  std::vector<OptionSpec> options = {
      {"--max-cells", "N", "refuse maps with more cells than N (default 1073741824 = 2^30)"},
      {"--max-file-bytes", "N", "refuse .lmap files larger than N bytes (default 2^31)"},
  };
  for (OptionSpec& o : LayerLimitOptionSpecs()) options.push_back(std::move(o));
  options.push_back({"--threads", "N",
                     "threads decoding the tiles of a 2.0 file, 0..4096 (default 0: one per "
                     "core); the result does not depend on it"});
  return options;
}

StatusOr<DecodeLimits> DecodeLimitsFrom(const ParsedArgs& args) {
  DecodeLimits limits;
  LINEMAP_ASSIGN_OR_RETURN(limits.max_cells,
                           args.GetUint64("--max-cells", limits.max_cells, /*min=*/1));
  LINEMAP_ASSIGN_OR_RETURN(limits.max_file_bytes,
                           args.GetUint64("--max-file-bytes", limits.max_file_bytes, /*min=*/1));
  LINEMAP_RETURN_IF_ERROR(LayerLimitsFrom(args, &limits));
  LINEMAP_ASSIGN_OR_RETURN(limits.max_threads, ThreadsFrom(args));
  return limits;
}

StatusOr<int> ThreadsFrom(const ParsedArgs& args) {
  constexpr int kMaxThreads = 4096;
  StatusOr<int> threads = args.GetInt("--threads", 0);
  if (!threads.ok() || *threads < 0 || *threads > kMaxThreads) {
    return InvalidArgumentError("--threads takes a whole number 0..4096 (0: one per core), not '" +
                                args.Get("--threads").value_or("") + "'");
  }
  return threads;
}

StatusOr<std::vector<std::uint8_t>> TrinaryPng(const Grid& grid) {
  // The 2-bit palette PNG: for three-level maps it is within a few bytes of
  // netpbm's `pnmtopng -compression 9` and four times cheaper to make than
  // the 8-bit grey one.
  const int w = grid.width();
  const int h = grid.height();
  std::vector<std::uint8_t> index(grid.size());
  for (int y = 0; y < h; ++y) {
    const int row = h - 1 - y;  // image row 0 is the top
    for (int x = 0; x < w; ++x) {
      index[static_cast<std::size_t>(y) * w + x] = static_cast<std::uint8_t>(grid.at(x, row));
    }
  }
  return EncodePalettePng(w, h, index, {kPgmFree, kPgmOccupied, kPgmUnknown});
}

StatusOr<std::size_t> SmallestTrinaryPngBytes(const Grid& grid) {
  LINEMAP_ASSIGN_OR_RETURN(std::vector<std::uint8_t> png, TrinaryPng(grid));
  return png.size();
}

double NowSeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace linemap::cli
