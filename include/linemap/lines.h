// Wall line segments from an occupancy grid: RM-Line (Liu & Zhang, Appl. Sci.
// 2022, 12, 9754) and linemap's own extractor, with the paper's measures.
//
// All geometry is in cell units (the centre of cell (col, row) is the point
// (col, row)); see grid.h for the conversion to map-frame metres.
//
// CONTRACT (fixed by the lead; extend, do not rename): the codec and the CLI
// call ExtractLines() and MeasureLineFidelity().
#ifndef LINEMAP_LINES_H_
#define LINEMAP_LINES_H_

#include <cstddef>
#include <optional>
#include <vector>

#include "linemap/grid.h"
#include "linemap/status.h"

namespace linemap {

struct LineSegment {
  double x1 = 0, y1 = 0;  // cell units
  double x2 = 0, y2 = 0;
};

// A point in cell units (col, row), e.g. the robot position.
struct CellPoint {
  double col = 0;
  double row = 0;
};

enum class LineMethod {
  kRmLine,   // the paper's method, as written
  kLinemap,  // linemap's own extractor (the default once it lands)
};

// The paper's edge map (section 2.1): obstacle cells 4-adjacent to the free
// cells flooded from the robot position (or from every free cell when no
// position is given).
struct EdgeMap {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> is_edge;  // width * height, grid-row order, 1 = edge point
  std::size_t edge_count = 0;
};

// `robot` in cell units; without it every free component is flooded.
EdgeMap ComputeEdgeMap(const Grid& grid, std::optional<CellPoint> robot = std::nullopt);

struct LineExtractionOptions {
  LineMethod method = LineMethod::kRmLine;
  std::optional<CellPoint> robot;  // cell units; see ComputeEdgeMap
  // RM-Line parameters (documented with units and defaults where defined).
  double rmline_dtheta_deg = 1.0;
  double rmline_ds_cells = 0.5;
  // linemap extractor: every edge cell lies within epsilon of a segment (cells).
  double epsilon_cells = 1.0;
};

struct LineExtraction {
  std::vector<LineSegment> segments;
  EdgeMap edges;  // the edge map the lines were extracted from
};

StatusOr<LineExtraction> ExtractLines(const Grid& grid, const LineExtractionOptions& options);

// The paper's measures (section 3.1, Eq. 5) over the edge cells.
struct LineFidelity {
  std::size_t edge_cells = 0;
  double displ_ave_cells = 0;  // DisPL_ave: mean distance from edge cell centre to nearest segment
  double displ_max_cells = 0;  // the largest such distance
  double share_within_1 = 0;   // share of edge cells within 1 cell of a segment
};

LineFidelity MeasureLineFidelity(const EdgeMap& edges, const std::vector<LineSegment>& segments);

}  // namespace linemap

#endif  // LINEMAP_LINES_H_
