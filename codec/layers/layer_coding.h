// The items of the vector layers in range-coded streams (spec/format.md
// sections 5.2-5.5) and the bodies of the 2.0 layer chunks WALL, ROOM and
// FURN (a varint count, then one stream). The sections of LAYR
// (layer_sections.h) hold the same items, a stream per section.
#ifndef LINEMAP_CODEC_LAYERS_LAYER_CODING_H_
#define LINEMAP_CODEC_LAYERS_LAYER_CODING_H_

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "format/range_coder.h"
#include "linemap/codec.h"
#include "linemap/status.h"
#include "linemap/vector_layers.h"

namespace linemap {

// Where a stream's points may lie: the box [col0, col1) x [row0, row1)
// (the grid, or a LAYR section's extent), and the bound on every coded
// offset and length (max(width, height) of the grid).
struct LayerBounds {
  std::int64_t col0 = 0, row0 = 0, col1 = 0, row1 = 0;
  std::int64_t side_limit = 0;
  static LayerBounds Grid(int width, int height);
  bool Holds(std::int64_t col, std::int64_t row) const {
    return col >= col0 && row >= row0 && col < col1 && row < row1;
  }
};

// Vertices and chain cells read so far, checked against the chain limit
// over all the streams of one chunk.
struct LayerTotals {
  std::uint64_t room_vertices = 0, room_cells = 0;
  std::uint64_t object_vertices = 0, object_cells = 0;
};

// One layer's items into a stream, with fresh models and the paths' state
// starting at `origin`, heading 0 (spec 5.2).
// `count` items from `items` on.
void EncodeWallItems(RangeEncoder* enc, const WallPolyline* walls, std::size_t count,
                     CellIndex origin);
void EncodeRoomItems(RangeEncoder* enc, const RoomOutline* rooms, std::size_t count,
                     CellIndex origin);
void EncodeFurnitureItems(RangeEncoder* enc, const FurnitureObject* furniture, std::size_t count,
                          CellIndex origin);
// The points of `walls` walls that hold at most `max_segments` segments
// in all: one more per wall (a wall of k + 1 segments has k + 2 points),
// saturating at 2^64 - 1 rather than wrapping (a caller may lift the limit
// to 2^64 - 1).
std::uint64_t MaxWallPoints(std::uint64_t max_segments, std::uint64_t walls);

// `count` items appended to `out`; points outside `bounds` are corrupt.
// Walls count their points in `points` against `max_points`
// (MaxWallPoints of `max_segments`, which errors name); objects are
// numbered from `first_id`.
Status DecodeWallItems(RangeDecoder* dec, std::uint64_t count, const LayerBounds& bounds,
                       std::uint64_t max_segments, std::uint64_t max_points, std::uint64_t* points,
                       CellIndex origin, std::vector<WallPolyline>* out);
Status DecodeRoomItems(RangeDecoder* dec, std::uint64_t count, const LayerBounds& bounds,
                       const DecodeLimits& limits, LayerTotals* totals, CellIndex origin,
                       bool expand_chains, std::vector<RoomOutline>* out);
Status DecodeFurnitureItems(RangeDecoder* dec, std::uint64_t count, const LayerBounds& bounds,
                            const DecodeLimits& limits, LayerTotals* totals, CellIndex origin,
                            bool expand_chains, std::uint32_t first_id,
                            std::vector<FurnitureObject>* out);
// A stream of `size` bytes must be read to its last byte (the encoder drops
// the implied zero tail); else `what`'s data is corrupt.
Status CheckLayerStreamEnd(const RangeDecoder& dec, std::size_t size, const std::string& what);

// Walls must be canonical (CanonicalizeWalls, layer_order.h): inside the grid, at least two
// points each, no zero-length step; any order (CanonicalizeWalls picks the
// cheap one).
std::vector<std::uint8_t> EncodeWalls(const std::vector<WallPolyline>& walls);
// Total points above limits.max_segments (plus one per polyline) is
// resource exhausted; points outside the width x height grid are corrupt.
StatusOr<std::vector<WallPolyline>> DecodeWalls(const std::vector<std::uint8_t>& body, int width,
                                                int height, const DecodeLimits& limits);

// Drops zero-length steps and polylines left with fewer than two points;
// the walls keep their order and orientation (CanonicalizeWalls, in
// layer_order.h, also orders them for coding).
void DropRepeatedWallPoints(std::vector<WallPolyline>* walls);

// Rooms must have strictly increasing ids and storable chains (8-adjacent
// steps, closed, inside the grid).
std::vector<std::uint8_t> EncodeRooms(const std::vector<RoomOutline>& rooms);
// With `expand_chains` false the chains are left empty (the polygons are
// read and checked alike): what a decoder that only draws hints needs.
StatusOr<std::vector<RoomOutline>> DecodeRooms(const std::vector<std::uint8_t>& body, int width,
                                               int height, const DecodeLimits& limits,
                                               bool expand_chains = true);

// Furniture ids are their index in the list; room_id is -1 or a room's id.
std::vector<std::uint8_t> EncodeFurniture(const std::vector<FurnitureObject>& furniture);
StatusOr<std::vector<FurnitureObject>> DecodeFurniture(const std::vector<std::uint8_t>& body,
                                                       int width, int height,
                                                       const DecodeLimits& limits,
                                                       bool expand_chains = true);

// True when consecutive cells (and the last and first) are 8-neighbours, not
// equal, and all lie in the width x height grid.
bool IsStorableChain(const std::vector<CellIndex>& chain, int width, int height);

}  // namespace linemap

#endif  // LINEMAP_CODEC_LAYERS_LAYER_CODING_H_
