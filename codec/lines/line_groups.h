// Groups, the candidate walls of linemap's extractor (linemap_extractor.cc):
// from step 3 on every chained edge cell is owned by one group and lies
// within epsilon of the group's segment. Here: the group, and the fit of its
// line and segment to its cells, which steps 3 and 4 share.
#ifndef LINEMAP_CODEC_LINES_LINE_GROUPS_H_
#define LINEMAP_CODEC_LINES_LINE_GROUPS_H_

#include <vector>

#include "codec/lines/edge_cells.h"
#include "codec/lines/line_fit.h"
#include "linemap/lines.h"

namespace linemap::lines_internal {

// Fits computed from prefix sums and from PointMoments may differ by
// rounding; the bound is guaranteed up to this many cells.
inline constexpr double kRoundingSlack = 1e-9;

// std::max and std::min for doubles as value selects: the same results
// (including the sign of zero and NaNs), but compiled to maxsd/minsd
// rather than to branches, which the merge's data-dependent tests
// mispredict.
inline double MaxOf(double a, double b) { return b > a ? b : a; }
inline double MinOf(double a, double b) { return b < a ? b : a; }

// A candidate wall: its cells, their moments and the fitted segment.
// The fields a merge's lower bound reads for every candidate pair come
// first, near each other.
struct Group {
  PointMoments moments;
  double cost = 0;          // sum of the cells' distances to `segment` (cells)
  double noise = 0;         // sum of the cells' local residuals (ChainMoments::LocalResidual)
  double max_residual = 0;  // largest distance of a cell to `line`
  FittedLine line;
  LineSegment segment;
  std::vector<CellXY> cells;  // (col, row): no division in the hot loops
  bool alive = true;
};

// Distances of cells to a line, and the extent of their projections.
struct LineSweep {
  double cost = 0;   // summed distance
  double worst = 0;  // largest distance
  double t_min = 0, t_max = 0;
  bool any = false;
};

// Adds `cells` to `sweep`; false as soon as a cell is farther than epsilon
// or the summed distance passes max_cost.
bool SweepCells(const FittedLine& line, const std::vector<CellXY>& cells, double epsilon,
                double max_cost, LineSweep* sweep);

// Gives `group` `line`, the sweep's distances and the segment over the
// extent of its cells' projections (`sweep`).
void SetLine(Group* group, const FittedLine& line, const LineSweep& sweep);

// Fits `line` and `segment` of a group from its cells; false when some cell
// is farther than epsilon from the line.
bool RefitGroup(Group* group, double epsilon);

}  // namespace linemap::lines_internal

#endif  // LINEMAP_CODEC_LINES_LINE_GROUPS_H_
