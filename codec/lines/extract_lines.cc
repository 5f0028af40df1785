// ExtractLines(): the edge map, then the chosen method (RM-Line or linemap's
// extractor) on it.
#include <cmath>

#include "codec/lines/rmline.h"
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
    case LineMethod::kLinemap:
      return UnsupportedError("the linemap line extractor is not implemented yet");
  }
  return InternalError("unknown line extraction method");
}

}  // namespace linemap
