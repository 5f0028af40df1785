// WALL, ROOM and FURN bodies (spec/format.md sections 5.2-5.4).
#include "codec/layers/layer_coding.h"

#include <algorithm>
#include <cstdlib>
#include <limits>
#include <memory>
#include <string>
#include <tuple>

#include "codec/layers/int_coding.h"
#include "codec/layers/raster.h"
#include "format/byte_io.h"
#include "format/range_coder.h"

namespace linemap {
namespace {

// Axis directions of a wall step: +col, +row, -col, -row.
constexpr int kAxisCol[4] = {1, 0, -1, 0};
constexpr int kAxisRow[4] = {0, 1, 0, -1};
bool EightAdjacent(CellIndex p, CellIndex q) {
  const int dc = std::abs(p.col - q.col), dr = std::abs(p.row - q.row);
  return dc <= 1 && dr <= 1 && dc + dr > 0;
}

bool Inside(CellIndex p, int width, int height) {
  return p.col >= 0 && p.row >= 0 && p.col < width && p.row < height;
}

// ---- paths: walls and polygons ----

// The encoder and the decoder run the same code (CodePath) over one of
// these: a writer codes the value it is given, a reader replaces it with the
// value it reads and returns false when the stream is corrupt. One body of
// code keeps the two sides from drifting apart.
class PathWriter {
 public:
  explicit PathWriter(RangeEncoder* enc) : enc_(enc) {}
  static constexpr bool kReading = false;
  bool Bit(BitModel* m, int* bit) {
    enc_->Encode(m, *bit);
    return true;
  }
  bool UInt(UIntModel* m, std::uint64_t* v) {
    EncodeUInt(enc_, m, *v);
    return true;
  }
  bool SInt(UIntModel* m, std::int64_t* v) {
    EncodeSInt(enc_, m, *v);
    return true;
  }
  bool Turn(SymbolModel<2>* m, unsigned* symbol) {
    EncodeSymbol<2>(enc_, m, *symbol);
    return true;
  }

 private:
  RangeEncoder* enc_;
};

class PathReader {
 public:
  explicit PathReader(RangeDecoder* dec) : dec_(dec) {}
  static constexpr bool kReading = true;
  bool Bit(BitModel* m, int* bit) {
    *bit = dec_->Decode(m);
    return true;
  }
  bool UInt(UIntModel* m, std::uint64_t* v) { return DecodeUInt(dec_, m, v); }
  bool SInt(UIntModel* m, std::int64_t* v) { return DecodeSInt(dec_, m, v); }
  bool Turn(SymbolModel<2>* m, unsigned* symbol) {
    *symbol = DecodeSymbol<2>(dec_, m);
    return true;
  }

 private:
  RangeDecoder* dec_;
};

// Length classes of a step's length along its main axis: 1, 2-3, 4-7,
// 8-15, 16-31, 32 and more.
constexpr int kLengthClasses = 6;
int LengthClass(std::uint64_t len) {
  int c = 0;
  while (c + 1 < kLengthClasses && (len >> (c + 1)) != 0) ++c;
  return c;
}

// Magnitude classes of a start's forward offset: 0, 1, 2-3, 4 and more.
int OffsetClass(std::int64_t v) {
  const std::uint64_t a = static_cast<std::uint64_t>(v < 0 ? -v : v);
  return a == 0 ? 0 : a == 1 ? 1 : a <= 3 ? 2 : 3;
}

// A path of lattice points: its number of points (less `min_points`), its
// start as an offset from the previous path's last point, then each step
// (spec/format.md section 5.2). Offsets and steps are coded in the frame of
// the heading (the main direction of the last step coded, carried from path
// to path): indoor walls run along a few directions, so the next piece
// mostly starts ahead of the last one and runs on or turns by a right angle.
struct PathModels {
  UIntModel points;
  UIntModel ahead;                  // start offset along the heading
  UIntModel side[4];                // across it, by OffsetClass(ahead)
  SymbolModel<2> turn[2][5];        // [later step][previous turn, 4 none]
  UIntModel length[2][2];           // length - 1: [later step][turned]
  UIntModel minor[kLengthClasses];  // |offset across the main axis|
  BitModel minor_sign[3][3];        // [turn: on, left or back, right][previous sign + 1]
};

struct PathState {
  CellIndex prev{0, 0};  // the last point coded
  int heading = 0;       // axis direction of the last step's main axis
};

// Codes one path (`*path` is read when writing, filled when reading);
// `points` counts the points against `max_points`. Returns false when the
// stream is corrupt, sets *exhausted when the points exceed the limit.
template <class IO>
bool CodePath(IO* io, PathModels* m, const LayerBounds& bounds, std::size_t min_points,
              std::uint64_t max_points, std::uint64_t* points, PathState* state,
              std::vector<CellIndex>* path, bool* exhausted) {
  const std::int64_t side_limit = bounds.side_limit;
  std::uint64_t k = IO::kReading ? 0 : path->size() - min_points;
  if (!io->UInt(&m->points, &k)) return false;
  *points += k + min_points;
  if (k + min_points > max_points || *points > max_points) {
    *exhausted = true;
    return false;
  }
  const int h = state->heading;
  std::int64_t ahead = 0, side = 0;
  if constexpr (!IO::kReading) {
    const std::int64_t dc = (*path)[0].col - state->prev.col;
    const std::int64_t dr = (*path)[0].row - state->prev.row;
    ahead = dc * kAxisCol[h] + dr * kAxisRow[h];
    side = dc * kAxisCol[(h + 1) & 3] + dr * kAxisRow[(h + 1) & 3];
  }
  if (!io->SInt(&m->ahead, &ahead) || std::llabs(ahead) >= side_limit ||
      !io->SInt(&m->side[OffsetClass(ahead)], &side) || std::llabs(side) >= side_limit) {
    return false;
  }
  // In 64 bits: the offsets are below max(width, height), not the sums.
  const std::int64_t col = state->prev.col + ahead * kAxisCol[h] + side * kAxisCol[(h + 1) & 3];
  const std::int64_t row = state->prev.row + ahead * kAxisRow[h] + side * kAxisRow[(h + 1) & 3];
  if (!bounds.Holds(col, row)) return false;
  CellIndex p{static_cast<int>(col), static_cast<int>(row)};
  if constexpr (IO::kReading) {
    // Room for the points at once rather than by doubling (a wall that
    // follows a slanted wall's pixel steps has dozens): capped, as a
    // corrupt count may pass the points limit's check.
    constexpr std::uint64_t kMaxReserved = 4096;
    path->clear();
    path->reserve(static_cast<std::size_t>(std::min(k + min_points, kMaxReserved)));
    path->push_back(p);
  }
  int heading = h;
  int later = 0;
  unsigned last_turn = 4;
  int last_sign = 0;
  for (std::uint64_t i = 1; i < k + min_points; ++i) {
    // The step as a main axis direction a, a length along it and an offset
    // across it (towards direction a + 1); the main axis is the one the
    // step moves along the most, ties to the heading's axis.
    unsigned turn = 0;
    std::uint64_t len = 0, minor_abs = 0;
    int sign = 0;
    if constexpr (!IO::kReading) {
      const std::int64_t dc = (*path)[i].col - (*path)[i - 1].col;
      const std::int64_t dr = (*path)[i].row - (*path)[i - 1].row;
      const bool heading_is_col = (heading & 1) == 0;
      const bool col_main =
          std::llabs(dc) > std::llabs(dr) || (std::llabs(dc) == std::llabs(dr) && heading_is_col);
      const int a = col_main ? (dc > 0 ? 0 : 2) : (dr > 0 ? 1 : 3);
      turn = static_cast<unsigned>((a - heading) & 3);
      len = static_cast<std::uint64_t>(col_main ? std::llabs(dc) : std::llabs(dr)) - 1;
      const std::int64_t across = dc * kAxisCol[(a + 1) & 3] + dr * kAxisRow[(a + 1) & 3];
      minor_abs = static_cast<std::uint64_t>(std::llabs(across));
      sign = across > 0 ? 1 : 0;
    }
    if (!io->Turn(&m->turn[later][last_turn], &turn)) return false;
    const int turned = turn == 0 ? 0 : 1;
    if (!io->UInt(&m->length[later][turned], &len) ||
        len >= static_cast<std::uint64_t>(side_limit)) {
      return false;
    }
    if (!io->UInt(&m->minor[LengthClass(len + 1)], &minor_abs) || minor_abs > len + 1) {
      return false;
    }
    if (minor_abs != 0) {
      const int turn_class = turn == 1 ? 1 : turn == 3 ? 2 : 0;
      if (!io->Bit(&m->minor_sign[turn_class][last_sign + 1], &sign)) return false;
    }
    const int a = static_cast<int>((heading + static_cast<int>(turn)) & 3);
    const std::int64_t across =
        sign == 1 ? static_cast<std::int64_t>(minor_abs) : -static_cast<std::int64_t>(minor_abs);
    const std::int64_t along = static_cast<std::int64_t>(len + 1);
    const std::int64_t c = p.col + along * kAxisCol[a] + across * kAxisCol[(a + 1) & 3];
    const std::int64_t r = p.row + along * kAxisRow[a] + across * kAxisRow[(a + 1) & 3];
    if (!bounds.Holds(c, r)) return false;
    p = {static_cast<int>(c), static_cast<int>(r)};
    if constexpr (IO::kReading) path->push_back(p);
    heading = a;
    later = 1;
    last_turn = turn;
    last_sign = minor_abs == 0 ? 0 : sign == 1 ? 1 : -1;
  }
  state->prev = p;
  state->heading = heading;
  return true;
}

void EncodePath(RangeEncoder* enc, PathModels* m, const std::vector<CellIndex>& p,
                std::size_t min_points, PathState* state) {
  PathWriter io(enc);
  std::uint64_t points = 0;
  bool exhausted = false;
  std::vector<CellIndex> copy = p;
  const LayerBounds any{std::numeric_limits<int>::min(), std::numeric_limits<int>::min(),
                        std::numeric_limits<int>::max(), std::numeric_limits<int>::max(),
                        std::numeric_limits<std::int64_t>::max()};
  CodePath(&io, m, any, min_points, std::numeric_limits<std::uint64_t>::max(), &points, state,
           &copy, &exhausted);
}

// Decodes one path; `points` counts its points against `max_points`, and
// `over_limit()` is the error when they exceed it (the caller's limit: wall
// segments, or a polygon's chain cells).
template <class OverLimit>
StatusOr<std::vector<CellIndex>> DecodePath(RangeDecoder* dec, PathModels* m,
                                            const LayerBounds& bounds, std::size_t min_points,
                                            std::uint64_t max_points, std::uint64_t* points,
                                            PathState* state, OverLimit over_limit) {
  PathReader io(dec);
  std::vector<CellIndex> path;
  bool exhausted = false;
  if (!CodePath(&io, m, bounds, min_points, max_points, points, state, &path, &exhausted)) {
    if (exhausted) return over_limit();
    return CorruptError("point out of the grid (or its section's box) or malformed");
  }
  return path;
}

// A closed polygon's vertices; the chain is expanded from them, its cells
// counted against the chain limit before it is allocated.
StatusOr<std::vector<CellIndex>> DecodePolygon(RangeDecoder* dec, PathModels* m,
                                               const LayerBounds& bounds,
                                               const DecodeLimits& limits, std::uint64_t* vertices,
                                               std::uint64_t* cells, PathState* prev) {
  StatusOr<std::vector<CellIndex>> polygon =
      DecodePath(dec, m, bounds, 1, limits.max_chain_length, vertices, prev, [&limits] {
        return OverLimitError(Limit::kChainLength, "polygon vertices exceed the chain limit of " +
                                                       std::to_string(limits.max_chain_length));
      });
  if (!polygon.ok()) return polygon.status();
  // The chain has one cell per step of each edge (max(|dcol|, |drow|)), and
  // one for a single vertex.
  std::uint64_t length = polygon->size() == 1 ? 1 : 0;
  for (std::size_t i = 0; i < polygon->size() && polygon->size() > 1; ++i) {
    const CellIndex a = (*polygon)[i], b = (*polygon)[(i + 1) % polygon->size()];
    length +=
        static_cast<std::uint64_t>(std::max(std::abs(b.col - a.col), std::abs(b.row - a.row)));
  }
  *cells += length;
  if (length > limits.max_chain_length || *cells > limits.max_chain_length) {
    return OverLimitError(Limit::kChainLength, "chain cells exceed the chain limit of " +
                                                   std::to_string(limits.max_chain_length));
  }
  return polygon;
}

struct RoomModels {
  UIntModel id_gap;  // id - previous id - 1 (previous -1 before the first)
  SymbolModel<2> kind;
  PathModels polygon;
};

struct FurnitureModels {
  BitModel same_room;  // 1: the previous object's room
  UIntModel room;      // room id + 1 (0: none)
  PathModels polygon;
};

PathState StartState(CellIndex origin) {
  PathState state;
  state.prev = origin;
  return state;
}

// The body of a 2.0 layer chunk: its count, then the items' stream coded
// from (0, 0) by `encode`.
template <class Item>
std::vector<std::uint8_t> ChunkBody(const std::vector<Item>& items,
                                    void (*encode)(RangeEncoder*, const Item*, std::size_t,
                                                   CellIndex)) {
  RangeEncoder enc;
  encode(&enc, items.data(), items.size(), {0, 0});
  enc.Finish();
  ByteWriter out;
  out.PutVarint(items.size());
  out.PutBytes(enc.bytes());
  return std::move(out.mutable_bytes());
}

// Reads a 2.0 layer chunk's count (above `limit`: resource exhausted) and
// opens its stream.
struct ChunkStream {
  std::uint64_t count = 0;
  std::size_t size = 0;
  const std::uint8_t* data = nullptr;
};
StatusOr<ChunkStream> OpenChunkStream(const std::vector<std::uint8_t>& body, const char* count_name,
                                      const char* items, std::uint64_t limit, Limit which,
                                      const char* limit_name) {
  ByteCursor cursor(body);
  ChunkStream stream;
  LINEMAP_ASSIGN_OR_RETURN(stream.count, cursor.ReadVarint(count_name));
  if (stream.count > limit) {
    return OverLimitError(which, std::to_string(stream.count) + " " + items + " exceed the " +
                                     limit_name + " limit of " + std::to_string(limit));
  }
  stream.size = cursor.remaining();
  stream.data = body.data() + cursor.position();
  return stream;
}

// The items of a 2.0 layer chunk: its count (checked against `limit`),
// then `decode(&decoder, count, &items)` over its stream, which must end
// where the chunk does.
template <class Item, class DecodeItems>
StatusOr<std::vector<Item>> DecodeChunkBody(const std::vector<std::uint8_t>& body,
                                            const char* chunk, const char* count_name,
                                            const char* items, std::uint64_t limit, Limit which,
                                            const char* limit_name, DecodeItems decode) {
  LINEMAP_ASSIGN_OR_RETURN(ChunkStream stream,
                           OpenChunkStream(body, count_name, items, limit, which, limit_name));
  RangeDecoder dec(stream.data, stream.size);
  std::vector<Item> out;
  LINEMAP_RETURN_IF_ERROR(decode(&dec, stream.count, &out));
  LINEMAP_RETURN_IF_ERROR(CheckLayerStreamEnd(dec, stream.size, chunk));
  return out;
}

}  // namespace

LayerBounds LayerBounds::Grid(int width, int height) {
  return {0, 0, width, height, std::max(width, height)};
}

Status CheckLayerStreamEnd(const RangeDecoder& dec, std::size_t size, const std::string& what) {
  if (!dec.valid_start() || dec.consumed() != size) {
    return CorruptError(what + " range-coded data is malformed or truncated");
  }
  return Status::Ok();
}

void DropRepeatedWallPoints(std::vector<WallPolyline>* walls) {
  std::vector<WallPolyline> kept;
  for (WallPolyline& wall : *walls) {
    std::vector<CellIndex> points;
    for (const CellIndex& q : wall.points) {
      if (points.empty() || !(points.back() == q)) points.push_back(q);
    }
    if (points.size() >= 2) kept.push_back({std::move(points)});
  }
  *walls = std::move(kept);
}

void EncodeWallItems(RangeEncoder* enc, const WallPolyline* walls, std::size_t count,
                     CellIndex origin) {
  auto m = std::make_unique<PathModels>();
  PathState state = StartState(origin);
  for (std::size_t i = 0; i < count; ++i) EncodePath(enc, m.get(), walls[i].points, 2, &state);
}

std::uint64_t MaxWallPoints(std::uint64_t max_segments, std::uint64_t walls) {
  return max_segments > UINT64_MAX - walls ? UINT64_MAX : max_segments + walls;
}

Status DecodeWallItems(RangeDecoder* dec, std::uint64_t count, const LayerBounds& bounds,
                       std::uint64_t max_segments, std::uint64_t max_points, std::uint64_t* points,
                       CellIndex origin, std::vector<WallPolyline>* out) {
  auto m = std::make_unique<PathModels>();
  PathState state = StartState(origin);
  for (std::uint64_t w = 0; w < count; ++w) {
    StatusOr<std::vector<CellIndex>> path =
        DecodePath(dec, m.get(), bounds, 2, max_points, points, &state, [max_segments] {
          return OverLimitError(Limit::kSegments, "wall segments exceed the segment limit of " +
                                                      std::to_string(max_segments));
        });
    if (!path.ok()) return path.status();
    out->push_back({std::move(*path)});
  }
  return Status::Ok();
}

void EncodeRoomItems(RangeEncoder* enc, const RoomOutline* rooms, std::size_t count,
                     CellIndex origin) {
  auto m = std::make_unique<RoomModels>();
  std::int64_t prev_id = -1;
  PathState state = StartState(origin);
  for (std::size_t i = 0; i < count; ++i) {
    const RoomOutline& room = rooms[i];
    EncodeUInt(enc, &m->id_gap, static_cast<std::uint64_t>(room.id - prev_id - 1));
    prev_id = room.id;
    EncodeSymbol<2>(enc, &m->kind, static_cast<unsigned>(room.kind));
    EncodePath(enc, &m->polygon, room.polygon, 1, &state);
  }
}

Status DecodeRoomItems(RangeDecoder* dec, std::uint64_t count, const LayerBounds& bounds,
                       const DecodeLimits& limits, LayerTotals* totals, CellIndex origin,
                       bool expand_chains, std::vector<RoomOutline>* out) {
  auto m = std::make_unique<RoomModels>();
  std::int64_t prev_id = -1;
  PathState state = StartState(origin);
  for (std::uint64_t i = 0; i < count; ++i) {
    std::uint64_t gap = 0;
    if (!DecodeUInt(dec, &m->id_gap, &gap) || gap > 0xFFFFFFFFu ||
        prev_id + 1 + static_cast<std::int64_t>(gap) > 0xFFFFFFFF) {
      return CorruptError("room id above 2^32 - 1");
    }
    RoomOutline room;
    room.id = static_cast<std::uint32_t>(prev_id + 1 + static_cast<std::int64_t>(gap));
    prev_id = room.id;
    const unsigned kind = DecodeSymbol<2>(dec, &m->kind);
    if (kind > 2) return CorruptError("room kind 3 is reserved");
    room.kind = static_cast<RoomKind>(kind);
    LINEMAP_ASSIGN_OR_RETURN(room.polygon,
                             DecodePolygon(dec, &m->polygon, bounds, limits, &totals->room_vertices,
                                           &totals->room_cells, &state));
    if (expand_chains) room.chain = ChainOfPolygon(room.polygon);
    out->push_back(std::move(room));
  }
  return Status::Ok();
}

void EncodeFurnitureItems(RangeEncoder* enc, const FurnitureObject* furniture, std::size_t count,
                          CellIndex origin) {
  auto m = std::make_unique<FurnitureModels>();
  PathState state = StartState(origin);
  std::uint64_t prev_room = 0;  // room id + 1 of the previous object
  for (std::size_t i = 0; i < count; ++i) {
    const FurnitureObject& object = furniture[i];
    const std::uint64_t room = static_cast<std::uint64_t>(std::int64_t{object.room_id} + 1);
    enc->Encode(&m->same_room, room == prev_room ? 1 : 0);
    if (room != prev_room) EncodeUInt(enc, &m->room, room);
    prev_room = room;
    EncodePath(enc, &m->polygon, object.polygon, 1, &state);
  }
}

Status DecodeFurnitureItems(RangeDecoder* dec, std::uint64_t count, const LayerBounds& bounds,
                            const DecodeLimits& limits, LayerTotals* totals, CellIndex origin,
                            bool expand_chains, std::uint32_t first_id,
                            std::vector<FurnitureObject>* out) {
  auto m = std::make_unique<FurnitureModels>();
  PathState state = StartState(origin);
  std::uint64_t prev_room = 0;
  for (std::uint64_t i = 0; i < count; ++i) {
    std::uint64_t room = 0;
    if (dec->Decode(&m->same_room) == 1) {
      room = prev_room;
    } else if (!DecodeUInt(dec, &m->room, &room) || room > 0x80000000u) {
      return CorruptError("furniture room id above 2^31 - 1");
    }
    prev_room = room;
    FurnitureObject object;
    object.id = static_cast<std::uint32_t>(first_id + i);
    object.room_id = static_cast<std::int32_t>(static_cast<std::int64_t>(room) - 1);
    LINEMAP_ASSIGN_OR_RETURN(
        object.polygon, DecodePolygon(dec, &m->polygon, bounds, limits, &totals->object_vertices,
                                      &totals->object_cells, &state));
    if (expand_chains) object.outline = ChainOfPolygon(object.polygon);
    out->push_back(std::move(object));
  }
  return Status::Ok();
}

std::vector<std::uint8_t> EncodeWalls(const std::vector<WallPolyline>& walls) {
  return ChunkBody(walls, EncodeWallItems);
}

StatusOr<std::vector<WallPolyline>> DecodeWalls(const std::vector<std::uint8_t>& body, int width,
                                                int height, const DecodeLimits& limits) {
  return DecodeChunkBody<WallPolyline>(
      body, "WALL", "wall count", "walls", limits.max_segments, Limit::kSegments, "segment",
      [&](RangeDecoder* dec, std::uint64_t count, std::vector<WallPolyline>* walls) {
        std::uint64_t points = 0;
        return DecodeWallItems(dec, count, LayerBounds::Grid(width, height), limits.max_segments,
                               MaxWallPoints(limits.max_segments, count), &points, {0, 0}, walls);
      });
}

bool IsStorableChain(const std::vector<CellIndex>& chain, int width, int height) {
  if (chain.empty()) return false;
  for (std::size_t i = 0; i < chain.size(); ++i) {
    if (!Inside(chain[i], width, height)) return false;
    if (i + 1 < chain.size() && !EightAdjacent(chain[i], chain[i + 1])) return false;
  }
  const int dc = std::abs(chain.back().col - chain.front().col);
  const int dr = std::abs(chain.back().row - chain.front().row);
  return dc <= 1 && dr <= 1;
}

std::vector<std::uint8_t> EncodeRooms(const std::vector<RoomOutline>& rooms) {
  return ChunkBody(rooms, EncodeRoomItems);
}

StatusOr<std::vector<RoomOutline>> DecodeRooms(const std::vector<std::uint8_t>& body, int width,
                                               int height, const DecodeLimits& limits,
                                               bool expand_chains) {
  return DecodeChunkBody<RoomOutline>(
      body, "ROOM", "room count", "rooms", limits.max_objects, Limit::kObjects, "object",
      [&](RangeDecoder* dec, std::uint64_t count, std::vector<RoomOutline>* rooms) {
        LayerTotals totals;
        return DecodeRoomItems(dec, count, LayerBounds::Grid(width, height), limits, &totals,
                               {0, 0}, expand_chains, rooms);
      });
}

std::vector<std::uint8_t> EncodeFurniture(const std::vector<FurnitureObject>& furniture) {
  return ChunkBody(furniture, EncodeFurnitureItems);
}

StatusOr<std::vector<FurnitureObject>> DecodeFurniture(const std::vector<std::uint8_t>& body,
                                                       int width, int height,
                                                       const DecodeLimits& limits,
                                                       bool expand_chains) {
  return DecodeChunkBody<FurnitureObject>(
      body, "FURN", "furniture count", "objects", limits.max_objects, Limit::kObjects, "object",
      [&](RangeDecoder* dec, std::uint64_t count, std::vector<FurnitureObject>* furniture) {
        LayerTotals totals;
        return DecodeFurnitureItems(dec, count, LayerBounds::Grid(width, height), limits, &totals,
                                    {0, 0}, expand_chains, 0, furniture);
      });
}

std::vector<CellIndex> ChainOfPolygon(const std::vector<CellIndex>& polygon) {
  std::vector<CellIndex> chain;
  if (polygon.size() == 1) return polygon;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const CellIndex a = polygon[i], b = polygon[(i + 1) % polygon.size()];
    if (a == b) continue;
    bool first = true;
    CellIndex last{};
    RasterizeSegment(a, b, [&](int c, int r) {
      if (!first) chain.push_back(last);
      last = {c, r};
      first = false;
    });
  }
  return chain;
}

}  // namespace linemap
