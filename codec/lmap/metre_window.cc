// A window given in map-frame metres, as the cells it covers: the rule that
// `linemap decode --window` and lmap_server's ~window share.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "linemap/codec.h"
#include "linemap/grid.h"

namespace linemap {
namespace {

// Cell-unit slack for box edges that fall on a cell centre: 0.025 m at
// 0.05 m/cell is 0.49999999999999994 cells in doubles.
constexpr double kEdgeSlackCells = 1e-9;

std::string CellsText(const CellWindow& w) {
  return "cells [" + std::to_string(w.col0) + ", " + std::to_string(w.col1) + ") x [" +
         std::to_string(w.row0) + ", " + std::to_string(w.row1) + ")";
}

std::string BoxText(const std::string& label, double x0, double y0, double x1, double y1) {
  char text[160];
  std::snprintf(text, sizeof(text), " %g,%g,%g,%g m", x0, y0, x1, y1);
  return label + text;
}

// What the map covers, for a window past it. Unturned, the map's cell
// centres span an axis-aligned box, which says it all. Turned by a yaw, the
// box around its rectangle's corners also holds points off the map (a
// window inside that box can still be refused), so the text says that the
// window is taken in map-frame metres into the turned grid, which columns
// and rows the grid has, and gives that box as the map's extent.
std::string ExtentText(const MapMetadata& meta, int width, int height) {
  Grid frame;  // only its metadata: the map's cell <-> metre transform
  frame.meta = meta;
  char text[400];
  if (meta.origin.yaw == 0) {
    double ax, ay, bx, by;
    frame.CellToWorld(0, 0, &ax, &ay);
    frame.CellToWorld(width - 1, height - 1, &bx, &by);
    std::snprintf(text, sizeof(text), "the map's %d x %d cells have centres from %g,%g to %g,%g m",
                  width, height, ax, ay, bx, by);
    return text;
  }
  const MetreBounds b = MapBoundsMetres(meta, width, height);
  std::snprintf(text, sizeof(text),
                "the window is taken in map-frame metres, and the map's grid (columns 0..%d, "
                "rows 0..%d) is turned by its origin's yaw of %g rad: the cells are those the "
                "window's corners fall in; the turned map spans x %g..%g m, y %g..%g m, a box "
                "not all of which is on the map",
                width - 1, height - 1, meta.origin.yaw, b.min_x, b.max_x, b.min_y, b.max_y);
  return text;
}

}  // namespace

StatusOr<CellWindow> CellWindowOfMetres(const MapMetadata& meta, int width, int height, double x0,
                                        double y0, double x1, double y1, const std::string& label) {
  // Written so that NaN fails it too.
  if (!(x0 <= x1 && y0 <= y1)) {
    return InvalidArgumentError(BoxText(label, x0, y0, x1, y1) +
                                ": X0 must not exceed X1, nor Y0 Y1 (finite metres)");
  }
  Grid frame;  // only its metadata: the map's cell <-> metre transform
  frame.meta = meta;
  double min_col = 0, max_col = 0, min_row = 0, max_row = 0;
  bool first = true;
  for (double x : {x0, x1}) {
    for (double y : {y0, y1}) {
      double col, row;
      frame.WorldToCell(x, y, &col, &row);
      min_col = first ? col : std::min(min_col, col);
      max_col = first ? col : std::max(max_col, col);
      min_row = first ? row : std::min(min_row, row);
      max_row = first ? row : std::max(max_row, row);
      first = false;
    }
  }
  // Far outside the map the indices would overflow an int: such a box is
  // past the border anyway.
  const double limit = 4.0 * std::max(width, height) + 4;
  auto clamp = [&](double v) { return std::isnan(v) ? -limit : std::clamp(v, -limit, limit); };
  CellWindow w;
  w.col0 = static_cast<int>(std::ceil(clamp(min_col - kEdgeSlackCells)));
  w.col1 = static_cast<int>(std::floor(clamp(max_col + kEdgeSlackCells))) + 1;
  w.row0 = static_cast<int>(std::ceil(clamp(min_row - kEdgeSlackCells)));
  w.row1 = static_cast<int>(std::floor(clamp(max_row + kEdgeSlackCells))) + 1;
  if (w.col0 >= w.col1 || w.row0 >= w.row1) {
    return InvalidArgumentError(BoxText(label, x0, y0, x1, y1) + " holds no cell centre");
  }
  if (w.col0 < 0 || w.row0 < 0 || w.col1 > width || w.row1 > height) {
    return InvalidArgumentError(BoxText(label, x0, y0, x1, y1) + " covers " + CellsText(w) +
                                ", past the map's border: " + ExtentText(meta, width, height));
  }
  return w;
}

}  // namespace linemap
