// The BLKS chunk of 2.x files (spec/format.md section 6.4): the cells of a
// file saved within a tolerance, as blocks of F cells a side, each one
// value, coded first; then every cell of the tile coded with its block's
// value as its hint, so a cell equal to its block costs almost nothing and
// the cells kept different (where a block would break a guarantee) are
// coded where they are. Cut into the same independently decodable tiles as
// CELL, so windows and threads work the same way.
//
// Why blocks: a map drawn in F x F blocks has about 1/F^2 of the cells to
// code, and every cell lies within F - 1 cells (Chebyshev) of every other
// cell of its block, which the tolerance allows a cell to move when
// F - 1 <= T. This is the PNG of the coarser map that the tolerance mode
// must beat, coded by the tile coder instead of deflate, and drawn back at
// full size so the file keeps the map's size, resolution and origin.
#ifndef LINEMAP_CODEC_CELLS_BLOCK_TILES_H_
#define LINEMAP_CODEC_CELLS_BLOCK_TILES_H_

#include <cstdint>
#include <vector>

#include "codec/cells/tile_coder.h"
#include "codec/layers/layer_hints.h"
#include "linemap/grid.h"
#include "linemap/status.h"

namespace linemap {

// Block sides a file may use (cells): up to tolerance 4's T + 1.
inline constexpr int kMinBlockCells = 2;
inline constexpr int kMaxBlockCells = 5;

// A grid drawn in blocks: block (bx, by) covers the cells
// [bx*F, bx*F + F) x [by*F, by*F + F) (clipped to the grid); a cell's value
// is its block's, or the original's where it is restored.
struct BlockCells {
  int block_cells = 0;  // F
  int blocks_x = 0, blocks_y = 0;
  std::vector<Cell> blocks;            // blocks_x * blocks_y, row 0 first
  std::vector<std::uint8_t> restored;  // one per cell of the grid, 1 = original value
};

// The cells `blocks` draw, taking restored cells from `original`.
Grid ComposeBlockCells(const Grid& original, const BlockCells& blocks);

// The chunk body: the cells ComposeBlockCells(original, blocks) draws, in
// tiles of `tile_size` cells on up to `threads` threads (the bytes do not
// depend on it); the blocks are coded against what `layers` (the file's
// vector layers) draw into them. The tile side must be 16..65536 and a multiple of F (so
// every tile's blocks are the grid's), else kInvalidArgument.
StatusOr<std::vector<std::uint8_t>> EncodeBlockChunk(const Grid& original, const BlockCells& blocks,
                                                     const LayerIndex& layers, int tile_size,
                                                     int threads);

// Decodes the tiles that meet `window` (inside the grid, non-empty) into
// `out`, a (x1 - x0) x (y1 - y0) array, row-major from y0. On an error the
// cells of `out` are unspecified (every caller drops them).
Status DecodeBlockChunk(const std::vector<std::uint8_t>& body, const LayerIndex& layers, int width,
                        int height, CellRect window, int threads, Cell* out);

}  // namespace linemap

#endif  // LINEMAP_CODEC_CELLS_BLOCK_TILES_H_
