// The cells of a file saved within a tolerance of T cells: the map drawn in
// blocks of T + 1 cells a side (BlockCells, cells/block_tiles.h), with cells given back
// their original value wherever a block breaks one of the guarantees of
// linemap/tolerance.h.
#ifndef LINEMAP_CODEC_TOLERANCE_TOLERANCE_BLOCKS_H_
#define LINEMAP_CODEC_TOLERANCE_TOLERANCE_BLOCKS_H_

#include <functional>

#include "codec/cells/block_tiles.h"
#include "linemap/grid.h"
#include "linemap/status.h"

namespace linemap {

// The blocks for a tolerance of `tolerance_cells` (1..kMaxToleranceCells,
// else invalid argument). A block is occupied if any of its cells is (so
// every occupied cell keeps an occupied cell within T, and every decoded
// occupied cell has an original one within 1); else free if any is and
// filling its unknown cells opens no new way between free cells; else
// unknown. Unknown cells turn free only next to a free cell of their block.
// What blocks can still break (a free cell with no free cell within T, two
// free regions joined or one split, a plan made longer or shorter) is found
// on exactly what the file decodes to and mended (cells restored, or a
// block turned unknown) round by round until every guarantee holds on
// ComposeBlockCells(grid, result); a map that does not settle gets every
// cell restored (the exact map). `after_round`, when given, is called after
// each round that mended cells without settling, with the number of rounds
// done so far (the caller's progress: the rounds that run are not known
// ahead). The plan checks run on up to `threads` threads (0: one per core);
// the result does not depend on them.
StatusOr<BlockCells> FitBlockCells(const Grid& grid, int tolerance_cells,
                                   const std::function<void(int)>& after_round = nullptr,
                                   int threads = 1);

}  // namespace linemap

#endif  // LINEMAP_CODEC_TOLERANCE_TOLERANCE_BLOCKS_H_
