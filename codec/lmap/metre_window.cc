// A window given in map-frame metres, as the cells it covers: the rule that
// `linemap decode --window` and lmap_server's ~window share.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "format/metre_cells.h"
#include "linemap/codec.h"
#include "linemap/grid.h"

namespace linemap {
namespace {

// A first or last cell index (whole, in a double): in full while a double
// holds every whole number around it, else rounded to 4 digits (a window of
// -1e18 m starts at column -2e+19, which no 64-bit integer holds).
std::string IndexText(double index) {
  index += 0.0;  // -0 (the ceiling of -0.4) prints as 0
  char text[64];
  if (std::abs(index) <= 1e15) {
    std::snprintf(text, sizeof(text), "%.0f", index);
  } else {
    std::snprintf(text, sizeof(text), "%.4g", index);
  }
  return text;
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
  // The first and last centres, inclusive, still in doubles: far off the
  // map (or on a map over 2^29 cells wide) no int holds them. A centre on
  // an edge is taken within the slack of that corner's coordinate
  // (CellPositionOf): the same rule as a point on a cell's edge.
  double c0 = 0, c1 = 0, r0 = 0, r1 = 0;
  bool first = true;
  for (double x : {x0, x1}) {
    for (double y : {y0, y1}) {
      const CellPosition p = CellPositionOf(meta, x, y);
      const double lo_col = std::ceil(p.col - p.col_slack),
                   hi_col = std::floor(p.col + p.col_slack);
      const double lo_row = std::ceil(p.row - p.row_slack),
                   hi_row = std::floor(p.row + p.row_slack);
      c0 = first ? lo_col : std::min(c0, lo_col);
      c1 = first ? hi_col : std::max(c1, hi_col);
      r0 = first ? lo_row : std::min(r0, lo_row);
      r1 = first ? hi_row : std::max(r1, hi_row);
      first = false;
    }
  }
  // Negated, so that a NaN fails too.
  if (!(c0 <= c1 && r0 <= r1)) {
    return InvalidArgumentError(BoxText(label, x0, y0, x1, y1) + " holds no cell centre");
  }
  if (!(c0 >= 0 && r0 >= 0 && c1 <= width - 1.0 && r1 <= height - 1.0)) {
    const std::string cells = "cells [" + IndexText(c0) + ", " + IndexText(c1 + 1) + ") x [" +
                              IndexText(r0) + ", " + IndexText(r1 + 1) + ")";
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
