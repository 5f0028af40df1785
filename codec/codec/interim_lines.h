// INTERIM wall-segment extractor, used only until ExtractLines()
// (include/linemap/lines.h) is implemented: maximal horizontal and vertical
// runs of wall cells. It is exact on the lattice (every covered cell is a wall
// cell) but finds no oblique walls; the OCCP plane codes what it misses.
#ifndef LINEMAP_CODEC_CODEC_INTERIM_LINES_H_
#define LINEMAP_CODEC_CODEC_INTERIM_LINES_H_

#include <cstdint>
#include <vector>

#include "linemap/codec.h"

namespace linemap {

// `wall` is width*height, grid-row order, 1 = wall cell. Runs shorter than
// `min_run_cells` (suggested 8 cells) are left out.
std::vector<LatticeSegment> InterimAxisRunSegments(const std::vector<std::uint8_t>& wall, int width,
                                                   int height, int min_run_cells);

}  // namespace linemap

#endif  // LINEMAP_CODEC_CODEC_INTERIM_LINES_H_
