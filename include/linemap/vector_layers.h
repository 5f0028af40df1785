// The vector layers of a 2.0 .lmap file: walls as polylines, one closed
// border chain per room, furniture outlines. All on the integer cell lattice
// (the centre of cell (col, row) is the point (col, row), row 0 at the
// origin), so every platform draws them alike.
#ifndef LINEMAP_VECTOR_LAYERS_H_
#define LINEMAP_VECTOR_LAYERS_H_

#include <cstdint>
#include <vector>

#include "linemap/cells.h"

namespace linemap {

// A wall as a polyline through lattice points: consecutive points are the
// ends of one straight segment; a closed wall repeats its first point last.
struct WallPolyline {
  std::vector<CellIndex> points;
  bool operator==(const WallPolyline&) const = default;
};

enum class RoomKind : std::uint8_t { kUnspecified = 0, kRoom = 1, kCorridor = 2 };
// "unspecified", "room" or "corridor".
const char* RoomKindName(RoomKind kind);

// One room: a closed 8-connected chain of border cells (each cell 8-adjacent
// to the next, the last to the first) enclosing the room's free space.
struct RoomOutline {
  std::uint32_t id = 0;
  RoomKind kind = RoomKind::kUnspecified;
  std::vector<CellIndex> chain;
  bool operator==(const RoomOutline&) const = default;
};

// One piece of furniture: its closed outline chain (8-connected, Moore
// tracing of its cells). The exact cells are the occupied cells of the
// decoded grid that the outline encloses.
struct FurnitureObject {
  std::uint32_t id = 0;
  std::int32_t room_id = -1;  // id of the room it stands in, -1 when none
  std::vector<CellIndex> outline;
  bool operator==(const FurnitureObject&) const = default;
};

}  // namespace linemap

#endif  // LINEMAP_VECTOR_LAYERS_H_
