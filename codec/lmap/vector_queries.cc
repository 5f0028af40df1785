// What a viewer of a large map reads without the rest of the file
// (include/linemap/lmap_vectors.h): the header, the layers' items near a
// window, and the room at a cell with the cells of its box.
#include <cstdint>
#include <numeric>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "codec/layers/raster.h"
#include "codec/lmap/chunk_coding.h"
#include "codec/lmap/decoder_v2.h"
#include "format/container.h"
#include "format/file_io.h"
#include "linemap/cells.h"
#include "linemap/lmap_vectors.h"

namespace linemap {
namespace {

StatusOr<LmapHeader> HeaderOf(const ContainerView& view, const DecodeLimits& limits) {
  if (view.chunks.empty() || view.chunks[0].type != kHeaderChunk) {
    return CorruptError("the first chunk is not LMHD");
  }
  StatusOr<HeaderFields> fields = ReadHeader(view.chunks[0].payload, view.chunks[0].size, limits);
  if (!fields.ok()) return fields.status().WithContext("chunk LMHD");
  LmapHeader header;
  header.major = view.major;
  header.minor = view.minor;
  header.lossless = fields->lossless;
  header.width = fields->width;
  header.height = fields->height;
  header.meta = fields->meta;
  // A corrupt `meta` chunk rejects the file in a whole-file read, so it does
  // here too; the last one holds the file's metadata.
  for (const Chunk& chunk : view.chunks) {
    if (chunk.type != kMetadataChunk) continue;
    PayloadCoder coder = PayloadCoder::kRaw;
    StatusOr<std::vector<std::uint8_t>> body =
        UnwrapV2Payload(chunk.payload, chunk.size, limits, &coder);
    if (!body.ok()) return body.status().WithContext("chunk meta");
    StatusOr<std::vector<std::pair<std::string, std::string>>> entries = ReadMetadata(*body);
    if (!entries.ok()) return entries.status().WithContext("chunk meta");
    header.metadata = std::move(*entries);
  }
  return header;
}

bool BoxMeets(const std::vector<CellIndex>& points, const CellWindow& w) {
  if (points.empty()) return false;
  const BoundingBox box = BoxOfCells(points);
  return box.min_col < w.col1 && box.max_col >= w.col0 && box.min_row < w.row1 &&
         box.max_row >= w.row0;
}

// Keeps the items of `items` whose points' box meets `window`, in order.
template <typename Item, typename Points>
void KeepMeeting(const CellWindow& window, Points points_of, std::vector<Item>* items) {
  std::erase_if(*items, [&](const Item& item) { return !BoxMeets(points_of(item), window); });
}

void KeepItemsMeeting(const CellWindow& window, LmapVectors* v) {
  // The walls keep their whole-file indices: a wall's id is its index.
  if (v->wall_indices.empty()) {
    v->wall_indices.resize(v->walls.size());
    std::iota(v->wall_indices.begin(), v->wall_indices.end(), std::uint64_t{0});
  }
  std::size_t kept = 0;
  for (std::size_t i = 0; i < v->walls.size(); ++i) {
    if (!BoxMeets(v->walls[i].points, window)) continue;
    if (kept != i) {  // a self-move would empty the wall
      v->walls[kept] = std::move(v->walls[i]);
      v->wall_indices[kept] = v->wall_indices[i];
    }
    ++kept;
  }
  v->walls.resize(kept);
  v->wall_indices.resize(kept);
  KeepMeeting(
      window, [](const RoomOutline& r) -> const auto& { return r.polygon; }, &v->rooms);
  KeepMeeting(
      window, [](const FurnitureObject& f) -> const auto& { return f.polygon; }, &v->furniture);
}

// 128-bit integers (a GCC and Clang extension, marked so for -Wpedantic).
__extension__ typedef __int128 Int128;

// Twice the area a polygon encloses (shoelace formula, absolute): rooms
// nest (a corridor's border runs around the rooms that open off it), and
// the innermost room holding a point has the smallest area. Each term fits
// in 64 bits; their sum over a file's polygon (up to the chain limit of
// vertices) may not, so it is kept in 128.
Int128 TwiceArea(const std::vector<CellIndex>& polygon) {
  Int128 sum = 0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const CellIndex p = polygon[i], q = polygon[(i + 1) % polygon.size()];
    sum += std::int64_t{p.col} * q.row - std::int64_t{q.col} * p.row;
  }
  return sum < 0 ? -sum : sum;
}

// The box of a chain's cells as a half-open window.
CellWindow ChainBox(const std::vector<CellIndex>& chain) {
  const BoundingBox box = BoxOfCells(chain);
  return {box.min_col, box.min_row, box.max_col + 1, box.max_row + 1};
}

template <typename Result>
StatusOr<Result> NamingFile(StatusOr<Result> result, const std::string& path) {
  if (!result.ok()) return result.status().WithContext("'" + path + "'");
  return result;
}

}  // namespace

StatusOr<LmapHeader> DecodeLmapHeader(const std::vector<std::uint8_t>& bytes,
                                      const DecodeLimits& limits) {
  LINEMAP_ASSIGN_OR_RETURN(ContainerView view, ParseContainer(bytes, limits.max_chunk_bytes));
  return HeaderOf(view, limits);
}

StatusOr<LmapHeader> LoadLmapHeader(const std::string& path, const DecodeLimits& limits) {
  LINEMAP_ASSIGN_OR_RETURN(std::vector<std::uint8_t> bytes,
                           ReadFileBytes(path, limits.max_file_bytes));
  return NamingFile(DecodeLmapHeader(bytes, limits), path);
}

StatusOr<std::optional<int>> LoadLmapToleranceCells(const std::string& path,
                                                    const DecodeLimits& limits) {
  LINEMAP_ASSIGN_OR_RETURN(LmapHeader header, LoadLmapHeader(path, limits));
  return ToleranceCellsOf(header.major, header.lossless, header.metadata);
}

StatusOr<LmapVectors> DecodeLmapVectorsInWindow(const std::vector<std::uint8_t>& bytes,
                                                const CellWindow& window,
                                                const DecodeLimits& limits) {
  LINEMAP_ASSIGN_OR_RETURN(ContainerView view, ParseContainer(bytes, limits.max_chunk_bytes));
  LINEMAP_ASSIGN_OR_RETURN(LmapHeader header, HeaderOf(view, limits));
  LINEMAP_RETURN_IF_ERROR(CheckWindow(window, header.width, header.height));
  LmapVectors v;
  if (view.major >= 2) {
    // LAYR's streams are read only for the sections whose box meets the
    // window: every item of another section has all its points elsewhere.
    LINEMAP_ASSIGN_OR_RETURN(V2File file, ReadV2File(view, limits, /*read_cells=*/false,
                                                     /*expand_chains=*/true, nullptr,
                                                     /*defer_sections=*/true));
    const CellRect rect{window.col0, window.row0, window.col1, window.row1};
    LINEMAP_RETURN_IF_ERROR(ReadLayersMeeting(limits, rect, &file));
    v.walls = std::move(file.walls);
    v.wall_indices = std::move(file.wall_indices);
    v.rooms = std::move(file.rooms);
    v.furniture = std::move(file.furniture);
  } else {
    LINEMAP_ASSIGN_OR_RETURN(v, DecodeLmapVectors(bytes, limits));
  }
  v.major = header.major;
  v.minor = header.minor;
  v.width = header.width;
  v.height = header.height;
  v.meta = header.meta;
  KeepItemsMeeting(window, &v);
  return v;
}

StatusOr<LmapVectors> LoadLmapVectorsInWindow(const std::string& path, const CellWindow& window,
                                              const DecodeLimits& limits) {
  LINEMAP_ASSIGN_OR_RETURN(std::vector<std::uint8_t> bytes,
                           ReadFileBytes(path, limits.max_file_bytes));
  return NamingFile(DecodeLmapVectorsInWindow(bytes, window, limits), path);
}

StatusOr<std::optional<LmapRoom>> DecodeLmapRoomAt(const std::vector<std::uint8_t>& bytes,
                                                   CellIndex cell, const DecodeLimits& limits) {
  LINEMAP_ASSIGN_OR_RETURN(LmapHeader header, DecodeLmapHeader(bytes, limits));
  if (cell.col < 0 || cell.row < 0 || cell.col >= header.width || cell.row >= header.height) {
    return InvalidArgumentError("cell (" + std::to_string(cell.col) + ", " +
                                std::to_string(cell.row) + ") is outside the map's " +
                                std::to_string(header.width) + " x " +
                                std::to_string(header.height) + " cells");
  }
  // A room's chain lies in the box of its polygon, so the rooms that may
  // enclose the cell are those whose box meets it.
  LINEMAP_ASSIGN_OR_RETURN(
      LmapVectors near,
      DecodeLmapVectorsInWindow(bytes, {cell.col, cell.row, cell.col + 1, cell.row + 1}, limits));
  RoomOutline* best = nullptr;
  Int128 best_area = 0;
  for (RoomOutline& room : near.rooms) {
    if (!ChainEncloses(room.chain, cell)) continue;
    const Int128 area = TwiceArea(room.polygon);
    if (best == nullptr || area < best_area) {
      best = &room;
      best_area = area;
    }
  }
  if (best == nullptr) return std::optional<LmapRoom>();
  LmapRoom found;
  found.window = ChainBox(best->chain);
  found.room = std::move(*best);
  LINEMAP_ASSIGN_OR_RETURN(found.grid, DecodeLmapRegion(bytes, found.window, limits));
  return std::optional<LmapRoom>(std::move(found));
}

StatusOr<std::optional<LmapRoom>> LoadLmapRoomAt(const std::string& path, CellIndex cell,
                                                 const DecodeLimits& limits) {
  LINEMAP_ASSIGN_OR_RETURN(std::vector<std::uint8_t> bytes,
                           ReadFileBytes(path, limits.max_file_bytes));
  return NamingFile(DecodeLmapRoomAt(bytes, cell, limits), path);
}

}  // namespace linemap
