// The map lmap_server publishes: a whole .lmap / map YAML / image, or the
// part of it inside a window given in map-frame metres.
#ifndef LINEMAP_ROS_SERVED_MAP_H_
#define LINEMAP_ROS_SERVED_MAP_H_

#include <cstdint>
#include <optional>
#include <span>
#include <string>

#include "linemap/codec.h"
#include "linemap/grid.h"
#include "linemap/status.h"

namespace linemap::ros_bridge {

// An axis-aligned rectangle in map-frame metres: x0 <= x1, y0 <= y1.
struct Window {
  double x0 = 0.0;
  double y0 = 0.0;
  double x1 = 0.0;
  double y1 = 0.0;
};

// Parses "x0,y0,x1,y1" (metres; also "[x0, y0, x1, y1]"). Fails on anything but four finite numbers
// with x0 <= x1 and y0 <= y1.
StatusOr<Window> ParseWindow(const std::string& text);
// Checks four numbers the same way (the ~window parameter given as a list).
StatusOr<Window> WindowFromValues(const double* values, int count);

// The cells of `grid` whose centres lie in the window, as `linemap decode
// --window` takes them (CellWindowOfMetres, linemap/codec.h), as a grid of
// their own whose origin is the lower-left corner of its first cell (the
// yaw is kept; for a rotated map the cell rectangle around the window's
// corners is taken). Fails (invalid argument) when those cells reach past
// the map's border, naming the window and the map's extent, and when the
// window holds no cell centre.
StatusOr<Grid> CropToWindow(const Grid& grid, const Window& window);

// A decode limit lmap_server takes as the private parameter ~NAME: a whole
// number from 1 to kMaxLimitValue (XmlRpc's largest int) that replaces
// DecodeLimits' field.
struct LimitParameter {
  Limit limit;       // what the library's errors over it carry (Status::limit())
  const char* unit;  // what it counts, for messages
  std::uint64_t DecodeLimits::*field;
  // "max_cells": the parameter ~max_cells, named as the library names the
  // field (LimitFieldName), as Python's DecodeLimits does.
  const char* name() const { return LimitFieldName(limit); }
};
inline constexpr std::int64_t kMaxLimitValue = 2147483647;

// ~max_cells (cells of the whole map, also of a map image), ~max_segments
// (wall segments per chunk of an .lmap file, or per band of layer sections
// read together) and ~max_objects (rooms, and
// furniture objects, per .lmap file), in that order.
std::span<const LimitParameter> LimitParameters();

// The limits that apply to the map at `path`, the first of
// LimitParameters(): all three for an .lmap file, ~max_cells for a map image.
std::span<const LimitParameter> LimitParametersFor(const std::string& path);

// A value of `limit` given as text (a `_NAME:=VALUE` argument or a string
// parameter), or as a number (an int or double parameter): a whole number
// from 1 to kMaxLimitValue, else an invalid argument naming ~NAME and that
// range.
StatusOr<std::uint64_t> ParseLimit(const LimitParameter& limit, const std::string& text);
StatusOr<std::uint64_t> LimitFromNumber(const LimitParameter& limit, double value);
// Their error for a value shown as `shown` ("'abc'", "2.5", "a list").
Status LimitRangeError(const LimitParameter& limit, const std::string& shown);

// Loads `path` (.lmap, map YAML or bare PGM/PNG) within `limits` and, with a
// window, keeps only the window's cells (the same cells as CropToWindow,
// refused as it refuses them). A 2.0 .lmap file decodes only the tiles the
// window meets (LoadLmapRegion); a map image is loaded whole and cropped.
// limits.max_cells applies to the whole map, with a window too, and to a map
// image (MapLoadOptions::max_cells); the other limits to .lmap files. A map
// over a limit is refused (resource exhausted), naming the file, and the
// parameter of LimitParametersFor(path) with its value when raising it can
// lift the refusal (not for the decoder's other limits: file and chunk
// bytes, chain cells).
StatusOr<Grid> LoadServedMap(const std::string& path, const std::optional<Window>& window,
                             const DecodeLimits& limits = {});

// What LoadServedMap(path, window, limits) checks before it decodes any
// cell, with the same errors: that the file opens, that its header (for an
// .lmap file also every chunk's CRC) is within limits.max_cells, and that the
// window lies on the map. Lets a node refuse a bad map before it knows all it
// needs to load it (the window and limits of the parameter server).
Status CheckServedMap(const std::string& path, const std::optional<Window>& window,
                      const DecodeLimits& limits = {});

}  // namespace linemap::ros_bridge

#endif  // LINEMAP_ROS_SERVED_MAP_H_
