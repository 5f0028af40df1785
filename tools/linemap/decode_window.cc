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

StatusOr<CellWindow> WindowFromCellList(const std::vector<double>& v) {
  for (double x : v) {
    // Written so that NaN fails it too.
    if (!(std::isfinite(x) && x == std::floor(x))) {
      return InvalidArgumentError("--window-cells takes whole cell indices C0,R0,C1,R1");
    }
  }
  for (double x : v) {
    if (std::abs(x) > std::numeric_limits<int>::max()) {
      char text[64];
      std::snprintf(text, sizeof(text), "%.15g", x);
      return InvalidArgumentError(std::string("--window-cells index ") + text +
                                  " is out of range (a cell index lies within +-" +
                                  std::to_string(std::numeric_limits<int>::max()) +
                                  ", and a window inside the map)");
    }
  }
  return CellWindow{static_cast<int>(v[0]), static_cast<int>(v[1]), static_cast<int>(v[2]),
                    static_cast<int>(v[3])};
}

}  // namespace

StatusOr<CellWindow> WindowFromMetres(const MetreBox& box, const MapMetadata& meta, int width,
                                      int height) {
  return CellWindowOfMetres(meta, width, height, box.x0, box.y0, box.x1, box.y1, "--window");
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
