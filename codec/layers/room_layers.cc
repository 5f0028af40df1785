// The rooms and furniture of a file from the map's segmentation
// (layer_extraction_internal.h).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

#include "codec/layers/layer_coding.h"
#include "codec/layers/layer_extraction_internal.h"
#include "codec/layers/layer_order.h"
#include "codec/layers/raster.h"
#include "linemap/segmentation.h"

namespace linemap::layer_extraction_internal {
namespace {

// Room and furniture borders are stored as polygons (spec/format.md 5.3):
// a room's traced border follows every cell step of its walls, and coded
// step by step it costs more than the cells it would spare the tile coder;
// its Douglas-Peucker polygon (vertices on the chain, every chain cell
// within kRoomTolerance of it) keeps the border within a few cells at a few
// vertices per wall. Measured on 8 maps of ../shared/maps (total bytes of
// the default files): tolerance 1 cell 67,157, 2 cells 64,936, 3 cells
// 64,148; 2 keeps a room's outline within 10 cm at 5 cm per cell.
constexpr double kRoomTolerance = 2.0;  // cells
// Furniture is simplified within one cell, or half a cell where that
// would leave some of the object's cells outside (FurniturePolygon).
constexpr double kPolygonTolerance = 1.0;  // cells

std::vector<CellIndex> SimplifyClosedChain(const std::vector<CellIndex>& chain,
                                           double tolerance = kPolygonTolerance) {
  const std::size_t n = chain.size();
  if (n <= 3) return chain;
  std::size_t far = 0;
  std::int64_t far_d = -1;  // squared distance: exact, and 2 (2^31)^2 < 2^63
  for (std::size_t i = 1; i < n; ++i) {
    const std::int64_t dc = chain[i].col - chain[0].col, dr = chain[i].row - chain[0].row;
    const std::int64_t d = dc * dc + dr * dr;
    if (d > far_d) {
      far_d = d;
      far = i;
    }
  }
  std::vector<bool> keep(n, false);
  keep[0] = keep[far] = true;
  // Spans (a, b) of chain indices, b == n meaning index 0 again.
  std::vector<std::pair<std::size_t, std::size_t>> spans = {{0, far}, {far, n}};
  while (!spans.empty()) {
    const auto [a, b] = spans.back();
    spans.pop_back();
    std::size_t worst = 0;
    double worst_d = tolerance;
    for (std::size_t i = a + 1; i < b; ++i) {
      const double d = PointSegmentDistance(chain[i], chain[a], chain[b % n]);
      if (d > worst_d) {
        worst_d = d;
        worst = i;
      }
    }
    if (worst == 0) continue;
    keep[worst] = true;
    spans.push_back({a, worst});
    spans.push_back({worst, b});
  }
  std::vector<CellIndex> polygon;
  for (std::size_t i = 0; i < n; ++i) {
    if (keep[i]) polygon.push_back(chain[i]);
  }
  return polygon;
}

// True when the fill of `chain` (FillChain, spec 8.2) holds every cell.
bool FillHolds(const std::vector<CellIndex>& chain, const std::vector<CellIndex>& cells) {
  const BoundingBox box = BoxOfCells(chain);
  const int w = box.max_col - box.min_col + 1;
  std::vector<std::uint8_t> in(static_cast<std::size_t>(w) * (box.max_row - box.min_row + 1), 0);
  FillChain(chain, [&](int c, int r) {
    in[static_cast<std::size_t>(r - box.min_row) * w + (c - box.min_col)] = 1;
  });
  for (const CellIndex& c : cells) {
    if (c.col < box.min_col || c.col > box.max_col || c.row < box.min_row || c.row > box.max_row ||
        !in[static_cast<std::size_t>(c.row - box.min_row) * w + (c.col - box.min_col)]) {
      return false;
    }
  }
  return true;
}

// A furniture outline's polygon: the simplest (tolerance 1, then 1/2, then
// every cell) whose outline still encloses all the object's cells, so a
// thin object (a shelf two cells deep) keeps its area.
std::vector<CellIndex> FurniturePolygon(const FurnitureBlob& blob) {
  for (const double tolerance : {kPolygonTolerance, 0.5}) {
    std::vector<CellIndex> polygon = SimplifyClosedChain(blob.outline, tolerance);
    if (FillHolds(ChainOfPolygon(polygon), blob.cells)) return polygon;
  }
  return blob.outline;
}

}  // namespace

Status RoomAndFurnitureLayers(const Grid& grid, const EncodeOptions& options,
                              VectorLayers* layers) {
  // The rooms of the whole map, whatever the robot's pose (the rooms
  // method reads none).
  const SegmentationOptions seg_options;
  LINEMAP_ASSIGN_OR_RETURN(Segmentation seg, SegmentMap(grid, seg_options));
  for (RoomBorder& room : seg.rooms) {
    if (!IsStorableChain(room.chain, grid.width(), grid.height())) continue;
    // Within a tolerance T the rooms' outlines may stray as far as their
    // cells plus one: T = 3 files 4 % smaller over the 25 maps of
    // ../shared/maps (T + 2 saved 1 % more; furniture within T instead of
    // one cell saved nothing, its polygons must enclose its cells).
    const double tolerance =
        std::max(kRoomTolerance, static_cast<double>(options.tolerance_cells + 1));
    std::vector<CellIndex> polygon = SimplifyClosedChain(room.chain, tolerance);
    std::vector<CellIndex> chain = ChainOfPolygon(polygon);
    layers->rooms.push_back(
        {static_cast<std::uint32_t>(room.id), room.kind, std::move(polygon), std::move(chain)});
  }
  // The file lists rooms by increasing id (the paper's method numbers
  // none), renumbered 1, 2, ... if two share one.
  std::stable_sort(layers->rooms.begin(), layers->rooms.end(),
                   [](const RoomOutline& a, const RoomOutline& b) { return a.id < b.id; });
  bool increasing = true;
  for (std::size_t i = 1; i < layers->rooms.size(); ++i) {
    increasing = increasing && layers->rooms[i].id > layers->rooms[i - 1].id;
  }
  std::unordered_map<std::uint32_t, std::int32_t> stored_id;  // segmentation's id -> file's
  for (std::size_t k = 0; k < layers->rooms.size(); ++k) {
    const std::uint32_t id = layers->rooms[k].id;
    if (!increasing) layers->rooms[k].id = static_cast<std::uint32_t>(k + 1);
    stored_id.emplace(id, static_cast<std::int32_t>(layers->rooms[k].id));
  }
  for (FurnitureBlob& blob : seg.blobs) {
    if (!IsStorableChain(blob.outline, grid.width(), grid.height())) continue;
    std::vector<CellIndex> polygon = FurniturePolygon(blob);
    std::vector<CellIndex> outline = ChainOfPolygon(polygon);
    // Room ids start at 1; 0 is no room, and so is a room the file cannot
    // store (an object naming it would name another room of a block after).
    const auto room =
        blob.room > 0 ? stored_id.find(static_cast<std::uint32_t>(blob.room)) : stored_id.end();
    layers->furniture.push_back({static_cast<std::uint32_t>(layers->furniture.size()),
                                 room == stored_id.end() ? -1 : room->second, std::move(polygon),
                                 std::move(outline)});
  }
  OrderFurnitureForCoding(&layers->furniture);
  return Status::Ok();
}

}  // namespace linemap::layer_extraction_internal
