// The occupancy-grid model shared by every part of linemap.
//
// Row order, stated once for the whole library: grid row 0 is the row at the
// map origin (the bottom of the map image), as in nav_msgs/OccupancyGrid.
// Image row 0 is the top of the picture, so image row = height - 1 - grid row.
// Only the ROS image reader and writer (format/ros_map.cc) convert between
// the two; everything else works in grid rows.
//
// Geometry inside the library is in cell units: the centre of cell
// (col, row) is the point (col, row); the cell covers [col-0.5, col+0.5] x
// [row-0.5, row+0.5]. Map-frame metres come from CellToWorld().
#ifndef LINEMAP_GRID_H_
#define LINEMAP_GRID_H_

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "linemap/cells.h"

namespace linemap {

// The three cell states of a trinary map. The values are stored in files
// (residual and test fixtures), so they never change.
enum class Cell : uint8_t {
  kFree = 0,
  kOccupied = 1,
  kUnknown = 2,
};

// How map_server turns pixels into cells (the YAML `mode` key).
enum class MapMode : uint8_t {
  kTrinary = 0,  // free / occupied / unknown by the two thresholds.
  kScale = 1,    // like trinary, but in-between values keep a 0..100 level.
  kRaw = 2,      // the grey value itself is the cell value (0..100).
};

const char* MapModeName(MapMode mode);
// The mode named `name` ("trinary", "scale" or "raw", as MapModeName
// spells them and map_server's YAML does); nullopt for any other text.
std::optional<MapMode> MapModeFromName(std::string_view name);

// A planar pose: x, y in metres, yaw in radians (counter-clockwise).
struct Pose2D {
  double x = 0.0;
  double y = 0.0;
  double yaw = 0.0;
  bool operator==(const Pose2D&) const = default;
};

// Defaults used when a map image has no YAML (as map_server's documentation).
inline constexpr double kDefaultResolution = 0.05;      // metres per cell
inline constexpr double kDefaultOccupiedThresh = 0.65;  // occupancy probability
inline constexpr double kDefaultFreeThresh = 0.196;     // occupancy probability

// Everything besides the cells that is needed to write the map back as the
// ROS YAML it came from.
struct MapMetadata {
  double resolution = kDefaultResolution;  // metres per cell, > 0
  Pose2D origin;                           // pose of the lower-left corner of cell (0, 0)
  MapMode mode = MapMode::kTrinary;
  bool negate = false;
  double occupied_thresh = kDefaultOccupiedThresh;
  double free_thresh = kDefaultFreeThresh;
  bool operator==(const MapMetadata&) const = default;
};

struct CellCounts {
  std::size_t free = 0;
  std::size_t occupied = 0;
  std::size_t unknown = 0;
};

class Grid {
 public:
  Grid() = default;
  // A width x height grid filled with `fill`. Dimensions must be >= 0.
  Grid(int width, int height, Cell fill = Cell::kUnknown);

  int width() const { return width_; }
  int height() const { return height_; }
  std::size_t size() const { return cells_.size(); }
  bool empty() const { return cells_.empty(); }

  bool Contains(int col, int row) const {
    return col >= 0 && row >= 0 && col < width_ && row < height_;
  }
  std::size_t Index(int col, int row) const {
    return static_cast<std::size_t>(row) * static_cast<std::size_t>(width_) +
           static_cast<std::size_t>(col);
  }
  Cell at(int col, int row) const { return cells_[Index(col, row)]; }
  void set(int col, int row, Cell value) { cells_[Index(col, row)] = value; }

  // Cells in grid-row order: row 0 (at the origin) first.
  const std::vector<Cell>& cells() const { return cells_; }
  std::vector<Cell>& mutable_cells() { return cells_; }

  CellCounts Count() const;

  MapMetadata meta;

  // Map-frame metres of a point in cell units (cell centre = integer point),
  // applying the origin's translation and yaw as map_server defines it.
  void CellToWorld(double col, double row, double* x, double* y) const;
  // The inverse of CellToWorld (result in cell units, not rounded).
  void WorldToCell(double x, double y, double* col, double* row) const;
  // The cell holding the map-frame point (x, y): CellHoldingPoint below.
  std::optional<CellIndex> CellHolding(double x, double y) const;

  bool operator==(const Grid& other) const = default;

 private:
  int width_ = 0;
  int height_ = 0;
  std::vector<Cell> cells_;
};

// The cell of a width x height map in `meta`'s frame whose square [c - 0.5,
// c + 0.5) x [r - 0.5, r + 0.5) (cell units, centres on whole numbers)
// holds the map-frame point (x, y) in metres: a point on a cell's lower or
// left edge is in that cell, one on its upper or right edge in the next.
// "On" an edge as typed in decimal: -6.9 m from an origin at -7 m at 0.05
// m/cell is 1.4999999999999929 cells in doubles, and is taken as the left
// edge of column 2, within the slack (1e-9 cell, more at large coordinates)
// by which CellWindowOfMetres takes a centre on a window's edge.
// nullopt off the map, and for a point that is not finite.
std::optional<CellIndex> CellHoldingPoint(const MapMetadata& meta, int width, int height, double x,
                                          double y);

// The box in map-frame metres around the outer corners of a width x
// height map's cells in `meta`'s frame (a yaw turns the rectangle, so the
// box then also holds points off the map).
struct MetreBounds {
  double min_x = 0, min_y = 0, max_x = 0, max_y = 0;
};
MetreBounds MapBoundsMetres(const MapMetadata& meta, int width, int height);

}  // namespace linemap

#endif  // LINEMAP_GRID_H_
