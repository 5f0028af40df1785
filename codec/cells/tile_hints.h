// Layer hints for the tile coder built from the library's own extractors:
// the wall segments of StraightWalls(), the room-border chains and the
// furniture outlines of SegmentMap(). The .lmap 2.0 encoder draws its hints
// from the layers it stores; this builder is what the tile coder's tests
// and bench (tools/bench_tiles) use to measure the coder with realistic
// hints before those layers exist.
#ifndef LINEMAP_CODEC_CELLS_TILE_HINTS_H_
#define LINEMAP_CODEC_CELLS_TILE_HINTS_H_

#include <cstdint>
#include <vector>

#include "linemap/grid.h"
#include "linemap/status.h"

namespace linemap {

// width*height hint bytes (LayerHintBits, tile_coder.h): walls are the
// segments with their ends rounded to the nearest cell, rasterised as
// spec/format.md "Rasterisation" draws them; rooms are FillChainPolygon of
// each chain (the chain's cells kHintRoomBorder, the others
// kHintRoomInside); furniture is each blob's outline filled.
StatusOr<std::vector<std::uint8_t>> BuildLayerHints(const Grid& grid);

}  // namespace linemap

#endif  // LINEMAP_CODEC_CELLS_TILE_HINTS_H_
