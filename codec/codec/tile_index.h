// The tile index that CELL and BLKS share (spec/format.md 6.1): one varint
// byte length per tile, then the tiles' data; and which tiles a window
// meets.
#ifndef LINEMAP_CODEC_CODEC_TILE_INDEX_H_
#define LINEMAP_CODEC_CODEC_TILE_INDEX_H_

#include <cstddef>
#include <cstdint>
#include <vector>

#include "codec/codec/cell_tiles.h"
#include "format/byte_io.h"
#include "linemap/status.h"

namespace linemap {

struct TileIndex {
  std::size_t base = 0;                // where tile 0's data starts in the body
  std::vector<std::uint64_t> offsets;  // count + 1 offsets from `base`
};

// Reads the lengths at `cursor` (just after the tile side) of a body of
// `body.size()` bytes. Every length takes at least one byte, so a tile
// count the body cannot hold is corrupt before anything is allocated; the
// lengths must add up to exactly the bytes after the index.
StatusOr<TileIndex> ReadTileIndex(const std::vector<std::uint8_t>& body, const TileLayout& layout,
                                  ByteCursor* cursor);

// The tiles (raster order) that meet `window`.
std::vector<std::uint64_t> TilesMeeting(const TileLayout& layout, CellRect window);

}  // namespace linemap

#endif  // LINEMAP_CODEC_CODEC_TILE_INDEX_H_
