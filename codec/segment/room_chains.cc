// Rooms split at doorways (SegmentationMethod::kRooms), steps 4 and 5:
//   4. each room's chain is the outer boundary of its own cells (Moore
//      tracing), so chains of two rooms never share a cell; its kind comes
//      from its elongation (area over the square of its width);
//   5. furniture: (a) free-standing: the furniture candidates of step 1
//      that keep off every room chain (an obstacle within a cell of a chain
//      hugs a wall or sits in a doorway), grouped by nearness within their
//      room (the legs of a table or a chair), and kept when they have
//      enough occupied cells to be more than a scan speck; a speck-sized
//      piece joins a group only through a piece it lines up with (legs
//      stand in rows and columns, scan specks anywhere); (b) against walls:
//      compact bumps of a wall into a room (wall_furniture.cc), cut from the
//      wall along its face. They are no room cells, so the room's chain runs
//      around them over the free cells along their faces: such a blob
//      borders its room's chain, no blob crosses one.
#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "codec/segment/no_room_boxes.h"
#include "codec/segment/range_scan.h"
#include "codec/segment/segment_internal.h"

namespace linemap::segment_internal {
namespace {

struct Piece {
  std::int32_t label = 0;  // in flood.enclosed
  std::int32_t room = 0;
  BoundingBox box;
  std::vector<CellIndex> occupied;
};

std::int32_t FindGroup(std::vector<std::int32_t>& parent, std::int32_t x) {
  while (parent[x] != x) {
    parent[x] = parent[parent[x]];
    x = parent[x];
  }
  return x;
}

// The cells on the rim of a box as a closed chain of 8-adjacent cells.
std::vector<CellIndex> BoxRing(const BoundingBox& box) {
  std::vector<CellIndex> ring;
  for (int c = box.min_col; c <= box.max_col; ++c) ring.push_back({c, box.min_row});
  for (int r = box.min_row + 1; r <= box.max_row; ++r) ring.push_back({box.max_col, r});
  if (box.max_row > box.min_row) {
    for (int c = box.max_col - 1; c >= box.min_col; --c) ring.push_back({c, box.max_row});
  } else {
    for (int c = box.max_col - 1; c > box.min_col; --c) ring.push_back({c, box.min_row});
  }
  for (int r = box.max_row - 1; r > box.min_row; --r) ring.push_back({box.min_col, r});
  return ring;
}

void Extend(BoundingBox* box, const BoundingBox& other) {
  box->min_col = std::min(box->min_col, other.min_col);
  box->min_row = std::min(box->min_row, other.min_row);
  box->max_col = std::max(box->max_col, other.max_col);
  box->max_row = std::max(box->max_row, other.max_row);
}

// Furniture candidates that stand in a room and keep off every chain.
std::vector<Piece> FurniturePieces(const Grid& grid, const RoomFlood& flood,
                                   const std::vector<std::uint8_t>& on_chain) {
  const std::size_t labels = flood.enclosed.components.size();
  std::vector<std::int32_t> piece_of(labels + 1, -1);
  std::vector<std::uint8_t> rejected(labels + 1, 0);
  std::vector<Piece> pieces;
  const int w = grid.width();
  const int h = grid.height();
  // Component by component in label order (the raster order of their first
  // cells) or over the whole map: a kept piece (no cell rejected) is made
  // at its first cell and gets its occupied cells in raster order either
  // way.
  ForEachFlaggedCell(flood.enclosed, flood.furniture_candidate, [&](std::size_t i) {
    const std::int32_t label = flood.enclosed.labels[i];
    if (rejected[label]) return;
    const int c = static_cast<int>(i % static_cast<std::size_t>(w));
    const int r = static_cast<int>(i / static_cast<std::size_t>(w));
    bool touches = false;
    for (int dr = -1; dr <= 1 && !touches; ++dr) {
      for (int dc = -1; dc <= 1 && !touches; ++dc) {
        const int nc = c + dc, nr = r + dr;
        touches = nc >= 0 && nr >= 0 && nc < w && nr < h && on_chain[grid.Index(nc, nr)];
      }
    }
    if (touches || flood.room_of_cell[i] == 0) {
      rejected[label] = 1;
      return;
    }
    if (piece_of[label] < 0) {
      piece_of[label] = static_cast<std::int32_t>(pieces.size());
      Piece piece;
      piece.label = label;
      piece.room = flood.room_of_cell[i];
      piece.box = flood.enclosed.components[label - 1].box;
      pieces.push_back(std::move(piece));
    }
    if (grid.cells()[i] == Cell::kOccupied) pieces[piece_of[label]].occupied.push_back({c, r});
  });
  std::vector<Piece> kept;
  for (Piece& piece : pieces) {
    if (!rejected[piece.label] && !piece.occupied.empty()) kept.push_back(std::move(piece));
  }
  return kept;
}

// Two boxes whose row spans or column spans overlap, give or take a cell.
bool LineUp(const BoundingBox& a, const BoundingBox& b) {
  return (a.min_row <= b.max_row + 1 && b.min_row <= a.max_row + 1) ||
         (a.min_col <= b.max_col + 1 && b.min_col <= a.max_col + 1);
}

// Union of pieces of one room whose boxes come within `gap` cells, found
// through square buckets of the map, as long as the group's box stays in
// room space (its rim is the blob's outline, which must not run through a
// wall, e.g. around the inner corner of an L-shaped room) and holds at
// most `max_box_cells` cells (one piece of furniture, not a field of specks).
// Speck rule: a piece of at most `speck_cells` occupied cells (a chair leg
// or a scan speck, which look alike) joins another piece only when the two
// line up. The legs of a table or a chair stand in rows and columns, so each
// lines up with a neighbour; a speck that lands near a table by chance
// rarely does, and stays out of its blob.
std::vector<std::int32_t> GroupPieces(const std::vector<Piece>& pieces, int gap,
                                      NoRoomBoxes* no_room, double max_box_cells,
                                      std::size_t speck_cells) {
  const std::int32_t n = static_cast<std::int32_t>(pieces.size());
  std::vector<std::int32_t> parent(n);
  std::vector<BoundingBox> group_box(n);
  for (std::int32_t k = 0; k < n; ++k) {
    parent[k] = k;
    group_box[k] = pieces[k].box;
  }
  const int bucket = std::max(32, gap + 2);
  auto key = [](int bc, int br) {
    return (static_cast<std::int64_t>(br) << 32) ^ (bc & 0xffffffff);
  };
  // Joins every two pieces of one room within `gap` for which `may_join`
  // holds, as long as the joined box stays small and in room space.
  auto join_near = [&](const auto& may_join) {
    std::unordered_map<std::int64_t, std::vector<std::int32_t>> buckets;
    for (std::int32_t k = 0; k < n; ++k) {
      const BoundingBox& b = pieces[k].box;
      // Boxes `gap` cells apart share a bucket when each reaches gap + 1
      // cells past its far side.
      for (int br = b.min_row / bucket; br <= (b.max_row + gap + 1) / bucket; ++br) {
        for (int bc = b.min_col / bucket; bc <= (b.max_col + gap + 1) / bucket; ++bc) {
          std::vector<std::int32_t>& list = buckets[key(bc, br)];
          for (const std::int32_t other : list) {
            const BoundingBox& o = pieces[other].box;
            const int gap_c = std::max(o.min_col - b.max_col, b.min_col - o.max_col) - 1;
            const int gap_r = std::max(o.min_row - b.max_row, b.min_row - o.max_row) - 1;
            if (pieces[other].room != pieces[k].room || std::max(gap_c, gap_r) > gap) continue;
            if (!may_join(k, other)) continue;
            const std::int32_t a = FindGroup(parent, k);
            const std::int32_t z = FindGroup(parent, other);
            if (a == z) continue;
            BoundingBox joined = group_box[a];
            Extend(&joined, group_box[z]);
            const double box_cells = static_cast<double>(joined.max_col - joined.min_col + 1) *
                                     (joined.max_row - joined.min_row + 1);
            if (box_cells > max_box_cells || no_room->Any(joined)) continue;
            parent[a] = z;
            group_box[z] = joined;
          }
          list.push_back(k);
        }
      }
    }
  };
  const auto speck = [&](std::int32_t k) { return pieces[k].occupied.size() <= speck_cells; };
  // First pass: specks join only what they line up with.
  join_near([&](std::int32_t k, std::int32_t other) {
    return (!speck(k) && !speck(other)) || LineUp(pieces[k].box, pieces[other].box);
  });
  // Second pass: what is more than a lone speck now (a piece of some size,
  // or legs that lined up: the two legs at one end of a table) joins
  // whatever else is more than a lone speck nearby (the legs at the other
  // end, a chair).
  std::vector<std::int32_t> members(n, 0);
  for (std::int32_t k = 0; k < n; ++k) ++members[FindGroup(parent, k)];
  std::vector<std::uint8_t> structure(n, 0);
  for (std::int32_t k = 0; k < n; ++k) {
    structure[k] = !speck(k) || members[FindGroup(parent, k)] > 1;
  }
  join_near([&](std::int32_t k, std::int32_t other) { return structure[k] && structure[other]; });
  for (std::int32_t k = 0; k < n; ++k) parent[k] = FindGroup(parent, k);
  return parent;
}

// Step 5a: blobs of the free-standing furniture.
std::vector<FurnitureBlob> FreeStandingBlobs(const Grid& grid, const RoomFlood& flood,
                                             const SegmentationOptions& options,
                                             const std::vector<std::uint8_t>& on_chain) {
  const std::vector<Piece> pieces = FurniturePieces(grid, flood, on_chain);
  const int gap =
      std::max(0, static_cast<int>(std::lround(options.furniture_group_m / grid.meta.resolution)));
  std::vector<std::int32_t> group;
  if (pieces.size() > 1) {
    NoRoomBoxes no_room(flood.room_of_cell, grid.width(), grid.height());
    const double res = grid.meta.resolution;
    group = GroupPieces(pieces, gap, &no_room, options.max_furniture_area_m2 / (res * res),
                        options.speck_max_cells);
  } else {
    group.assign(pieces.size(), 0);
  }
  std::vector<std::vector<std::int32_t>> members(pieces.size());
  for (std::size_t k = 0; k < pieces.size(); ++k) members[group[k]].push_back(k);
  std::vector<FurnitureBlob> blobs;
  for (const std::vector<std::int32_t>& list : members) {
    if (list.empty()) continue;
    FurnitureBlob blob;
    blob.room = pieces[list[0]].room;
    blob.box = pieces[list[0]].box;
    for (const std::int32_t k : list) {
      blob.cells.insert(blob.cells.end(), pieces[k].occupied.begin(), pieces[k].occupied.end());
      Extend(&blob.box, pieces[k].box);
    }
    if (blob.cells.size() < options.min_furniture_cells) continue;
    std::sort(blob.cells.begin(), blob.cells.end(), [](const CellIndex& a, const CellIndex& b) {
      return a.row != b.row ? a.row < b.row : a.col < b.col;
    });
    blob.cell_count = blob.cells.size();
    blob.first_cell = blob.cells.front();
    // One piece: its own outline (around its unknown core too); several:
    // the rim of their common box.
    blob.outline = list.size() == 1 ? TraceOuterContour(flood.enclosed, pieces[list[0]].label)
                                    : BoxRing(blob.box);
    blobs.push_back(std::move(blob));
  }
  return blobs;
}

// Step 5b: blobs of the furniture against walls, added to `blobs`.
void AddWallBlobs(const Grid& grid, const std::vector<std::int32_t>& room_of_cell,
                  const SegmentationOptions& options, WallFurnitureScratch scratch,
                  std::vector<FurnitureBlob>* blobs) {
  for (WallPiece& piece : FindWallFurniture(grid, room_of_cell, options, std::move(scratch))) {
    if (piece.occupied.size() < options.min_furniture_cells) continue;
    FurnitureBlob blob;
    blob.room = piece.room;
    blob.against_wall = true;
    blob.box = piece.box;
    blob.cells = std::move(piece.occupied);
    blob.cell_count = blob.cells.size();
    blob.first_cell = blob.cells.front();
    blob.outline = std::move(piece.outline);
    blobs->push_back(std::move(blob));
  }
}

}  // namespace

void BuildRooms(const Grid& grid, const SegmentationOptions& options, RoomFlood flood,
                Segmentation* result) {
  const double start = ThreadCpuMs();
  const double res = grid.meta.resolution;
  const int w = grid.width();
  const int h = grid.height();
  Labeling rooms;
  rooms.width = w;
  rooms.height = h;
  rooms.components.resize(flood.room_count);
  std::vector<std::size_t> free_cells(flood.room_count, 0);
  for (int r = 0; r < h; ++r) {
    const std::int32_t* ids = flood.room_of_cell.data() + grid.Index(0, r);
    const Cell* cells = grid.cells().data() + grid.Index(0, r);
    const auto next_run = [&](int col) {
      return static_cast<int>(
          FirstOtherThan(ids, static_cast<std::size_t>(col), static_cast<std::size_t>(w), 0));
    };
    for (int c = next_run(0); c < w;) {
      const std::int32_t id = ids[c];
      // A run of one room's cells (a room crosses a row in a few long
      // runs): its statistics updated once for the run, not once a cell;
      // runs and the gaps between them found four cells at a time.
      const int end = static_cast<int>(
          FirstOtherThan(ids, static_cast<std::size_t>(c), static_cast<std::size_t>(w), id));
      std::size_t free = 0;
      for (int k = c; k < end; ++k) free += cells[k] == Cell::kFree;
      ComponentStats& stats = rooms.components[id - 1];
      if (stats.cell_count == 0) {
        stats.first_cell = {c, r};
        stats.box = {c, r, c, r};
      }
      stats.cell_count += static_cast<std::size_t>(end - c);
      stats.box.min_col = std::min(stats.box.min_col, c);
      stats.box.max_col = std::max(stats.box.max_col, end - 1);
      stats.box.max_row = r;
      free_cells[id - 1] += free;
      c = next_run(end);
    }
  }
  rooms.labels = std::move(flood.room_of_cell);
  std::vector<std::uint8_t> on_chain(grid.size(), 0);
  for (std::int32_t id = 1; id <= flood.room_count; ++id) {
    const ComponentStats& stats = rooms.components[id - 1];
    RoomBorder room;
    room.chain = TraceOuterContour(rooms, id);
    for (const CellIndex& cell : room.chain) on_chain[grid.Index(cell.col, cell.row)] = 1;
    room.id = id;
    room.cells = stats.cell_count;
    room.free_cells = free_cells[id - 1];
    room.area_m2 = static_cast<double>(stats.cell_count) * res * res;
    room.first_cell = stats.first_cell;
    room.box = stats.box;
    const double width_cells = std::max(1.0, 2.0 * ClearanceCells(flood.peak[id]) - 1.0);
    room.width_m = width_cells * res;
    const double elongation = static_cast<double>(stats.cell_count) / (width_cells * width_cells);
    room.kind =
        elongation >= options.corridor_min_elongation ? RoomKind::kCorridor : RoomKind::kRoom;
    result->rooms.push_back(std::move(room));
  }
  flood.room_of_cell = std::move(rooms.labels);
  result->blobs = FreeStandingBlobs(grid, flood, options, on_chain);
  // The obstacles' labels and the chains' cells are done with: their
  // storage becomes the wall furniture's grid-sized arrays (on a large map
  // those were the segmentation's peak, and fresh pages cost faults).
  WallFurnitureScratch scratch{std::move(flood.enclosed.labels), std::move(on_chain)};
  AddWallBlobs(grid, flood.room_of_cell, options, std::move(scratch), &result->blobs);
  std::sort(result->blobs.begin(), result->blobs.end(),
            [](const FurnitureBlob& a, const FurnitureBlob& b) {
              return a.first_cell.row != b.first_cell.row ? a.first_cell.row < b.first_cell.row
                                                          : a.first_cell.col < b.first_cell.col;
            });
  result->room_of_cell = std::move(flood.room_of_cell);
  result->doors = std::move(flood.doors);
  result->timings.chains_ms += ThreadCpuMs() - start;
}

}  // namespace linemap::segment_internal
