// Steps 7 and 8 of linemap's extractor (see linemap_extractor.cc): each line
// moves towards the least-absolute-distance line of its cells, and wall ends
// that meet at a corner are extended to it.
#ifndef LINEMAP_CODEC_LINES_POLISH_AND_CORNERS_H_
#define LINEMAP_CODEC_LINES_POLISH_AND_CORNERS_H_

#include <vector>

#include "codec/lines/line_groups.h"
#include "linemap/lines.h"

namespace linemap::lines_internal {

// Buffers reused across PolishGroupL1 calls.
struct PolishScratch {
  std::vector<double> xs, ys, w;
};

// Step 7: moves each group's line towards the least-absolute-distance line
// of its cells (what DisPL_ave measures) by iteratively reweighted total
// least squares (weights 1 / max(|r|, 0.1 cell), Eigen on the weighted 2x2
// covariance), keeping a new line only while it lowers the summed distance
// and keeps every cell within epsilon. The segment spans all cells.
void PolishGroupL1(Group* group, double epsilon, PolishScratch* scratch);

// Step 8: corners. Two segments whose ends are within `reach` cells of each
// other and which meet at more than 20 degrees are both extended to the
// intersection of their lines when that point lies beyond both ends and
// within `reach` of each, so that decoded walls close at corners. Segments
// only grow, so no cell gets farther from its segment.
void JoinCorners(std::vector<LineSegment>* segments, int width, int height, double reach);

}  // namespace linemap::lines_internal

#endif  // LINEMAP_CODEC_LINES_POLISH_AND_CORNERS_H_
