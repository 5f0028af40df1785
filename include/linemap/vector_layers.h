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

// One room: its border as a closed polygon through lattice points (the
// closing edge from the last vertex back to the first is implied), and the
// same border as a closed 8-connected chain of cells (each cell 8-adjacent
// to the next, the last to the first): the cells of the polygon's edges
// (ChainOfPolygon), enclosing the room's free space.
struct RoomOutline {
  std::uint32_t id = 0;
  RoomKind kind = RoomKind::kUnspecified;
  std::vector<CellIndex> polygon;
  std::vector<CellIndex> chain;
  bool operator==(const RoomOutline&) const = default;
};

// One piece of furniture: its outline as a closed polygon and as the
// closed 8-connected chain of that polygon's cells, as for rooms. The exact
// cells are the occupied cells of the decoded grid that the outline
// encloses.
struct FurnitureObject {
  std::uint32_t id = 0;
  std::int32_t room_id = -1;  // id of the room it stands in, -1 when none
  std::vector<CellIndex> polygon;
  std::vector<CellIndex> outline;
  bool operator==(const FurnitureObject&) const = default;
};

// The closed chain of a closed polygon: for each edge v_i -> v_(i+1) (the
// last back to the first) the cells of its rasterisation (spec/format.md
// section 8.1) but its last, in order. One vertex is a one-cell chain.
std::vector<CellIndex> ChainOfPolygon(const std::vector<CellIndex>& polygon);

}  // namespace linemap

#endif  // LINEMAP_VECTOR_LAYERS_H_
