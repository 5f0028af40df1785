// Lossy saves with a tolerance that holds: a simplified grid, within T cells
// (Chebyshev) of the input, that the exact 2.0 coder codes in fewer bytes.
// The guarantees and their measures are public (linemap/tolerance.h).
#ifndef LINEMAP_CODEC_TOLERANCE_SIMPLIFY_H_
#define LINEMAP_CODEC_TOLERANCE_SIMPLIFY_H_

#include "linemap/grid.h"
#include "linemap/status.h"
#include "linemap/tolerance.h"

namespace linemap {

// The grid a file saved within `tolerance_cells` (0..kMaxToleranceCells;
// else invalid argument) decodes to when its cells are in blocks: the map
// drawn in blocks of T + 1 cells a side, with cells given back their original
// value wherever a guarantee of linemap/tolerance.h would fail (FitBlockCells,
// tolerance_blocks.h), so CheckTolerance(grid, result, tolerance_cells)
// .Holds() is true. tolerance_cells == 0 returns the grid unchanged.
// Deterministic; metadata is kept.
StatusOr<Grid> SimplifyWithinTolerance(const Grid& grid, int tolerance_cells);

}  // namespace linemap

#endif  // LINEMAP_CODEC_TOLERANCE_SIMPLIFY_H_
