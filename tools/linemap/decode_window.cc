#include "tools/linemap/decode_window.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

#include "linemap/lmap_vectors.h"
#include "tools/linemap/lmap_cli_util.h"

namespace linemap::cli {

namespace {

// Cell-unit slack for box edges that fall on a cell centre: 0.025 m at
// 0.05 m/cell is 0.49999999999999994 cells in doubles.
constexpr double kEdgeSlackCells = 1e-9;

std::string WindowText(const CellWindow& w) {
  return "cells [" + std::to_string(w.col0) + ", " + std::to_string(w.col1) + ") x [" +
         std::to_string(w.row0) + ", " + std::to_string(w.row1) + ")";
}

std::string BoxText(const MetreBox& b) {
  char text[128];
  std::snprintf(text, sizeof(text), "%g,%g,%g,%g m", b.x0, b.y0, b.x1, b.y1);
  return text;
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
  const auto [min_x, min_y, max_x, max_y] = MapExtentMetres(meta, width, height);
  std::snprintf(text, sizeof(text),
                "the window is taken in map-frame metres, and the map's grid (columns 0..%d, "
                "rows 0..%d) is turned by its origin's yaw of %g rad: the cells are those the "
                "window's corners fall in; the turned map spans x %g..%g m, y %g..%g m, a box "
                "not all of which is on the map",
                width - 1, height - 1, meta.origin.yaw, min_x, max_x, min_y, max_y);
  return text;
}

StatusOr<CellWindow> WindowFromCellList(const std::vector<double>& v) {
  for (double x : v) {
    if (x != std::floor(x) || std::abs(x) > std::numeric_limits<int>::max()) {
      return InvalidArgumentError("--window-cells takes whole cell indices C0,R0,C1,R1");
    }
  }
  return CellWindow{static_cast<int>(v[0]), static_cast<int>(v[1]), static_cast<int>(v[2]),
                    static_cast<int>(v[3])};
}

}  // namespace

StatusOr<CellWindow> WindowFromMetres(const MetreBox& box, const MapMetadata& meta, int width,
                                      int height) {
  if (!(box.x0 <= box.x1 && box.y0 <= box.y1)) {
    return InvalidArgumentError("--window " + BoxText(box) + ": X0 must not exceed X1, nor Y0 Y1");
  }
  Grid frame;  // only its metadata: the map's cell <-> metre transform
  frame.meta = meta;
  double min_col = 0, max_col = 0, min_row = 0, max_row = 0;
  bool first = true;
  for (double x : {box.x0, box.x1}) {
    for (double y : {box.y0, box.y1}) {
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
  auto clamp = [&](double v) { return std::clamp(v, -limit, limit); };
  CellWindow w;
  w.col0 = static_cast<int>(std::ceil(clamp(min_col - kEdgeSlackCells)));
  w.col1 = static_cast<int>(std::floor(clamp(max_col + kEdgeSlackCells))) + 1;
  w.row0 = static_cast<int>(std::ceil(clamp(min_row - kEdgeSlackCells)));
  w.row1 = static_cast<int>(std::floor(clamp(max_row + kEdgeSlackCells))) + 1;
  if (w.col0 >= w.col1 || w.row0 >= w.row1) {
    return InvalidArgumentError("--window " + BoxText(box) + " holds no cell centre");
  }
  if (w.col0 < 0 || w.row0 < 0 || w.col1 > width || w.row1 > height) {
    return InvalidArgumentError("--window " + BoxText(box) + " covers " + WindowText(w) +
                                ", past the map's border: " + ExtentText(meta, width, height));
  }
  return w;
}

StatusOr<CellIndex> RoomCellFromArgs(const ParsedArgs& args, const LmapHeader& header,
                                     const std::string& lmap_path) {
  LINEMAP_ASSIGN_OR_RETURN(std::vector<double> v, args.GetDoubleList("--room-at", 2));
  if (!std::isfinite(v[0]) || !std::isfinite(v[1])) {
    return InvalidArgumentError("--room-at takes finite metres X,Y");
  }
  const std::optional<CellIndex> cell =
      CellHoldingPoint(header.meta, header.width, header.height, v[0], v[1]);
  if (!cell) {
    char text[160];
    std::snprintf(text, sizeof(text), "--room-at %g,%g m lies outside the map's %d x %d cells",
                  v[0], v[1], header.width, header.height);
    return InvalidArgumentError(std::string(text) + " ('" + lmap_path + "')");
  }
  return *cell;
}

StatusOr<std::optional<CellWindow>> WindowFromArgs(const ParsedArgs& args,
                                                   const std::string& lmap_path,
                                                   const DecodeLimits& limits) {
  const bool metres = args.Get("--window").has_value();
  const bool cells = args.Get("--window-cells").has_value();
  const bool room = args.Get("--room-at").has_value();
  if (metres + cells + room > 1) {
    return InvalidArgumentError("give one of --window, --window-cells and --room-at");
  }
  if (cells) {
    LINEMAP_ASSIGN_OR_RETURN(std::vector<double> v, args.GetDoubleList("--window-cells", 4));
    LINEMAP_ASSIGN_OR_RETURN(CellWindow w, WindowFromCellList(v));
    return std::optional<CellWindow>(w);
  }
  if (!metres) return std::optional<CellWindow>();
  LINEMAP_ASSIGN_OR_RETURN(std::vector<double> v, args.GetDoubleList("--window", 4));
  for (double x : v) {
    if (!std::isfinite(x)) return InvalidArgumentError("--window takes finite metres X0,Y0,X1,Y1");
  }
  LINEMAP_ASSIGN_OR_RETURN(LmapHeader file, LoadLmapHeader(lmap_path, limits));
  StatusOr<CellWindow> w =
      WindowFromMetres(MetreBox{v[0], v[1], v[2], v[3]}, file.meta, file.width, file.height);
  if (!w.ok()) return w.status().WithContext("'" + lmap_path + "'");
  return std::optional<CellWindow>(*w);
}

}  // namespace linemap::cli
