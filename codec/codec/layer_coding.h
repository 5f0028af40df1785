// The bodies of the 2.0 vector-layer chunks WALL, ROOM and FURN
// (spec/format.md sections 5.2-5.4): a varint count, then one range-coded
// stream with adaptive integer models (int_coding.h).
#ifndef LINEMAP_CODEC_CODEC_LAYER_CODING_H_
#define LINEMAP_CODEC_CODEC_LAYER_CODING_H_

#include <cstdint>
#include <vector>

#include "linemap/codec.h"
#include "linemap/status.h"
#include "linemap/vector_layers.h"

namespace linemap {

// Walls must be canonical (CanonicalizeWalls): inside the grid, at least two
// points each, no zero-length step; any order (CanonicalizeWalls picks the
// cheap one).
std::vector<std::uint8_t> EncodeWalls(const std::vector<WallPolyline>& walls);
// Total points above limits.max_segments (plus one per polyline) is
// resource exhausted; points outside the width x height grid are corrupt.
StatusOr<std::vector<WallPolyline>> DecodeWalls(const std::vector<std::uint8_t>& body, int width,
                                                int height, const DecodeLimits& limits);

// Drops zero-length steps and polylines left with fewer than two points,
// then orders and orients the rest for coding (OrderWallsForCoding).
void CanonicalizeWalls(std::vector<WallPolyline>* walls);

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

#endif  // LINEMAP_CODEC_CODEC_LAYER_CODING_H_
