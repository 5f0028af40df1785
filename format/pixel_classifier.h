// nav2 map_server's pixel classification (see include/linemap/map_io.h for
// the rule in words). Kept apart so tests can check it pixel by pixel.
#ifndef LINEMAP_FORMAT_PIXEL_CLASSIFIER_H_
#define LINEMAP_FORMAT_PIXEL_CLASSIFIER_H_

#include <cstdint>

#include "linemap/grid.h"

namespace linemap {

// `samples` holds `channels` quanta (0..65535): grey, grey+alpha, RGB or RGBA.
Cell ClassifyPixel(const std::uint16_t* samples, int channels, const MapMetadata& meta);

// The same for an opaque 8-bit grey value.
Cell ClassifyGrey8(std::uint8_t grey, const MapMetadata& meta);

}  // namespace linemap

#endif  // LINEMAP_FORMAT_PIXEL_CLASSIFIER_H_
