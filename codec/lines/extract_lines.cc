// ExtractLines(): the edge map, then the chosen method (RM-Line or linemap's
// extractor) on it.
#include "codec/lines/extract_lines.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "codec/lines/linemap_extractor.h"
#include "codec/lines/rmline.h"
#include "format/metre_cells.h"
#include "linemap/lines.h"

namespace linemap {
namespace {

Status CheckRobot(const Grid& grid, const CellPoint& robot) {
  const double col = std::floor(robot.col + 0.5);
  const double row = std::floor(robot.row + 0.5);
  if (!(col >= 0 && row >= 0 && col < grid.width() && row < grid.height())) {
    return InvalidArgumentError("the robot position is off the map");
  }
  if (grid.at(static_cast<int>(col), static_cast<int>(row)) != Cell::kFree) {
    return InvalidArgumentError("the robot position is not on a free cell");
  }
  return Status::Ok();
}

}  // namespace

StatusOr<LineExtraction> ExtractLines(const Grid& grid, const LineExtractionOptions& options) {
  if (options.robot) LINEMAP_RETURN_IF_ERROR(CheckRobot(grid, *options.robot));
  LineExtraction result;
  result.edges = ComputeEdgeMap(grid, options.robot);
  switch (options.method) {
    case LineMethod::kRmLine: {
      LINEMAP_ASSIGN_OR_RETURN(
          result.segments, lines_internal::ExtractRmLine(result.edges, options.rmline_dtheta_deg,
                                                         options.rmline_ds_cells));
      return result;
    }
    case LineMethod::kLinemap: {
      LINEMAP_ASSIGN_OR_RETURN(lines_internal::LinemapLines lines,
                               lines_internal::ExtractLinemapLines(result.edges, options));
      result.segments = std::move(lines.segments);
      result.left_to_blobs = std::move(lines.left_to_blobs);
      result.cells_left_to_blobs = lines.cells_left_to_blobs;
      return result;
    }
  }
  return InternalError("unknown line extraction method");
}

StatusOr<std::vector<LineSegment>> ExtractLineSegments(const Grid& grid,
                                                       const LineExtractionOptions& options) {
  if (options.method != LineMethod::kLinemap) {
    LINEMAP_ASSIGN_OR_RETURN(LineExtraction lines, ExtractLines(grid, options));
    return std::move(lines.segments);
  }
  if (options.robot) LINEMAP_RETURN_IF_ERROR(CheckRobot(grid, *options.robot));
  std::vector<std::uint32_t> speckle;
  return lines_internal::ExtractLinemapSegments(ComputeEdgeMap(grid, options.robot), options,
                                                &speckle);
}

CellPoint RobotCellPoint(const Grid& grid, double x, double y) {
  if (const std::optional<CellIndex> cell = grid.CellHolding(x, y)) {
    return {static_cast<double>(cell->col), static_cast<double>(cell->row)};
  }
  // Off the map. A point typed on its upper or right edge is off it by
  // CellHoldingPoint's rule (an edge belongs to the next cell) yet within
  // the slack of the last cell's centre + 0.5, where the callers' rounding
  // would put it inside: it goes onto the edge, which that rounding takes
  // as outside too.
  const CellPosition p = CellPositionOf(grid.meta, x, y);
  CellPoint point{p.col, p.row};
  if (std::floor(p.col + 0.5 + p.col_slack) >= grid.width()) {
    point.col = std::max(point.col, grid.width() - 0.5);
  }
  if (std::floor(p.row + 0.5 + p.row_slack) >= grid.height()) {
    point.row = std::max(point.row, grid.height() - 0.5);
  }
  return point;
}

LineExtractionOptions StraightWalls(LineExtractionOptions options) {
  options.split_epsilon_cells = 0.3;
  options.target_mean_distance_cells = 0;
  options.distance_growth_factor = 0;
  options.prune_added_cost_cells = 3.0;
  options.noise_merge_factor = 0;
  options.speck_max_cells = 0;
  return options;
}

}  // namespace linemap
