// General-purpose compressors over the raw trinary cells (one byte per cell,
// values 0 free / 1 occupied / 2 unknown, grid-row order), as a user would
// store a map with `zstd -19` or `xz -9e`.
#ifndef LINEMAP_TOOLS_BENCH_GENERAL_CODECS_H_
#define LINEMAP_TOOLS_BENCH_GENERAL_CODECS_H_

#include <cstdint>
#include <span>
#include <string>

#include "linemap/grid.h"
#include "linemap/status.h"

namespace linemap::bench {

std::span<const std::uint8_t> RawCells(const Grid& grid);

// A zstd frame at `level` (19 = zstd -19), content size recorded.
StatusOr<std::string> ZstdCompress(std::span<const std::uint8_t> data, int level = 19);
// An .xz stream with preset `preset` (0..9) and CRC-64, as xz writes it;
// `extreme` adds LZMA_PRESET_EXTREME (xz -9e: slower, at most as large).
StatusOr<std::string> XzCompress(std::span<const std::uint8_t> data, int preset = 9,
                                 bool extreme = true);

}  // namespace linemap::bench

#endif  // LINEMAP_TOOLS_BENCH_GENERAL_CODECS_H_
