// The 1.0 encoder (lossy by default), kept behind EncodeOptions::format_v1.
#ifndef LINEMAP_CODEC_CODEC_ENCODER_V1_H_
#define LINEMAP_CODEC_CODEC_ENCODER_V1_H_

#include <cstdint>
#include <vector>

#include "linemap/codec.h"

namespace linemap {

StatusOr<std::vector<std::uint8_t>> EncodeLmapV1(const Grid& grid, const EncodeOptions& options);

}  // namespace linemap

#endif  // LINEMAP_CODEC_CODEC_ENCODER_V1_H_
