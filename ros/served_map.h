// The map lmap_server publishes: a whole .lmap / map YAML / image, or the
// part of it inside a window given in map-frame metres.
#ifndef LINEMAP_ROS_SERVED_MAP_H_
#define LINEMAP_ROS_SERVED_MAP_H_

#include <optional>
#include <string>

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
// with x0 < x1 and y0 < y1.
StatusOr<Window> ParseWindow(const std::string& text);
// Checks four numbers the same way (the ~window parameter given as a list).
StatusOr<Window> WindowFromValues(const double* values, int count);

// The cells of `grid` whose squares overlap the window's interior, as a grid
// of their own whose origin is the lower-left corner of its first cell (the
// yaw is kept; for a rotated map the window's bounding box in cells is
// taken). Fails (invalid argument) when those cells reach past the map's
// border (a window whose edges lie on the border does not), naming the
// window and the map's extent, and when no cell overlaps.
StatusOr<Grid> CropToWindow(const Grid& grid, const Window& window);

// Loads `path` (.lmap, map YAML or bare PGM/PNG) and, with a window, keeps
// only the window's cells (the same cells as CropToWindow, refused as it
// refuses them). A 2.0 .lmap file decodes only the tiles the window meets
// (LoadLmapRegion); a map image is loaded whole and cropped.
StatusOr<Grid> LoadServedMap(const std::string& path, const std::optional<Window>& window);

}  // namespace linemap::ros_bridge

#endif  // LINEMAP_ROS_SERVED_MAP_H_
