// The vector layers of an .lmap file, read without decoding the raster:
// what a viewer, a planner or a GIS takes from the file.
//
// Geometry is on the integer cell lattice (the centre of cell (col, row) is
// the point (col, row), row 0 at the origin); ToWorld() gives map-frame
// metres as Grid::CellToWorld does.
#ifndef LINEMAP_LMAP_VECTORS_H_
#define LINEMAP_LMAP_VECTORS_H_

#include <cstdint>
#include <string>
#include <vector>

#include "linemap/cells.h"
#include "linemap/codec.h"
#include "linemap/grid.h"
#include "linemap/status.h"

namespace linemap {

// A wall as a polyline through lattice points: consecutive points are the
// ends of one straight segment; a closed wall repeats its first point last.
struct WallPolyline {
  std::vector<CellIndex> points;
};

enum class RoomKind : std::uint8_t { kUnspecified = 0, kRoom = 1, kCorridor = 2 };
const char* RoomKindName(RoomKind kind);

// One room: a closed 8-connected chain of border cells (each cell 8-adjacent
// to the next, the last to the first) enclosing the room's free space.
struct RoomOutline {
  std::uint32_t id = 0;
  RoomKind kind = RoomKind::kUnspecified;
  std::vector<CellIndex> chain;
};

// One piece of furniture: its closed outline chain (8-connected) and, when
// the file stores them, its exact cells.
struct FurnitureObject {
  std::uint32_t id = 0;
  std::int32_t room_id = -1;  // the room it stands in, -1 when none is stored
  std::vector<CellIndex> outline;
  std::vector<CellIndex> cells;
};

struct LmapVectors {
  int major = 0;
  int minor = 0;
  int width = 0;   // cells
  int height = 0;  // cells
  MapMetadata meta;
  std::vector<WallPolyline> walls;
  std::vector<RoomOutline> rooms;
  std::vector<FurnitureObject> furniture;

  // Map-frame metres of a lattice point.
  void ToWorld(const CellIndex& p, double* x, double* y) const;
};

StatusOr<LmapVectors> DecodeLmapVectors(const std::vector<std::uint8_t>& bytes,
                                        const DecodeLimits& limits = {});
StatusOr<LmapVectors> LoadLmapVectors(const std::string& path, const DecodeLimits& limits = {});

}  // namespace linemap

#endif  // LINEMAP_LMAP_VECTORS_H_
