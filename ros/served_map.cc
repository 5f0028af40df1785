#include "ros/served_map.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <sstream>
#include <vector>

#include "linemap/codec.h"
#include "linemap/lmap_vectors.h"
#include "linemap/map_io.h"

namespace linemap::ros_bridge {

StatusOr<Window> WindowFromValues(const double* values, int count) {
  if (count != 4) {
    return InvalidArgumentError("window: expected x0,y0,x1,y1 (4 numbers), got " +
                                std::to_string(count));
  }
  for (int i = 0; i < 4; ++i) {
    if (!std::isfinite(values[i])) return InvalidArgumentError("window: numbers must be finite");
  }
  const Window window{values[0], values[1], values[2], values[3]};
  // A box of no width may hold a row of centres: CellWindowOfMetres says
  // whether it holds any, as for `linemap decode --window`.
  if (!(window.x0 <= window.x1) || !(window.y0 <= window.y1)) {
    return InvalidArgumentError("window: needs x0 <= x1 and y0 <= y1 (metres)");
  }
  return window;
}

StatusOr<Window> ParseWindow(const std::string& text) {
  // roscpp hands a `_window:=[x0, y0, x1, y1]` argument over as this text:
  // brackets and spaces are allowed around the numbers.
  std::string bare;
  for (const char c : text) {
    if (c != '[' && c != ']' && c != ' ') bare += c;
  }
  std::vector<double> values;
  std::stringstream stream(bare);
  std::string item;
  while (std::getline(stream, item, ',')) {
    char* end = nullptr;
    errno = 0;
    const double value = std::strtod(item.c_str(), &end);
    if (item.empty() || end == item.c_str() || *end != '\0' || errno != 0) {
      return InvalidArgumentError("window: '" + text + "' is not x0,y0,x1,y1 in metres");
    }
    values.push_back(value);
  }
  return WindowFromValues(values.data(), static_cast<int>(values.size()));
}

namespace {

// The cells of a window in metres on a map of `width` x `height` cells in
// `meta`'s frame: the rule of `linemap decode --window` (CellWindowOfMetres),
// so that the same window serves and writes the same cells.
StatusOr<CellWindow> WindowCells(int width, int height, const MapMetadata& meta,
                                 const Window& window) {
  return CellWindowOfMetres(meta, width, height, window.x0, window.y0, window.x1, window.y1,
                            "window");
}

}  // namespace

StatusOr<Grid> CropToWindow(const Grid& grid, const Window& window) {
  LINEMAP_ASSIGN_OR_RETURN(CellWindow w,
                           WindowCells(grid.width(), grid.height(), grid.meta, window));
  Grid out(w.col1 - w.col0, w.row1 - w.row0);
  for (int row = 0; row < out.height(); ++row) {
    for (int col = 0; col < out.width(); ++col)
      out.set(col, row, grid.at(w.col0 + col, w.row0 + row));
  }
  out.meta = grid.meta;
  // The lower-left corner of cell (col0, row0) is half a cell before its centre.
  grid.CellToWorld(w.col0 - 0.5, w.row0 - 0.5, &out.meta.origin.x, &out.meta.origin.y);
  return out;
}

namespace {

constexpr LimitParameter kLimitParameters[] = {
    {Limit::kCells, "cells", &DecodeLimits::max_cells},
    {Limit::kSegments, "wall segments per chunk", &DecodeLimits::max_segments},
    {Limit::kObjects, "rooms, and furniture objects, per file", &DecodeLimits::max_objects},
};

// `status` (a map over a limit) with the parameter of `applying` it is over
// and its value, when one is.
Status NamingTheLimit(const Status& status, const DecodeLimits& limits,
                      std::span<const LimitParameter> applying) {
  if (status.code() != StatusCode::kResourceExhausted) return status;
  // The decoder's other limits (file and chunk bytes, chain cells) are no
  // parameter: raising one of these would not lift them.
  for (const LimitParameter& limit : applying) {
    if (status.limit() == limit.limit) {
      return Status(status.code(),
                    status.message() + " (limit: ~" + limit.name() + " " +
                        std::to_string(limits.*limit.field) + ")",
                    status.limit());
    }
  }
  return status;
}

// A window of an .lmap file: only the tiles it meets are decoded (the
// header is read first, for the map's size and frame). The library's errors
// name the file; the window's are given its name here.
StatusOr<Grid> LoadLmapWindow(const std::string& path, const Window& window,
                              const DecodeLimits& limits) {
  LINEMAP_ASSIGN_OR_RETURN(LmapHeader header, LoadLmapHeader(path, limits));
  StatusOr<CellWindow> cells = WindowCells(header.width, header.height, header.meta, window);
  if (!cells.ok()) return cells.status().WithContext("'" + path + "'");
  return LoadLmapRegion(path, *cells, limits);
}

MapLoadOptions ImageLoadOptions(const DecodeLimits& limits) {
  MapLoadOptions options;
  options.max_cells = limits.max_cells;
  return options;
}

StatusOr<Grid> LoadWithin(const std::string& path, const std::optional<Window>& window,
                          const DecodeLimits& limits) {
  if (window && IsLmapPath(path)) return LoadLmapWindow(path, *window, limits);
  StatusOr<Grid> grid =
      IsLmapPath(path) ? LoadLmap(path, limits) : LoadRosMap(path, ImageLoadOptions(limits));
  if (!grid.ok()) return grid.status();
  if (!window) return grid;
  StatusOr<Grid> cropped = CropToWindow(*grid, *window);
  if (!cropped.ok()) return cropped.status().WithContext("'" + path + "'");
  return cropped;
}

// The size and frame of the map at `path`, from its header alone.
struct MapFrame {
  int width = 0;
  int height = 0;
  MapMetadata meta;
};

StatusOr<MapFrame> ReadMapFrame(const std::string& path, const DecodeLimits& limits) {
  if (IsLmapPath(path)) {
    LINEMAP_ASSIGN_OR_RETURN(LmapHeader header, LoadLmapHeader(path, limits));
    return MapFrame{header.width, header.height, header.meta};
  }
  LINEMAP_ASSIGN_OR_RETURN(std::unique_ptr<MapRowReader> reader,
                           MapRowReader::Open(path, ImageLoadOptions(limits)));
  return MapFrame{reader->width(), reader->height(), reader->meta()};
}

}  // namespace

std::span<const LimitParameter> LimitParameters() { return kLimitParameters; }

std::span<const LimitParameter> LimitParametersFor(const std::string& path) {
  return IsLmapPath(path) ? LimitParameters() : LimitParameters().first(1);
}

Status LimitRangeError(const LimitParameter& limit, const std::string& shown) {
  return InvalidArgumentError(
      "~" + std::string(limit.name()) + " must be a whole number from 1 to " +
      std::to_string(kMaxLimitValue) + " (" + limit.unit + "), not " + shown);
}

StatusOr<std::uint64_t> LimitFromNumber(const LimitParameter& limit, double value) {
  if (!(value >= 1 && value <= static_cast<double>(kMaxLimitValue)) || value != std::floor(value)) {
    // The shortest text that reads back as the value (0.1, not 0.1000...01).
    char text[64];
    for (int digits = 1; digits <= 17; ++digits) {
      std::snprintf(text, sizeof(text), "%.*g", digits, value);
      if (std::strtod(text, nullptr) == value || std::isnan(value)) break;
    }
    return LimitRangeError(limit, text);
  }
  return static_cast<std::uint64_t>(value);
}

StatusOr<std::uint64_t> ParseLimit(const LimitParameter& limit, const std::string& text) {
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || end == text.c_str() || *end != '\0' || errno != 0 ||
      !LimitFromNumber(limit, value).ok()) {
    return LimitRangeError(limit, "'" + text + "'");
  }
  return static_cast<std::uint64_t>(value);
}

StatusOr<Grid> LoadServedMap(const std::string& path, const std::optional<Window>& window,
                             const DecodeLimits& limits) {
  StatusOr<Grid> grid = LoadWithin(path, window, limits);
  if (!grid.ok()) return NamingTheLimit(grid.status(), limits, LimitParametersFor(path));
  return grid;
}

Status CheckServedMap(const std::string& path, const std::optional<Window>& window,
                      const DecodeLimits& limits) {
  const StatusOr<MapFrame> frame = ReadMapFrame(path, limits);
  if (!frame.ok()) return NamingTheLimit(frame.status(), limits, LimitParametersFor(path));
  if (!window) return Status::Ok();
  const StatusOr<CellWindow> cells = WindowCells(frame->width, frame->height, frame->meta, *window);
  return cells.ok() ? Status::Ok() : cells.status().WithContext("'" + path + "'");
}

}  // namespace linemap::ros_bridge
