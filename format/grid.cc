#include "linemap/grid.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "format/large_vector.h"
#include "format/metre_cells.h"

namespace linemap {

const char* MapModeName(MapMode mode) {
  switch (mode) {
    case MapMode::kTrinary:
      return "trinary";
    case MapMode::kScale:
      return "scale";
    case MapMode::kRaw:
      return "raw";
  }
  return "trinary";
}

std::optional<MapMode> MapModeFromName(std::string_view name) {
  for (const MapMode mode : {MapMode::kTrinary, MapMode::kScale, MapMode::kRaw}) {
    if (name == MapModeName(mode)) return mode;
  }
  return std::nullopt;
}

Grid::Grid(int width, int height, Cell fill)
    : width_(width < 0 ? 0 : width), height_(height < 0 ? 0 : height) {
  AssignLarge(&cells_, static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_), fill);
}

CellCounts Grid::Count() const {
  CellCounts counts;
  for (Cell c : cells_) {
    switch (c) {
      case Cell::kFree:
        ++counts.free;
        break;
      case Cell::kOccupied:
        ++counts.occupied;
        break;
      case Cell::kUnknown:
        ++counts.unknown;
        break;
    }
  }
  return counts;
}

void Grid::CellToWorld(double col, double row, double* x, double* y) const {
  // The origin is the pose of the lower-left corner of cell (0, 0); the centre
  // of that cell lies half a cell inside it along both map axes.
  const double u = (col + 0.5) * meta.resolution;
  const double v = (row + 0.5) * meta.resolution;
  const double c = std::cos(meta.origin.yaw);
  const double s = std::sin(meta.origin.yaw);
  *x = meta.origin.x + c * u - s * v;
  *y = meta.origin.y + s * u + c * v;
}

CellPosition CellPositionOf(const MapMetadata& meta, double x, double y) {
  Grid frame;  // only its metadata: the map's cell <-> metre transform
  frame.meta = meta;
  CellPosition p;
  frame.WorldToCell(x, y, &p.col, &p.row);
  const double c = std::abs(std::cos(meta.origin.yaw)), s = std::abs(std::sin(meta.origin.yaw));
  const double along_x = std::abs(x) + std::abs(meta.origin.x);
  const double along_y = std::abs(y) + std::abs(meta.origin.y);
  const double ulps = 16 * std::numeric_limits<double>::epsilon() / meta.resolution;
  p.col_slack = 1e-9 + ulps * (c * along_x + s * along_y);
  p.row_slack = 1e-9 + ulps * (s * along_x + c * along_y);
  return p;
}

std::optional<CellIndex> CellHoldingPoint(const MapMetadata& meta, int width, int height, double x,
                                          double y) {
  // Cell c's square is [c - 0.5, c + 0.5): a point within the slack below
  // its lower or left edge was typed on that edge.
  const CellPosition p = CellPositionOf(meta, x, y);
  const double col = std::floor(p.col + 0.5 + p.col_slack);
  const double row = std::floor(p.row + 0.5 + p.row_slack);
  // Written so that NaN fails it too.
  if (!(col >= 0 && row >= 0 && col < width && row < height)) return std::nullopt;
  return CellIndex{static_cast<int>(col), static_cast<int>(row)};
}

MetreBounds MapBoundsMetres(const MapMetadata& meta, int width, int height) {
  Grid frame;  // only its metadata: the map's cell <-> metre transform
  frame.meta = meta;
  MetreBounds box;
  bool first = true;
  for (double col : {-0.5, width - 0.5}) {
    for (double row : {-0.5, height - 0.5}) {
      double x, y;
      frame.CellToWorld(col, row, &x, &y);
      box.min_x = first ? x : std::min(box.min_x, x);
      box.min_y = first ? y : std::min(box.min_y, y);
      box.max_x = first ? x : std::max(box.max_x, x);
      box.max_y = first ? y : std::max(box.max_y, y);
      first = false;
    }
  }
  return box;
}

std::optional<CellIndex> Grid::CellHolding(double x, double y) const {
  return CellHoldingPoint(meta, width_, height_, x, y);
}

void Grid::WorldToCell(double x, double y, double* col, double* row) const {
  const double dx = x - meta.origin.x;
  const double dy = y - meta.origin.y;
  const double c = std::cos(meta.origin.yaw);
  const double s = std::sin(meta.origin.yaw);
  *col = (c * dx + s * dy) / meta.resolution - 0.5;
  *row = (-s * dx + c * dy) / meta.resolution - 0.5;
}

}  // namespace linemap
