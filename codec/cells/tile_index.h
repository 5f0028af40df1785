// The tile index that CELL and BLKS share (spec/format.md 6.1): one varint
// byte length per tile, then the tiles' data; and which tiles a window
// meets.
#ifndef LINEMAP_CODEC_CELLS_TILE_INDEX_H_
#define LINEMAP_CODEC_CELLS_TILE_INDEX_H_

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "codec/cells/cell_tiles.h"
#include "format/byte_io.h"
#include "linemap/status.h"

namespace linemap {

struct TileIndex {
  std::size_t base = 0;                // where tile 0's data starts in the body
  std::vector<std::uint64_t> offsets;  // count + 1 offsets from `base`
};

// Codes every tile of `layout` with encode(tile) on up to `threads`
// threads, then appends the tiles' byte lengths and their data, in order
// (the bytes do not depend on the number of threads).
void WriteTiles(const TileLayout& layout, int threads,
                const std::function<std::vector<std::uint8_t>(CellRect)>& encode, ByteWriter* out);

// Reads the lengths at `cursor` (just after the tile side) of a body of
// `body.size()` bytes. Every length takes at least one byte, so a tile
// count the body cannot hold is corrupt before anything is allocated; the
// lengths must add up to exactly the bytes after the index.
StatusOr<TileIndex> ReadTileIndex(const std::vector<std::uint8_t>& body, const TileLayout& layout,
                                  ByteCursor* cursor);

// The tiles (raster order) that meet `window`.
std::vector<std::uint64_t> TilesMeeting(const TileLayout& layout, CellRect window);

// Writes the cells of tile `tile` from its `size` bytes at `data`: row r of
// the tile at cells + r * stride, for its first `rows` rows (the ones the
// window needs; the scan codes the rows of a tile in order, so a decoder
// stops after them). `cells` holds min(rows + 1, tile height) rows.
using TileDecoder = std::function<Status(CellRect tile, const std::uint8_t* data, std::size_t size,
                                         int rows, Cell* cells, std::ptrdiff_t stride)>;

// Decodes the tiles that meet `window` (inside the grid, non-empty) into
// `out`, a (x1 - x0) x (y1 - y0) array, row-major from y0, on up to
// `threads` threads: a tile inside the window straight into `out`, others
// through a buffer of their own. Errors name the tile.
Status DecodeTilesInWindow(const std::vector<std::uint8_t>& body, const TileLayout& layout,
                           const TileIndex& index, CellRect window, int threads, Cell* out,
                           const TileDecoder& decode);

}  // namespace linemap

#endif  // LINEMAP_CODEC_CELLS_TILE_INDEX_H_
