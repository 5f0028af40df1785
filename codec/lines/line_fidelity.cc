// RM-Line's accuracy measure (Liu & Zhang 2022, section 3.1, Eq. 5):
// DisPL_ave = (sum over the edge map's obstacle cells of the distance from
// the cell centre to the nearest extracted segment) / N. Distances are to the
// segments (not their infinite lines), in cells. We also report the largest
// distance and the share of cells within one cell of a segment.
#include <algorithm>
#include <limits>

#include "codec/lines/segment_index.h"
#include "linemap/lines.h"

namespace linemap {

LineFidelity MeasureLineFidelity(const EdgeMap& edges, const std::vector<LineSegment>& segments) {
  LineFidelity fidelity;
  lines_internal::SegmentIndex index(&segments, edges.width, edges.height);
  double sum = 0;
  std::size_t within_1 = 0;
  for (int row = 0; row < edges.height; ++row) {
    for (int col = 0; col < edges.width; ++col) {
      if (!edges.is_edge[static_cast<std::size_t>(row) * edges.width + col]) continue;
      const double d = index.NearestDistance(col, row);
      ++fidelity.edge_cells;
      sum += d;
      fidelity.displ_max_cells = std::max(fidelity.displ_max_cells, d);
      if (d <= 1.0) ++within_1;
    }
  }
  if (fidelity.edge_cells > 0) {
    const double n = static_cast<double>(fidelity.edge_cells);
    fidelity.displ_ave_cells = sum / n;
    fidelity.share_within_1 = static_cast<double>(within_1) / n;
  }
  return fidelity;
}

}  // namespace linemap
