// The CELL chunk of 2.0 files (spec/format.md section 6): the grid cut
// into square tiles, each coded on its own by the tile coder against the
// hints the vector layers draw into it, so that a window decodes only the
// tiles it touches and tiles spread over threads.
#ifndef LINEMAP_CODEC_CELLS_CELL_TILES_H_
#define LINEMAP_CODEC_CELLS_CELL_TILES_H_

#include <cstdint>
#include <functional>
#include <vector>

#include "codec/cells/tile_coder.h"
#include "codec/layers/layer_hints.h"
#include "linemap/codec.h"
#include "linemap/grid.h"
#include "linemap/status.h"

namespace linemap {

// Tile sides a file may use (cells).
inline constexpr int kMinTileSize = 16;
inline constexpr int kMaxTileSize = 1 << 16;

// The tile side the encoder picks for a map of at most 4096 cells a side
// (one tile for most maps of ../shared/maps: each tile starts its models
// afresh, so fewer tiles code smaller).
inline constexpr int kTileCells = 1024;
// The tile side of larger maps, whose users read them by windows: a window
// decodes every tile it meets from the tile's first row and across its
// whole width. On a generated 8192 x 8192 office map a 1 % window decodes
// in 5.7-5.9 ms with tiles of 512 rather than 6.6 (the whole map: about
// 150 ms of CPU), for files 2.2 % larger (2.6 % on the 282-Mcell office
// map: 1,496,415 against 1,458,314 bytes); tiles of 256 would cost 8 %.
inline constexpr int kLargeMapTileCells = 512;

// The tile side the encoder writes: `requested` when positive (the caller
// checked it is kMinTileSize..kMaxTileSize), else kTileCells for a map of
// at most 4096 cells a side and kLargeMapTileCells beyond.
int TileSide(int width, int height, int requested);

struct TileLayout {
  int width = 0;
  int height = 0;
  int tile_size = 0;
  int tiles_x = 0;  // ceil(width / tile_size)
  int tiles_y = 0;

  TileLayout(int width, int height, int tile_size);
  std::uint64_t count() const {
    return std::uint64_t{static_cast<std::uint64_t>(tiles_x)} * tiles_y;
  }
  // Tile i in raster order of tiles (row 0 at the origin), clipped to the grid.
  CellRect Tile(std::uint64_t i) const;
};

// Runs body(i) for i in [0, n) on up to `threads` threads (the calling one
// included); 0 = the machine's cores.
void ForEachIndexParallel(std::uint64_t n, int threads,
                          const std::function<void(std::uint64_t)>& body);

// The tile's cells as a tile-sized array, row-major (the tile coder sees
// the tile as a grid of its own, so it cannot read past it).
std::vector<Cell> TileCells(const Grid& grid, CellRect t);

// One tile's data (cells and hints tw x th, row-major): the smallest of
// TileModel::kLayerContext, the layer context with the wall term alone
// (LayerContextWithout the two hint changes) and kTemplate, in that order
// on a tie; a tile without any hint is coded with kTemplate alone. The
// decoder reads the model from the tile's first byte. Why three: with the
// layers a 2.x file stores, the full layer context is 4 % smaller than
// kTemplate at the tuning median and the wall term alone smaller on other
// maps (5 % together); on the noisy willow scans kTemplate is up to 2 %
// smaller, and without hints (--raster-only, tiles no layer reaches) it
// always is. The choice costs three encodings of the tile (of a tile of
// more than 256 rows: three of its first 128 rows, then whole only the
// models within 2 % or 8 bytes of the smallest on them) and nothing when
// decoding.
// With `compact`, kMixedLayerAllCells and kMixedAllCells join the choice
// (in every tile: model 12's WIDE input pays without hints too), tried
// after the others: the smallest exact coding, for files sent more often
// than they are read.
std::vector<std::uint8_t> EncodeCellTile(const std::vector<Cell>& cells,
                                         const std::vector<std::uint8_t>& hints, int tw, int th,
                                         bool compact = false);

std::vector<std::uint8_t> EncodeCellChunk(const Grid& grid, const LayerIndex& layers, int tile_size,
                                          int threads, bool compact = false);

// Decodes the tiles that meet `window` (inside the grid, non-empty) into
// `out`, a (x1 - x0) x (y1 - y0) array, row-major from y0. On an error the
// cells of `out` are unspecified (partly decoded tiles; every caller drops
// them).
Status DecodeCellChunk(const std::vector<std::uint8_t>& body, const LayerIndex& layers, int width,
                       int height, CellRect window, int threads, Cell* out);

}  // namespace linemap

#endif  // LINEMAP_CODEC_CELLS_CELL_TILES_H_
