// LAYR bodies (spec/format.md section 5.6).
#include "codec/layers/layer_sections.h"

#include <algorithm>
#include <limits>
#include <string>
#include <utility>

#include "codec/layers/layer_coding.h"
#include "format/byte_io.h"
#include "format/range_coder.h"

namespace linemap {
namespace {

// The sections of a width x height grid: ceil(width / side) columns by
// ceil(height / side) rows, numbered row-major from the origin.
struct SectionGrid {
  SectionGrid(int width, int height, std::int64_t side)
      : side(side), cols((width + side - 1) / side), rows((height + side - 1) / side) {}
  std::int64_t count() const { return cols * rows; }
  std::int64_t Of(CellIndex lower) const { return lower.row / side * cols + lower.col / side; }
  std::int64_t side, cols, rows;
};

// The box of a list of points, inclusive at both ends.
struct PointBox {
  int c0 = std::numeric_limits<int>::max(), r0 = std::numeric_limits<int>::max();
  int c1 = std::numeric_limits<int>::min(), r1 = std::numeric_limits<int>::min();
  void Add(const std::vector<CellIndex>& points) {
    for (const CellIndex& p : points) {
      c0 = std::min(c0, p.col);
      r0 = std::min(r0, p.row);
      c1 = std::max(c1, p.col);
      r1 = std::max(r1, p.row);
    }
  }
  CellIndex lower() const { return {c0, r0}; }
};

const std::vector<CellIndex>& PointsOf(const WallPolyline& wall) { return wall.points; }
const std::vector<CellIndex>& PointsOf(const RoomOutline& room) { return room.polygon; }
const std::vector<CellIndex>& PointsOf(const FurnitureObject& object) { return object.polygon; }

// [begin, end) of each section's run in a grouped list.
std::vector<std::size_t> RunStarts(const std::vector<std::int64_t>& sections, std::int64_t count) {
  std::vector<std::size_t> starts(static_cast<std::size_t>(count) + 1, sections.size());
  for (std::size_t i = sections.size(); i-- > 0;) {
    starts[static_cast<std::size_t>(sections[i])] = i;
  }
  // Empty sections start where the next one does.
  for (std::int64_t s = count; s-- > 0;) {
    starts[s] = std::min(starts[s], starts[s + 1]);
  }
  return starts;
}

bool Meets(const LayerSection& e, const CellRect& region) {
  return e.c0 < region.x1 && e.c1 >= region.x0 && e.r0 < region.y1 && e.r1 >= region.y0;
}

}  // namespace

std::int64_t SectionOfPoints(const std::vector<CellIndex>& points, int width, int side) {
  PointBox box;
  box.Add(points);
  return SectionGrid(width, 0, side).Of(box.lower());
}

std::vector<std::uint8_t> EncodeLayerSections(const std::vector<WallPolyline>& walls,
                                              const std::vector<RoomOutline>& rooms,
                                              const std::vector<FurnitureObject>& furniture,
                                              int width, int height, int side) {
  const SectionGrid grid(width, height, side);
  const auto sections_of = [&](const auto& items) {
    std::vector<std::int64_t> sections;
    sections.reserve(items.size());
    for (const auto& item : items) sections.push_back(SectionOfPoints(PointsOf(item), width, side));
    return sections;
  };
  const std::vector<std::size_t> wall_starts = RunStarts(sections_of(walls), grid.count());
  const std::vector<std::size_t> room_starts = RunStarts(sections_of(rooms), grid.count());
  const std::vector<std::size_t> object_starts = RunStarts(sections_of(furniture), grid.count());
  ByteWriter table;
  table.PutVarint(static_cast<std::uint64_t>(side));
  ByteWriter streams;
  for (std::int64_t s = 0; s < grid.count(); ++s) {
    const std::size_t w0 = wall_starts[s], wn = wall_starts[s + 1] - w0;
    const std::size_t r0 = room_starts[s], rn = room_starts[s + 1] - r0;
    const std::size_t o0 = object_starts[s], on = object_starts[s + 1] - o0;
    table.PutVarint(wn);
    table.PutVarint(rn);
    table.PutVarint(on);
    if (wn + rn + on == 0) continue;
    PointBox box;
    for (std::size_t i = 0; i < wn; ++i) box.Add(walls[w0 + i].points);
    for (std::size_t i = 0; i < rn; ++i) box.Add(rooms[r0 + i].polygon);
    for (std::size_t i = 0; i < on; ++i) box.Add(furniture[o0 + i].polygon);
    CellIndex origin{0, 0};
    if (grid.count() > 1) {
      table.PutVarint(static_cast<std::uint64_t>(box.c0));
      table.PutVarint(static_cast<std::uint64_t>(box.r0));
      table.PutVarint(static_cast<std::uint64_t>(box.c1 - box.c0));
      table.PutVarint(static_cast<std::uint64_t>(box.r1 - box.r0));
      origin = box.lower();
    }
    RangeEncoder enc;
    EncodeWallItems(&enc, walls.data() + w0, wn, origin);
    EncodeRoomItems(&enc, rooms.data() + r0, rn, origin);
    EncodeFurnitureItems(&enc, furniture.data() + o0, on, origin);
    enc.Finish();
    table.PutVarint(enc.bytes().size());
    streams.PutBytes(enc.bytes());
  }
  table.PutBytes(streams.bytes());
  return std::move(table.mutable_bytes());
}

namespace {

// Ids are 32-bit (a room's is stored, an object's is its place in the
// chunk), so no limit a caller sets makes a section of more than 2^32 - 1
// items, or more than 2^32 rooms or objects in the chunk, readable: these
// are checked for all three counts of an entry before any limit, and the
// file gets one error whatever the limits. `*rooms` and `*objects` are the
// chunk's totals so far (below 2^64: at most 2^32 after each entry).
Status CheckEntryCounts(std::uint64_t w, std::uint64_t r, std::uint64_t o, std::uint64_t* rooms,
                        std::uint64_t* objects) {
  for (const auto& [count, items] :
       {std::pair{w, "walls"}, std::pair{r, "rooms"}, std::pair{o, "objects"}}) {
    if (count > UINT32_MAX) {
      return CorruptError(std::to_string(count) + " " + items + " in one section, above 2^32 - 1");
    }
  }
  *rooms += r;
  *objects += o;
  if (*rooms > std::uint64_t{1} << 32 || *objects > std::uint64_t{1} << 32) {
    return CorruptError("more than 2^32 rooms or objects in the chunk (their ids are 32-bit)");
  }
  return Status::Ok();
}

// A count of one section's items (at most 2^32 - 1: CheckEntryCounts), at
// most the limit summed with the sections before (`*sum`).
Status AddCount(std::uint64_t count, std::uint64_t limit, Limit which, const char* items,
                const char* limit_name, std::uint64_t* sum, std::uint32_t* out) {
  // The sum stays below 2^64: each term is cut to limit + 1 first.
  *sum += std::min<std::uint64_t>(count, limit == UINT64_MAX ? limit : limit + 1);
  if (*sum > limit) {
    return OverLimitError(which, std::string(items) + " exceed the " + limit_name + " limit of " +
                                     std::to_string(limit));
  }
  *out = static_cast<std::uint32_t>(count);
  return Status::Ok();
}

// The box of section `k` (n > 1 sections), checked against the grid.
Status ReadBox(ByteCursor* cursor, int width, int height, std::int64_t k, LayerSection* e) {
  std::uint64_t c0 = 0, r0 = 0, dc = 0, dr = 0;
  LINEMAP_ASSIGN_OR_RETURN(c0, cursor->ReadVarint("section box column"));
  LINEMAP_ASSIGN_OR_RETURN(r0, cursor->ReadVarint("section box row"));
  LINEMAP_ASSIGN_OR_RETURN(dc, cursor->ReadVarint("section box width"));
  LINEMAP_ASSIGN_OR_RETURN(dr, cursor->ReadVarint("section box height"));
  if (c0 >= static_cast<std::uint64_t>(width) || dc >= static_cast<std::uint64_t>(width) - c0 ||
      r0 >= static_cast<std::uint64_t>(height) || dr >= static_cast<std::uint64_t>(height) - r0) {
    return CorruptError("section " + std::to_string(k) + ": box outside the grid");
  }
  e->c0 = static_cast<int>(c0);
  e->r0 = static_cast<int>(r0);
  e->c1 = static_cast<int>(c0 + dc);
  e->r1 = static_cast<int>(r0 + dr);
  return Status::Ok();
}

}  // namespace

StatusOr<LayerSectionTable> ReadLayerSectionTable(const std::vector<std::uint8_t>& body, int width,
                                                  int height, const DecodeLimits& limits) {
  ByteCursor cursor(body);
  LINEMAP_ASSIGN_OR_RETURN(std::uint64_t s, cursor.ReadVarint("section side"));
  if (s < static_cast<std::uint64_t>(kMinSectionSide) ||
      s > static_cast<std::uint64_t>(kMaxSectionSide)) {
    return CorruptError("section side " + std::to_string(s) + " outside 16..2^31-1");
  }
  LayerSectionTable table;
  table.side = static_cast<std::int64_t>(s);
  const SectionGrid grid(width, height, table.side);
  // An entry takes at least three bytes (its counts).
  if (static_cast<std::uint64_t>(grid.count()) > cursor.remaining() / 3) {
    return CorruptError(std::to_string(grid.count()) + " sections do not fit the chunk");
  }
  std::uint64_t rooms = 0, objects = 0, stream_bytes = 0;
  std::uint64_t all_rooms = 0, all_objects = 0;  // not capped, for the 32-bit ids
  for (std::int64_t k = 0; k < grid.count(); ++k) {
    LayerSection e;
    std::uint64_t w = 0, r = 0, o = 0;
    LINEMAP_ASSIGN_OR_RETURN(w, cursor.ReadVarint("section wall count"));
    LINEMAP_ASSIGN_OR_RETURN(r, cursor.ReadVarint("section room count"));
    LINEMAP_ASSIGN_OR_RETURN(o, cursor.ReadVarint("section object count"));
    LINEMAP_RETURN_IF_ERROR(CheckEntryCounts(w, r, o, &all_rooms, &all_objects));
    e.first_wall = table.walls;
    LINEMAP_RETURN_IF_ERROR(AddCount(w, limits.max_segments, Limit::kSegments, "walls", "segment",
                                     &table.walls, &e.walls));
    LINEMAP_RETURN_IF_ERROR(
        AddCount(r, limits.max_objects, Limit::kObjects, "rooms", "object", &rooms, &e.rooms));
    e.first_object = objects;
    LINEMAP_RETURN_IF_ERROR(AddCount(o, limits.max_objects, Limit::kObjects, "objects", "object",
                                     &objects, &e.objects));
    if (w + r + o == 0) continue;  // no box, no stream: not kept
    e.index = static_cast<std::uint64_t>(k);
    if (grid.count() == 1) {
      e.c1 = width - 1;
      e.r1 = height - 1;
    } else {
      LINEMAP_RETURN_IF_ERROR(ReadBox(&cursor, width, height, k, &e));
    }
    LINEMAP_ASSIGN_OR_RETURN(e.stream_bytes, cursor.ReadVarint("section stream length"));
    if (e.stream_bytes > cursor.remaining()) {
      return CorruptError("section " + std::to_string(k) + ": stream past the end of the chunk");
    }
    e.stream_offset = stream_bytes;  // from the streams' start, for now
    stream_bytes += e.stream_bytes;
    table.sections.push_back(e);
  }
  if (stream_bytes != cursor.remaining()) {
    return CorruptError("the section streams do not fill the chunk");
  }
  for (LayerSection& e : table.sections) e.stream_offset += cursor.position();
  return table;
}

namespace {

// One section's stream into `out`.
Status DecodeSection(const std::uint8_t* data, const LayerSection& e, int width, int height,
                     const DecodeLimits& limits, bool expand_chains, std::uint64_t max_points,
                     std::uint64_t* points, LayerTotals* totals, DecodedLayers* out) {
  const LayerBounds bounds{e.c0, e.r0, std::int64_t{e.c1} + 1, std::int64_t{e.r1} + 1,
                           std::max(width, height)};
  const std::size_t size = static_cast<std::size_t>(e.stream_bytes);
  RangeDecoder dec(data + e.stream_offset, size);
  const CellIndex origin{e.c0, e.r0};
  const std::size_t first_wall = out->walls.size();
  LINEMAP_RETURN_IF_ERROR(DecodeWallItems(&dec, e.walls, bounds, limits.max_segments, max_points,
                                          points, origin, &out->walls));
  for (std::size_t i = first_wall; i < out->walls.size(); ++i) {
    out->wall_indices.push_back(e.first_wall + (i - first_wall));
  }
  const std::size_t first_room = out->rooms.size();
  LINEMAP_RETURN_IF_ERROR(
      DecodeRoomItems(&dec, e.rooms, bounds, limits, totals, origin, expand_chains, &out->rooms));
  if (first_room > 0 && first_room < out->rooms.size() &&
      out->rooms[first_room].id <= out->rooms[first_room - 1].id) {
    return CorruptError("room ids do not increase");
  }
  LINEMAP_RETURN_IF_ERROR(
      DecodeFurnitureItems(&dec, e.objects, bounds, limits, totals, origin, expand_chains,
                           static_cast<std::uint32_t>(e.first_object), &out->furniture));
  return CheckLayerStreamEnd(dec, size, "the section's");
}

}  // namespace

StatusOr<DecodedLayers> DecodeLayerSections(const std::vector<std::uint8_t>& body,
                                            const LayerSectionTable& table, int width, int height,
                                            const DecodeLimits& limits, bool expand_chains,
                                            const CellRect* region) {
  const std::uint64_t max_points = MaxWallPoints(limits.max_segments, table.walls);
  std::uint64_t points = 0;
  LayerTotals totals;
  DecodedLayers out;
  for (std::size_t k = 0; k < table.sections.size(); ++k) {
    const LayerSection& e = table.sections[k];
    if (region != nullptr && !Meets(e, *region)) continue;
    const Status status = DecodeSection(body.data(), e, width, height, limits, expand_chains,
                                        max_points, &points, &totals, &out);
    if (!status.ok()) return status.WithContext("section " + std::to_string(e.index));
  }
  return out;
}

}  // namespace linemap
