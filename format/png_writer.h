// PNG writing (libpng, zlib level 9) for size comparisons: the reference the
// issue measures .lmap files against is the smallest PNG of the trinary map.
#ifndef LINEMAP_FORMAT_PNG_WRITER_H_
#define LINEMAP_FORMAT_PNG_WRITER_H_

#include <cstdint>
#include <vector>

#include "linemap/status.h"

namespace linemap {

// 8-bit grey PNG of `grey` (width*height, top image row first).
StatusOr<std::vector<std::uint8_t>> EncodeGreyPng(int width, int height,
                                                  const std::vector<std::uint8_t>& grey);
// 2-bit palette PNG of `index` (values 0..3, top image row first) with the
// palette's grey levels `levels`.
StatusOr<std::vector<std::uint8_t>> EncodePalettePng(int width, int height,
                                                     const std::vector<std::uint8_t>& index,
                                                     const std::vector<std::uint8_t>& levels);

}  // namespace linemap

#endif  // LINEMAP_FORMAT_PNG_WRITER_H_
