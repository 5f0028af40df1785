// A window given in map-frame metres, as the cells it covers: the rule that
// `linemap decode --window` and lmap_server's ~window share.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "linemap/codec.h"
#include "linemap/grid.h"

namespace linemap {
namespace {

// Cell-unit slack for box edges that fall on a cell centre: 0.025 m at
// 0.05 m/cell is 0.49999999999999994 cells in doubles. The rounding grows
// with the coordinates (an origin at a UTM northing of 5,412,345.67 m puts
// an edge typed on a centre 2e-8 cells off at 0.05 m/cell), so the slack
// does too: a few units in the last place of the largest coordinate, in
// cells.
double EdgeSlackCells(const MapMetadata& meta, double x0, double y0, double x1, double y1) {
  const double scale = std::max({std::abs(x0), std::abs(y0), std::abs(x1), std::abs(y1)}) +
                       std::abs(meta.origin.x) + std::abs(meta.origin.y);
  return 1e-9 + 16 * std::numeric_limits<double>::epsilon() * scale / meta.resolution;
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
                "rows 0..%d) is turned by its origin's yaw of %g rad: the cells are those whose "
                "centres lie within the window's corners taken into the grid; the turned map "
                "spans x %g..%g m, y %g..%g m, a box not all of which is on the map",
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
  // The first and last centres, inclusive, still in doubles: far off the
  // map (or on a map over 2^29 cells wide) no int holds them.
  const double slack = EdgeSlackCells(meta, x0, y0, x1, y1);
  const double c0 = std::ceil(min_col - slack), c1 = std::floor(max_col + slack);
  const double r0 = std::ceil(min_row - slack), r1 = std::floor(max_row + slack);
  // Negated, so that a NaN fails too.
  if (!(c0 <= c1 && r0 <= r1)) {
    return InvalidArgumentError(BoxText(label, x0, y0, x1, y1) + " holds no cell centre");
  }
  if (!(c0 >= 0 && r0 >= 0 && c1 <= width - 1.0 && r1 <= height - 1.0)) {
    // Held to a few map sizes off the map, so that they print as whole
    // numbers.
    const double limit = 4.0 * std::max(width, height) + 4;
    auto index = [&](double v) { return static_cast<long long>(std::clamp(v, -limit, limit)); };
    char cells[160];
    std::snprintf(cells, sizeof(cells), "cells [%lld, %lld) x [%lld, %lld)", index(c0),
                  index(c1) + 1, index(r0), index(r1) + 1);
    return InvalidArgumentError(BoxText(label, x0, y0, x1, y1) + " covers " + cells +
                                ", past the map's border: " + ExtentText(meta, width, height));
  }
  CellWindow w;
  w.col0 = static_cast<int>(c0);
  w.col1 = static_cast<int>(c1) + 1;
  w.row0 = static_cast<int>(r0);
  w.row1 = static_cast<int>(r1) + 1;
  return w;
}

}  // namespace linemap
