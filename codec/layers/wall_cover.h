// Short wall segments for the obstacles the line extractor leaves out, so
// that the wall layer accounts for every obstacle surface of the map.
//
// The extractor fits lines to what looks like a wall; specks, clutter and
// ragged bits of wall (scan noise on SLAM maps) are left out, and a viewer or
// planner that reads the layers would not see them: on 6 of the 25 maps of
// ../shared/maps more than 5 % of the edge cells (occupied, with a free
// 4-neighbour) were more than one cell from any wall and in no furniture.
// CoveringSegments() closes that gap with the fewest segments it finds
// cheaply: each 8-connected cluster of such cells gets the segment between
// its two farthest cells, split until every cell of the cluster lies within
// one cell of a piece and every cell a piece is drawn over lies next to an
// occupied cell.
#ifndef LINEMAP_CODEC_LAYERS_WALL_COVER_H_
#define LINEMAP_CODEC_LAYERS_WALL_COVER_H_

#include <cstdint>
#include <vector>

#include "linemap/codec.h"
#include "linemap/grid.h"

namespace linemap {

// The segments that bring every edge cell of `grid` that is more than one
// cell (Euclidean, to the segment, as `linemap eval` measures) from all of
// `walls` and not marked in `covered` (one byte per cell; may be null: the
// cells inside furniture) within one cell of a wall. Deterministic; empty
// when nothing is left out.
std::vector<LatticeSegment> CoveringSegments(const Grid& grid,
                                             const std::vector<LatticeSegment>& walls,
                                             const std::vector<std::uint8_t>* covered);
// The same with the grid's edge cells given (`edge`: one byte per cell,
// non-zero exactly at the edge cells, as ComputeEdgeMap's is_edge), for a
// caller that has them already.
std::vector<LatticeSegment> CoveringSegments(const Grid& grid,
                                             const std::vector<LatticeSegment>& walls,
                                             const std::vector<std::uint8_t>* covered,
                                             const std::uint8_t* edge);

}  // namespace linemap

#endif  // LINEMAP_CODEC_LAYERS_WALL_COVER_H_
