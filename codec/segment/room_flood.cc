// Rooms split at doorways (SegmentationMethod::kRooms), steps 1 to 3:
//   1. enclosed obstacles: furniture candidates count as room space;
//   2. clearance: chamfer 3-4 distance of every room-space cell to the
//      nearest wall or unknown cell (the map edge counts as wall);
//   3. flooding from the highest clearance down with a union-find (a merge
//      tree): pieces that meet at a doorway stay apart, all others join
//      (above a door's clearance all join, so those levels are joined in
//      one raster pass);
//      then pieces joined only through passages narrower than a door, and
//      pieces smaller than a room, are merged into their neighbours.
// The work is done on a copy of the grid padded by one wall cell on every
// side, so that neighbours are index offsets without bounds checks.
//
// The flood itself is merge_tree.cc, the merging of its pieces
// piece_graph.cc.
#include <algorithm>
#include <cmath>
#include <tuple>
#include <utility>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "codec/segment/chamfer.h"
#include "codec/segment/merge_tree.h"
#include "codec/segment/piece_graph.h"
#include "codec/segment/segment_internal.h"
#include "format/large_vector.h"

namespace linemap::segment_internal {
namespace {

// Clearances are in chamfer units (chamfer.h): 3 per side step.
constexpr int kSide = kChamferSide;
constexpr std::uint16_t kFar = kChamferFar;

// A thin shape of area A and perimeter P (cell edges) is about P / 2 long
// and 2 A / P thick, whatever its bends (an L or a T of wall between doors).
bool IsWallPiece(std::size_t cells, std::size_t perimeter, const SegmentationOptions& options,
                 double res) {
  if (perimeter == 0) return false;
  const double length = perimeter / 2.0;
  const double thickness = 2.0 * static_cast<double>(cells) / static_cast<double>(perimeter);
  return length * res >= options.wall_min_length_m &&
         thickness * res <= options.wall_max_thickness_m;
}

// Cell edges between each enclosed component and the cells around it.
std::vector<std::size_t> Perimeters(const Labeling& labels,
                                    const std::vector<std::uint8_t>& enclosed) {
  std::vector<std::size_t> perimeter(labels.components.size() + 1, 0);
  // Enclosed components stay off the map edge (TouchesEdge), so their
  // cells' neighbours are all on the map.
  const std::size_t w = static_cast<std::size_t>(labels.width);
  const std::int32_t* l = labels.labels.data();
  ForEachFlaggedCell(labels, enclosed, [&](std::size_t i) {
    const std::int32_t k = l[i];
    perimeter[k] += (l[i - 1] != k) + (l[i + 1] != k) + (l[i - w] != k) + (l[i + w] != k);
  });
  return perimeter;
}

bool TouchesEdge(const BoundingBox& box, int width, int height) {
  return box.min_col == 0 || box.min_row == 0 || box.max_col == width - 1 ||
         box.max_row == height - 1;
}

DoorRule MakeDoorRule(const SegmentationOptions& options, double res) {
  // A doorway is decided by the clearance s (cells) at the passage's
  // middle: width 2 s - 1 cells, with one cell of tolerance at the lower
  // end and two at the upper (an opening of n cells along the grid has s =
  // ceil(n / 2)): max_door = round(1.5 (max / res + 2)) and min_door =
  // round(1.5 min / res) chamfer units, so at 0.05 m/cell the default
  // 0.5..1.2 m take openings of 9..26 cells (0.45..1.30 m), at 0.1 m/cell
  // 5..14 cells (0.5..1.4 m); segmentation.h and the README say so. (Taking
  // exactly the openings in the range found 37 fewer rooms of 354 on the 24
  // maps of ../shared/maps, on 13 of them: not taken.)
  auto clearance_of_width = [&](double width_m, double slack_cells) {
    return static_cast<int>(std::lround(kSide * (width_m / res + 1.0 + slack_cells) / 2.0));
  };
  DoorRule rule;
  rule.max_door = clearance_of_width(options.max_door_width_m, 1.0);
  rule.min_door = clearance_of_width(options.min_door_width_m, -1.0);
  // Never under two cells: a single wall speck narrows a passage by one.
  rule.constriction =
      std::max(2 * kSide, static_cast<int>(std::lround(kSide * options.door_constriction_m / res)));
  rule.max_room_cells =
      options.max_room_area_m2 > 0
          ? static_cast<std::int64_t>(std::ceil(options.max_room_area_m2 / (res * res)))
          : 0;
  return rule;
}

// Step 1: the obstacles the free space encloses (8-connected components of
// the non-free cells that stay off the map edge), and which of them are
// furniture candidates.
void FindFurnitureCandidates(const Grid& grid, const SegmentationOptions& options,
                             RoomFlood* flood) {
  const int w = grid.width(), h = grid.height();
  const double res = grid.meta.resolution;
  BinaryMask blocked(w, h);
  // Through local pointers: a store through the mask's bytes may alias the
  // vectors' own pointers, which would then be reloaded every cell and
  // keep the loop from being vectorised.
  const Cell* cells = grid.cells().data();
  std::uint8_t* bits = blocked.bits.data();
  const std::size_t n = grid.size();
  for (std::size_t i = 0; i < n; ++i) bits[i] = cells[i] != Cell::kFree;
  flood->enclosed = LabelComponents(blocked, Connectivity::kEight);
  std::vector<std::uint8_t>& candidate = flood->furniture_candidate;
  candidate.assign(flood->enclosed.components.size() + 1, 0);
  const double max_cells = options.max_furniture_area_m2 / (res * res);
  for (std::size_t k = 0; k < flood->enclosed.components.size(); ++k) {
    const ComponentStats& stats = flood->enclosed.components[k];
    candidate[k + 1] = !TouchesEdge(stats.box, w, h) && stats.cell_count <= max_cells;
  }
  const std::vector<std::size_t> perimeter = Perimeters(flood->enclosed, candidate);
  for (std::size_t k = 1; k < candidate.size(); ++k) {
    if (candidate[k] &&
        IsWallPiece(flood->enclosed.components[k - 1].cell_count, perimeter[k], options, res)) {
      candidate[k] = 0;
    }
  }
}

// Step 2: clearance over room space (free cells and furniture
// candidates): chamfer 3-4 units on the grid padded by one cell on every
// side ((width + 2) x (height + 2)), 0 outside room space.
std::vector<std::uint16_t> ComputeClearance(const Grid& grid, RoomFlood* flood) {
  const int w = grid.width(), h = grid.height();
  const int pw = w + 2, ph = h + 2;
  flood->width = w;
  flood->height = h;
  std::vector<std::uint16_t> clearance =
      LargeVector<std::uint16_t>(static_cast<std::size_t>(pw) * ph, 0);
  const Cell* cells = grid.cells().data();
  for (int r = 0; r < h; ++r) {
    std::uint16_t* out = clearance.data() + static_cast<std::size_t>(r + 1) * pw + 1;
    const Cell* in = cells + grid.Index(0, r);
    for (int c = 0; c < w; ++c) out[c] = in[c] == Cell::kFree ? kFar : 0;
  }
  const std::size_t wide = static_cast<std::size_t>(w);
  ForEachFlaggedCell(flood->enclosed, flood->furniture_candidate, [&](std::size_t i) {
    clearance[(i / wide + 1) * pw + (i % wide + 1)] = kFar;
  });
  ChamferInPlace(&clearance, pw, ph);
  return clearance;
}

// out[c] = room_of[in[c] + 1] for c in [0, w); `out` may be `in` moved
// back by at least four entries (NumberRooms rewrites the pieces in place).
// Four cells of no room space (-1, most of many maps: walls, unknown) take
// their 0 at once where SSE2 is at hand: looked up one by one, the rooms
// of the cells were 2 % of an encode.
void RoomsOfRow(const std::int32_t* in, const std::int32_t* room_of, int w, std::int32_t* out) {
  int c = 0;
#if defined(__SSE2__)
  const __m128i none = _mm_set1_epi32(-1);
  for (; c + 4 <= w; c += 4) {
    const __m128i pieces = _mm_loadu_si128(reinterpret_cast<const __m128i*>(in + c));
    if (_mm_movemask_epi8(_mm_cmpeq_epi32(pieces, none)) == 0xffff) {
      _mm_storeu_si128(reinterpret_cast<__m128i*>(out + c), _mm_setzero_si128());
      continue;
    }
    for (int k = c; k < c + 4; ++k) out[k] = room_of[static_cast<std::size_t>(in[k] + 1)];
  }
#endif
  for (; c < w; ++c) out[c] = room_of[static_cast<std::size_t>(in[c] + 1)];
}

// Room ids in raster order of the rooms' first cells; pieces still below
// `min_cells` (free specks with no neighbour) are no rooms. Returns the room
// of each root piece (-1: none). The graph's pieces of the cells are
// rewritten into the rooms of the cells where they lie (a grid cell's index
// is below its padded cell's, so raster order reads each entry before it is
// overwritten): a large map holds one such array, not two.
std::vector<std::int32_t> NumberRooms(const Grid& grid, PieceGraph* graph, std::size_t min_cells,
                                      RoomFlood* flood) {
  const int w = grid.width(), h = grid.height();
  const std::size_t pw = static_cast<std::size_t>(w) + 2;
  std::vector<std::int32_t> room_of_piece(graph->size(), -1);
  // Each piece's root once, not once per cell: the union-find is final.
  std::vector<std::int32_t> root_of(graph->size());
  for (std::int32_t k = 0; k < graph->size(); ++k) root_of[k] = graph->Root(k);
  // Pieces are numbered in raster order of their first cells (PieceGraph),
  // so a room's lowest piece holds the room's first cell: numbered as their
  // pieces come, the rooms are numbered in raster order of their first cells.
  std::int32_t rooms = 0;
  for (std::int32_t k = 0; k < graph->size(); ++k) {
    const std::int32_t root = root_of[k];
    if (graph->Area(root) >= min_cells && room_of_piece[root] < 0) room_of_piece[root] = ++rooms;
  }
  // The room of each piece, one entry up, so that "no room space" (-1)
  // reads 0 without a test per cell.
  std::vector<std::int32_t> room_of(static_cast<std::size_t>(graph->size()) + 1, 0);
  for (std::int32_t k = 0; k < graph->size(); ++k) {
    room_of[static_cast<std::size_t>(k) + 1] = std::max(room_of_piece[root_of[k]], 0);
  }
  std::vector<std::int32_t> cells = graph->TakePieces();
  for (int r = 0; r < h; ++r) {
    const std::int32_t* in = cells.data() + (r + 1) * pw + 1;
    std::int32_t* out = cells.data() + grid.Index(0, r);
    RoomsOfRow(in, room_of.data(), w, out);
  }
  cells.resize(grid.size());
  flood->room_of_cell = std::move(cells);
  flood->room_count = rooms;
  flood->peak.assign(static_cast<std::size_t>(rooms) + 1, 0);
  for (std::int32_t k = 0; k < graph->size(); ++k) {
    const std::int32_t room = room_of_piece[root_of[k]];
    if (room > 0) flood->peak[room] = std::max(flood->peak[room], graph->Peak(k));
  }
  return room_of_piece;
}

// The passage between each pair of neighbouring rooms, at its widest.
void ListDoors(PieceGraph* graph, const std::vector<std::int32_t>& room_of_piece, int pw,
               double res, RoomFlood* flood) {
  for (std::int32_t a = 0; a < graph->size(); ++a) {
    if (!graph->IsRoot(a) || room_of_piece[a] < 0) continue;
    for (const auto& [b, edge] : graph->Neighbours(a)) {
      if (room_of_piece[b] < 0 || room_of_piece[a] >= room_of_piece[b]) continue;
      Doorway door;
      door.room_a = room_of_piece[a];
      door.room_b = room_of_piece[b];
      door.cell = {edge.cell % pw - 1, edge.cell / pw - 1};
      door.width_m = static_cast<double>(edge.width) / kSide * res;
      flood->doors.push_back(door);
    }
  }
  std::sort(flood->doors.begin(), flood->doors.end(), [](const Doorway& x, const Doorway& y) {
    return std::tie(x.room_a, x.room_b) < std::tie(y.room_a, y.room_b);
  });
}

}  // namespace

RoomFlood FloodRooms(const Grid& grid, const SegmentationOptions& options,
                     SegmentationTimings* timings, bool join_plateaus) {
  const double res = grid.meta.resolution;
  RoomFlood flood;
  double start = ThreadCpuMs();
  FindFurnitureCandidates(grid, options, &flood);
  std::vector<std::uint16_t> clearance = ComputeClearance(grid, &flood);
  timings->clearance_ms += ThreadCpuMs() - start;

  start = ThreadCpuMs();
  const int pw = grid.width() + 2;
  const DoorRule rule = MakeDoorRule(options, res);
  std::vector<std::int32_t> parent;
  const std::vector<Contact> contacts = FloodMergeTree(clearance, pw, rule, join_plateaus, &parent);
  PieceGraph graph(std::move(parent), clearance, contacts);
  // The pieces hold their peaks: the clearance's memory is given back.
  std::vector<std::uint16_t>().swap(clearance);
  if (rule.max_room_cells > 0) graph.MergeWidePassages(rule.max_door, rule.max_room_cells);
  graph.MergeNarrowPassages(rule.min_door);
  const std::size_t min_cells =
      static_cast<std::size_t>(std::ceil(options.min_room_area_m2 / (res * res)));
  graph.MergeSmallPieces(min_cells);
  const std::vector<std::int32_t> room_of_piece = NumberRooms(grid, &graph, min_cells, &flood);
  ListDoors(&graph, room_of_piece, pw, res, &flood);
  timings->flooding_ms += ThreadCpuMs() - start;
  return flood;
}

double ClearanceCells(std::uint16_t chamfer) { return static_cast<double>(chamfer) / kSide; }

}  // namespace linemap::segment_internal
