// RM-Line's screening model and ray model (Liu & Zhang, "RM-Line: A
// Ray-Model-Based Straight-Line Extraction Method for the Grid Map of Mobile
// Robot", Appl. Sci. 2022, 12, 9754, sections 2.2-2.4). Exposed for tests;
// the public entry point is ExtractLines() in linemap/lines.h.
#ifndef LINEMAP_CODEC_LINES_RMLINE_H_
#define LINEMAP_CODEC_LINES_RMLINE_H_

#include <array>
#include <cstdint>
#include <vector>

#include "linemap/lines.h"
#include "linemap/status.h"

namespace linemap::lines_internal {

struct CellOffset {
  int dcol = 0;
  int drow = 0;
  bool operator==(const CellOffset&) const = default;
};

// The 8 neighbours p0..p7 of the target point (Figure 2a), counter-clockwise
// from east: p0 (+1,0), p1 (+1,+1), p2 (0,+1), p3 (-1,+1), p4 (-1,0),
// p5 (-1,-1), p6 (0,-1), p7 (+1,-1) (column, row offsets; row up).
const std::array<CellOffset, 8>& ScreeningNeighbours();

// The three tail points p_i0, p_i1, p_i2 of neighbour `neighbour` (Figure 2b),
// as offsets from the TARGET point: the cells one step further out from the
// neighbour, in the neighbour's direction d turned by -45, 0 and +45 degrees:
// tail_j = d + rotate(d, (j - 1) * 45 deg). So for east (+1,0) they are
// (2,-1), (2,0), (2,1); for north-east (+1,+1) they are (2,1), (2,2), (1,2).
// The middle tail p_i1 is the straight continuation (the paper's example:
// p_2 and its tail p_21 are obstacles, so p_t is active).
std::array<CellOffset, 3> TailPoints(const CellOffset& neighbour);

// Section 2.2: an edge point is active when some 8-neighbour is an edge
// point and at least one of that neighbour's tail points is an edge point
// too. Isolated points and the ends of contours shorter than three cells are
// thus inactive. Returns width*height flags (1 = active).
std::vector<std::uint8_t> ScreenActivePoints(const EdgeMap& edges);

// Section 2.3: the best ray pair from one start cell.
struct RayPair {
  int score = 0;                     // Eq. (1): obstacle scoring points on both rays
  int direction_index = 0;           // n: the rays point along n*dtheta and n*dtheta+180
  std::vector<std::uint32_t> cells;  // the cluster: distinct cells traversed, sorted
};

// Casts the rays from cell (col, row) at n*dtheta_deg (0 <= n <= 180/dtheta)
// and their reverses, a scoring point every ds_cells from the centre, each
// ray stopping at its first scoring point that is not an edge point (or off
// the map). Ties keep the smallest n.
RayPair CastBestRayPair(const EdgeMap& edges, int col, int row, double dtheta_deg, double ds_cells);

// Section 2.4: the whole method on an edge map. dtheta_deg in (0, 180],
// ds_cells in (0, 1].
StatusOr<std::vector<LineSegment>> ExtractRmLine(const EdgeMap& edges, double dtheta_deg,
                                                 double ds_cells);

}  // namespace linemap::lines_internal

#endif  // LINEMAP_CODEC_LINES_RMLINE_H_
