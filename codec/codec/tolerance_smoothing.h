// The smoothing SimplifyWithinTolerance() proposes before checking it: what
// makes a map cheaper for the tile coder (fewer specks, straighter borders
// between free and unknown space), each change local and at most a few
// cells from where the map had that kind of cell.
#ifndef LINEMAP_CODEC_CODEC_TOLERANCE_SMOOTHING_H_
#define LINEMAP_CODEC_CODEC_TOLERANCE_SMOOTHING_H_

#include "linemap/grid.h"

namespace linemap::tolerance_internal {

struct SmoothingParams {
  // Free space opened by a square of this radius (cells; thin free rays
  // into unknown space become unknown), except within open_radius + 1 of
  // an occupied cell, where doorways are.
  int open_radius = 1;
  // Free space closed by a square of this radius (cells): unknown notches
  // and specks inside free space become free. Occupied cells never change.
  int close_radius = 1;
  // Occupied 8-connected components of at most this many cells, surrounded
  // by free cells and within T of a larger occupied component, become free.
  int speck_cells = 4;
  // Passes of a 3x3 majority vote between occupied and unknown among the
  // cells with no free 8-neighbour (the backs of walls).
  int wall_back_passes = 1;
  // Side of the aligned blocks every cell takes its block's value from
  // (occupied if any cell is, else unknown if any is, else free) before the
  // rest; 1 (or less) leaves cells alone.
  int block_cells = 1;
  // The same for the non-free cells only (free cells stay): in each aligned
  // block of this side the non-free cells all become occupied if any of
  // them is, else stay unknown. Free space, and so every plan, is kept
  // exactly; obstacles move by less than the block side. 1 leaves them.
  int nonfree_block_cells = 1;
};

// The parameters used for a tolerance of `t` cells (1..4).
SmoothingParams DefaultSmoothingParams(int t);

// The proposed grid; the guarantees are not checked here.
Grid ProposeSmoothing(const Grid& grid, int t, const SmoothingParams& params);
inline Grid ProposeSmoothing(const Grid& grid, int t) {
  return ProposeSmoothing(grid, t, DefaultSmoothingParams(t));
}

}  // namespace linemap::tolerance_internal

#endif  // LINEMAP_CODEC_CODEC_TOLERANCE_SMOOTHING_H_
