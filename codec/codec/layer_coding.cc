// WALL, ROOM and FURN bodies (spec/format.md sections 5.2-5.4).
#include "codec/codec/layer_coding.h"

#include <algorithm>
#include <cstdlib>
#include <memory>
#include <string>
#include <tuple>

#include "codec/codec/int_coding.h"
#include "codec/codec/layer_order.h"
#include "codec/codec/raster.h"
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

// The range-coded part of a body starts after the count; it must be read to
// its last byte (the encoder drops the implied zero tail).
Status CheckEnd(const RangeDecoder& dec, std::size_t size, const char* layer) {
  if (!dec.valid_start() || dec.consumed() != size) {
    return CorruptError(std::string(layer) + " range-coded data is malformed or truncated");
  }
  return Status::Ok();
}

std::vector<std::uint8_t> WithCount(std::uint64_t count, const RangeEncoder& enc) {
  ByteWriter out;
  out.PutVarint(count);
  out.PutBytes(enc.bytes());
  return std::move(out.mutable_bytes());
}

// ---- paths: walls and polygons ----

// A path of lattice points: its number of points (less `min_points`), its
// start as an offset from the previous path's last point, then each step
// (spec/format.md section 5.2).
struct PathModels {
  UIntModel points;
  UIntModel start[2];     // dcol, drow
  BitModel axis[3];       // by the previous step: first, axis, diagonal
  SymbolModel<2> dir[5];  // by the previous axis direction, 4 = none
  UIntModel axis_len[2];  // length - 1; first step, later steps
  UIntModel diag[2];      // dcol, drow of a diagonal step
};

void EncodePath(RangeEncoder* enc, PathModels* m, const std::vector<CellIndex>& p,
                std::size_t min_points, CellIndex* prev) {
  EncodeUInt(enc, &m->points, p.size() - min_points);
  EncodeSInt(enc, &m->start[0], p[0].col - prev->col);
  EncodeSInt(enc, &m->start[1], p[0].row - prev->row);
  *prev = p.back();
  int kind = 0;      // 0 first step, 1 axis, 2 diagonal
  int last_dir = 4;  // previous axis direction, 4 = none
  for (std::size_t i = 1; i < p.size(); ++i) {
    const int dc = p[i].col - p[i - 1].col;
    const int dr = p[i].row - p[i - 1].row;
    const bool axis = dc == 0 || dr == 0;
    enc->Encode(&m->axis[kind], axis ? 1 : 0);
    if (axis) {
      const int dir = dc > 0 ? 0 : dr > 0 ? 1 : dc < 0 ? 2 : 3;
      const unsigned symbol = last_dir == 4 ? dir : (dir - last_dir) & 3;
      EncodeSymbol<2>(enc, &m->dir[last_dir], symbol);
      EncodeUInt(enc, &m->axis_len[kind == 0 ? 0 : 1], std::abs(dc) + std::abs(dr) - 1);
      last_dir = dir;
      kind = 1;
    } else {
      EncodeSInt(enc, &m->diag[0], dc);
      EncodeSInt(enc, &m->diag[1], dr);
      last_dir = 4;
      kind = 2;
    }
  }
}

// Decodes one path; `points` counts its points against `max_points`.
StatusOr<std::vector<CellIndex>> DecodePath(RangeDecoder* dec, PathModels* m, int width, int height,
                                            std::size_t min_points, std::uint64_t max_points,
                                            std::uint64_t* points, CellIndex* prev) {
  const Status corrupt = CorruptError("point out of the grid or malformed");
  std::uint64_t k = 0;
  std::int64_t dcol = 0, drow = 0;
  if (!DecodeUInt(dec, &m->points, &k)) return corrupt;
  *points += k + min_points;
  if (k + min_points > max_points || *points > max_points) {
    return ResourceExhaustedError("points exceed the limit");
  }
  if (!DecodeSInt(dec, &m->start[0], &dcol) || !DecodeSInt(dec, &m->start[1], &drow) ||
      std::llabs(dcol) >= width || std::llabs(drow) >= height) {
    return corrupt;
  }
  CellIndex p{prev->col + static_cast<int>(dcol), prev->row + static_cast<int>(drow)};
  if (!Inside(p, width, height)) return corrupt;
  std::vector<CellIndex> path = {p};
  int kind = 0, last_dir = 4;
  for (std::uint64_t i = 1; i < k + min_points; ++i) {
    std::int64_t dc = 0, dr = 0;
    if (dec->Decode(&m->axis[kind]) == 1) {
      const unsigned symbol = DecodeSymbol<2>(dec, &m->dir[last_dir]);
      const int dir =
          last_dir == 4 ? static_cast<int>(symbol) : static_cast<int>((symbol + last_dir) & 3);
      std::uint64_t len = 0;
      if (!DecodeUInt(dec, &m->axis_len[kind == 0 ? 0 : 1], &len) ||
          len >= static_cast<std::uint64_t>(std::max(width, height))) {
        return corrupt;
      }
      dc = kAxisCol[dir] * static_cast<std::int64_t>(len + 1);
      dr = kAxisRow[dir] * static_cast<std::int64_t>(len + 1);
      last_dir = dir;
      kind = 1;
    } else {
      if (!DecodeSInt(dec, &m->diag[0], &dc) || !DecodeSInt(dec, &m->diag[1], &dr) || dc == 0 ||
          dr == 0 || std::llabs(dc) >= width || std::llabs(dr) >= height) {
        return corrupt;
      }
      last_dir = 4;
      kind = 2;
    }
    const std::int64_t c = p.col + dc;
    const std::int64_t r = p.row + dr;
    if (c < 0 || r < 0 || c >= width || r >= height) return corrupt;
    p = {static_cast<int>(c), static_cast<int>(r)};
    path.push_back(p);
  }
  *prev = p;
  return path;
}

}  // namespace

void CanonicalizeWalls(std::vector<WallPolyline>* walls) {
  std::vector<WallPolyline> kept;
  for (WallPolyline& wall : *walls) {
    std::vector<CellIndex> points;
    for (const CellIndex& q : wall.points) {
      if (points.empty() || !(points.back() == q)) points.push_back(q);
    }
    if (points.size() >= 2) kept.push_back({std::move(points)});
  }
  *walls = std::move(kept);
  OrderWallsForCoding(walls);
}

std::vector<std::uint8_t> EncodeWalls(const std::vector<WallPolyline>& walls) {
  RangeEncoder enc;
  auto m = std::make_unique<PathModels>();
  CellIndex prev{0, 0};
  for (const WallPolyline& wall : walls) EncodePath(&enc, m.get(), wall.points, 2, &prev);
  enc.Finish();
  return WithCount(walls.size(), enc);
}

StatusOr<std::vector<WallPolyline>> DecodeWalls(const std::vector<std::uint8_t>& body, int width,
                                                int height, const DecodeLimits& limits) {
  ByteCursor cursor(body);
  LINEMAP_ASSIGN_OR_RETURN(std::uint64_t count, cursor.ReadVarint("wall count"));
  if (count > limits.max_segments) {
    return ResourceExhaustedError(std::to_string(count) + " walls exceed the segment limit");
  }
  const std::size_t size = cursor.remaining();
  RangeDecoder dec(body.data() + cursor.position(), size);
  auto m = std::make_unique<PathModels>();
  std::vector<WallPolyline> walls;
  // Points, against the segment limit plus one point per wall (a wall of
  // k + 1 segments has k + 2 points).
  std::uint64_t points = 0;
  const std::uint64_t max_points = limits.max_segments + count;
  CellIndex prev{0, 0};
  for (std::uint64_t w = 0; w < count; ++w) {
    StatusOr<std::vector<CellIndex>> path =
        DecodePath(&dec, m.get(), width, height, 2, max_points, &points, &prev);
    if (!path.ok()) {
      return path.status().code() == StatusCode::kResourceExhausted
                 ? ResourceExhaustedError("wall segments exceed the segment limit")
                 : path.status();
    }
    walls.push_back({std::move(*path)});
  }
  LINEMAP_RETURN_IF_ERROR(CheckEnd(dec, size, "WALL"));
  return walls;
}

// ---- chains (rooms and furniture) ----

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

namespace {

// A closed polygon's vertices; the chain is expanded from them, its cells
// counted against the chain limit before it is allocated.
StatusOr<std::vector<CellIndex>> DecodePolygon(RangeDecoder* dec, PathModels* m, int width,
                                               int height, const DecodeLimits& limits,
                                               std::uint64_t* vertices, std::uint64_t* cells,
                                               CellIndex* prev) {
  StatusOr<std::vector<CellIndex>> polygon =
      DecodePath(dec, m, width, height, 1, limits.max_chain_length, vertices, prev);
  if (!polygon.ok()) {
    return polygon.status().code() == StatusCode::kResourceExhausted
               ? ResourceExhaustedError("polygon vertices exceed the chain limit")
               : polygon.status();
  }
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
    return ResourceExhaustedError("chain cells exceed the chain limit");
  }
  return polygon;
}

struct RoomModels {
  UIntModel id_gap;  // id - previous id - 1 (previous -1 before the first)
  SymbolModel<2> kind;
  PathModels polygon;
};

struct FurnitureModels {
  UIntModel room;  // room id + 1 (0: none)
  PathModels polygon;
};

}  // namespace

std::vector<std::uint8_t> EncodeRooms(const std::vector<RoomOutline>& rooms) {
  RangeEncoder enc;
  auto m = std::make_unique<RoomModels>();
  std::int64_t prev_id = -1;
  CellIndex prev_start{0, 0};
  for (const RoomOutline& room : rooms) {
    EncodeUInt(&enc, &m->id_gap, static_cast<std::uint64_t>(room.id - prev_id - 1));
    prev_id = room.id;
    EncodeSymbol<2>(&enc, &m->kind, static_cast<unsigned>(room.kind));
    EncodePath(&enc, &m->polygon, room.polygon, 1, &prev_start);
  }
  enc.Finish();
  return WithCount(rooms.size(), enc);
}

StatusOr<std::vector<RoomOutline>> DecodeRooms(const std::vector<std::uint8_t>& body, int width,
                                               int height, const DecodeLimits& limits,
                                               bool expand_chains) {
  ByteCursor cursor(body);
  LINEMAP_ASSIGN_OR_RETURN(std::uint64_t count, cursor.ReadVarint("room count"));
  if (count > limits.max_chain_length) {
    return ResourceExhaustedError(std::to_string(count) + " rooms exceed the chain limit");
  }
  const std::size_t size = cursor.remaining();
  RangeDecoder dec(body.data() + cursor.position(), size);
  auto m = std::make_unique<RoomModels>();
  std::vector<RoomOutline> rooms;
  std::uint64_t cells = 0, vertices = 0;
  std::int64_t prev_id = -1;
  CellIndex prev_start{0, 0};
  for (std::uint64_t i = 0; i < count; ++i) {
    std::uint64_t gap = 0;
    if (!DecodeUInt(&dec, &m->id_gap, &gap) || gap > 0xFFFFFFFFu ||
        prev_id + 1 + static_cast<std::int64_t>(gap) > 0xFFFFFFFF) {
      return CorruptError("room id above 2^32 - 1");
    }
    RoomOutline room;
    room.id = static_cast<std::uint32_t>(prev_id + 1 + static_cast<std::int64_t>(gap));
    prev_id = room.id;
    const unsigned kind = DecodeSymbol<2>(&dec, &m->kind);
    if (kind > 2) return CorruptError("room kind 3 is reserved");
    room.kind = static_cast<RoomKind>(kind);
    LINEMAP_ASSIGN_OR_RETURN(room.polygon, DecodePolygon(&dec, &m->polygon, width, height, limits,
                                                         &vertices, &cells, &prev_start));
    if (expand_chains) room.chain = ChainOfPolygon(room.polygon);
    rooms.push_back(std::move(room));
  }
  LINEMAP_RETURN_IF_ERROR(CheckEnd(dec, size, "ROOM"));
  return rooms;
}

std::vector<std::uint8_t> EncodeFurniture(const std::vector<FurnitureObject>& furniture) {
  RangeEncoder enc;
  auto m = std::make_unique<FurnitureModels>();
  CellIndex prev_start{0, 0};
  for (const FurnitureObject& object : furniture) {
    EncodeUInt(&enc, &m->room, static_cast<std::uint64_t>(std::int64_t{object.room_id} + 1));
    EncodePath(&enc, &m->polygon, object.polygon, 1, &prev_start);
  }
  enc.Finish();
  return WithCount(furniture.size(), enc);
}

StatusOr<std::vector<FurnitureObject>> DecodeFurniture(const std::vector<std::uint8_t>& body,
                                                       int width, int height,
                                                       const DecodeLimits& limits,
                                                       bool expand_chains) {
  ByteCursor cursor(body);
  LINEMAP_ASSIGN_OR_RETURN(std::uint64_t count, cursor.ReadVarint("furniture count"));
  if (count > limits.max_chain_length) {
    return ResourceExhaustedError(std::to_string(count) + " objects exceed the chain limit");
  }
  const std::size_t size = cursor.remaining();
  RangeDecoder dec(body.data() + cursor.position(), size);
  auto m = std::make_unique<FurnitureModels>();
  std::vector<FurnitureObject> furniture;
  std::uint64_t cells = 0, vertices = 0;
  CellIndex prev_start{0, 0};
  for (std::uint64_t i = 0; i < count; ++i) {
    std::uint64_t room = 0;
    if (!DecodeUInt(&dec, &m->room, &room) || room > 0x80000000u) {
      return CorruptError("furniture room id above 2^31 - 1");
    }
    FurnitureObject object;
    object.id = static_cast<std::uint32_t>(i);
    object.room_id = static_cast<std::int32_t>(static_cast<std::int64_t>(room) - 1);
    LINEMAP_ASSIGN_OR_RETURN(object.polygon, DecodePolygon(&dec, &m->polygon, width, height, limits,
                                                           &vertices, &cells, &prev_start));
    if (expand_chains) object.outline = ChainOfPolygon(object.polygon);
    furniture.push_back(std::move(object));
  }
  LINEMAP_RETURN_IF_ERROR(CheckEnd(dec, size, "FURN"));
  return furniture;
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
