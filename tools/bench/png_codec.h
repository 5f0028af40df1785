// PNG comparators: a trinary grid written as map_saver's pixel values (254
// free, 205 unknown, 0 occupied; image row 0 = top) through libpng at zlib
// level 9, as netpbm's `pnmtopng -compression 9` would, and read back.
#ifndef LINEMAP_TOOLS_BENCH_PNG_CODEC_H_
#define LINEMAP_TOOLS_BENCH_PNG_CODEC_H_

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "linemap/grid.h"
#include "linemap/status.h"

namespace linemap::bench {

enum class PngLayout {
  kGrey8,     // 8-bit greyscale, libpng's default (adaptive) row filters
  kPalette8,  // 8-bit palette of the three values, filter none (libpng's default)
  kPalette2,  // 2-bit packed palette, four cells per byte, filter none
};

const char* PngLayoutName(PngLayout layout);

// The PNG file bytes. `zlib_level` 0..9 (9 = pnmtopng -compression 9).
StatusOr<std::string> EncodeTrinaryPng(const Grid& grid, PngLayout layout, int zlib_level = 9);

// Decodes a PNG written by EncodeTrinaryPng (or any 8-bit-or-less grey or
// palette PNG with map_saver's values) back to a trinary grid: 254 free,
// 0 occupied, anything else unknown. Metadata stays at the defaults.
StatusOr<Grid> DecodeTrinaryPng(std::span<const std::uint8_t> png);

}  // namespace linemap::bench

#endif  // LINEMAP_TOOLS_BENCH_PNG_CODEC_H_
