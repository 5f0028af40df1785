// SEGS bodies coded with Draco (payload coder 2, spec/format.md 4.5.1): the
// segments as a Draco point cloud, one point per segment with a single
// GENERIC int32 attribute of four components (a.col, a.row, b.col, b.row),
// sequential encoding so the order is kept. Integer attributes are coded
// losslessly by Draco.
#ifndef LINEMAP_CODEC_LMAP_DRACO_SEGMENTS_H_
#define LINEMAP_CODEC_LMAP_DRACO_SEGMENTS_H_

#include <cstdint>
#include <vector>

#include "linemap/codec.h"

namespace linemap {

// Empty when Draco fails or there are no segments. No file is written with
// it any more (1.0 files are not); tests build Draco-coded SEGS with it.
std::vector<std::uint8_t> EncodeSegmentsDraco(const std::vector<LatticeSegment>& segments);

// Decodes and checks the segments as the varint form is checked (inside the
// grid, canonical, at most the segment limit, no trailing bytes), after the
// header rules of spec 4.5.1 (sequential point cloud, no metadata, at most
// 1024 points per byte).
StatusOr<std::vector<LatticeSegment>> DecodeSegmentsDraco(const std::vector<std::uint8_t>& body,
                                                          int width, int height,
                                                          const DecodeLimits& limits);

}  // namespace linemap

#endif  // LINEMAP_CODEC_LMAP_DRACO_SEGMENTS_H_
