// General-purpose compressors over the raw trinary cells (one byte per cell,
// values 0 free / 1 occupied / 2 unknown, grid-row order), as a user would
// store a map with `zstd -19` or `xz -9`.
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
// An .xz stream with preset `preset` (9 = xz -9) and CRC-64, as xz writes it.
StatusOr<std::string> XzCompress(std::span<const std::uint8_t> data, int preset = 9);

}  // namespace linemap::bench

#endif  // LINEMAP_TOOLS_BENCH_GENERAL_CODECS_H_
