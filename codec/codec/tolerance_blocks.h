// The cells of a file saved within a tolerance of T cells: the map drawn in
// blocks of T + 1 cells a side (BlockCells, block_tiles.h), with exact
// patches wherever a block breaks one of the guarantees of tolerance.h.
#ifndef LINEMAP_CODEC_CODEC_TOLERANCE_BLOCKS_H_
#define LINEMAP_CODEC_CODEC_TOLERANCE_BLOCKS_H_

#include "codec/codec/block_tiles.h"
#include "linemap/grid.h"
#include "linemap/status.h"

namespace linemap {

// Blocks of `tolerance_cells` + 1 (1..kMaxToleranceCells, else invalid
// argument): a block is occupied if any of its cells is, else unknown if
// any is, else free. So every occupied cell keeps an occupied cell within T
// (its block), every decoded occupied cell has an original one within T,
// and free cells only ever turn unknown or occupied, never the other way:
// no leak and no unknown turned free. What blocks can break (a free cell
// with no free block within T, a doorway closed, a plan made longer) is
// found by CheckTolerance's measures and patched, 8 x 8-cell unit by unit,
// until every guarantee holds on ComposeBlockCells(grid, result).
StatusOr<BlockCells> FitBlockCells(const Grid& grid, int tolerance_cells);

}  // namespace linemap

#endif  // LINEMAP_CODEC_CODEC_TOLERANCE_BLOCKS_H_
