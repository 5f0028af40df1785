// Vector layers from a grid (codec/layers/layer_extraction.h): the whole
// map at once, or block by block on maps over kLayerBlockCells a side.
#include "codec/layers/layer_extraction.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <future>
#include <string>
#include <system_error>

#include "codec/cells/cell_tiles.h"
#include "codec/layers/layer_coding.h"
#include "codec/layers/layer_extraction_internal.h"
#include "codec/layers/layer_order.h"
#include "codec/layers/raster.h"
#include "codec/layers/start_task.h"
#include "codec/layers/wall_cover.h"

namespace linemap {
namespace {

using layer_extraction_internal::DropRedundantSegments;
using layer_extraction_internal::EdgeCells;
using layer_extraction_internal::JoinSegmentsUnordered;
using layer_extraction_internal::RoomAndFurnitureLayers;
using layer_extraction_internal::WallSegments;

// Walls for the edge cells that no wall holds within one cell and no
// furniture outline encloses (wall_cover.h). On the 25 maps of
// ../shared/maps they are nearly all lone occupied cells in free space (scan
// specks): covering them raised the share of edge cells within one cell of
// a wall or in furniture from 0.34-1.00 (10 maps at 0.99 or more) to
// 0.9994-1.0000 on every map and lowered DisPL_ave on every map (willow-2010
// 210 -> 2.8 cm, willow-full-0.05 10.5 -> 0.8 cm), for 3.1 % more bytes in
// the 25 default files (190,249 -> 196,194).
void AddCoveringSegments(const Grid& grid, const EdgeCells& edges,
                         const std::vector<FurnitureObject>& furniture,
                         std::vector<LatticeSegment>* segments) {
  std::vector<std::uint8_t> in_furniture(grid.size(), 0);
  for (const FurnitureObject& object : furniture) {
    FillChain(object.outline, [&](int c, int r) { in_furniture[grid.Index(c, r)] = 1; });
  }
  const std::vector<LatticeSegment> cover =
      CoveringSegments(grid, *segments, &in_furniture, edges.bytes());
  segments->insert(segments->end(), cover.begin(), cover.end());
}

// Drops the segments shorter than `min_cells` (Chebyshev length) that
// share neither end with another segment. Within a tolerance T, a lone
// piece shorter than 2T + 1 cells is clutter at the file's scale (a chair,
// a scan artefact), which the cells keep within T; segments joined to
// others stay, so no polyline is cut, and so do those with an end on the
// border of `grid` (on a map over 2048 cells a side that is a block's, and
// the piece may go on in the next block). Over the 25 maps of ../shared/maps:
// T = 1 150,877 -> 145,772 bytes, T = 3 115,205 -> 108,436 (dropping
// every short segment, joined or not, saved 0.3 % more).
void DropShortLoneSegments(const Grid& grid, int min_cells, std::vector<LatticeSegment>* segments) {
  const auto key = [](CellIndex c) {
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(c.row)) << 32) |
           static_cast<std::uint32_t>(c.col);
  };
  std::vector<std::uint64_t> ends;
  ends.reserve(2 * segments->size());
  for (const LatticeSegment& s : *segments) {
    ends.push_back(key(s.a));
    if (!(s.a == s.b)) ends.push_back(key(s.b));
  }
  std::sort(ends.begin(), ends.end());
  const auto shared = [&](CellIndex c) {
    if (c.col == 0 || c.row == 0 || c.col == grid.width() - 1 || c.row == grid.height() - 1) {
      return true;
    }
    const auto [lo, hi] = std::equal_range(ends.begin(), ends.end(), key(c));
    return hi - lo > 1;
  };
  std::erase_if(*segments, [&](const LatticeSegment& s) {
    const int length = std::max(std::abs(s.a.col - s.b.col), std::abs(s.a.row - s.b.row));
    return length < min_cells && !shared(s.a) && !shared(s.b);
  });
}

// With `order_walls` false the walls are left unordered, zero-length steps
// and all (the caller canonicalises them).
StatusOr<VectorLayers> ExtractWholeMapLayers(const Grid& grid, const EncodeOptions& options,
                                             bool order_walls) {
  VectorLayers layers;
  auto walls_task =
      StartTask(options.max_threads != 1, [&] { return WallSegments(grid, options); });
  const Status rooms = RoomAndFurnitureLayers(grid, options, &layers);
  StatusOr<std::vector<LatticeSegment>> segments = walls_task.get();
  LINEMAP_RETURN_IF_ERROR(rooms);
  if (!segments.ok()) return segments.status();
  // The edge cells are found anew rather than kept from the walls task: a
  // large map's segmentation peaks while that task runs. The covering
  // walls read the same cells (found a third time before, 1.5 % of an
  // encode).
  EdgeCells edges(grid);
  DropRedundantSegments(&edges, &*segments);
  // Within a tolerance the cells keep the scan specks within T cells, and
  // the walls are the map's walls without them: 7,300 of 158,000 bytes at
  // T = 1 over the 25 maps.
  if (options.tolerance_cells == 0) {
    AddCoveringSegments(grid, edges, layers.furniture, &*segments);
  } else {
    DropShortLoneSegments(grid, 2 * options.tolerance_cells + 1, &*segments);
  }
  layers.walls = order_walls ? JoinSegments(*segments) : JoinSegmentsUnordered(*segments);
  return layers;
}

void Shift(std::vector<CellIndex>* points, int dc, int dr) {
  for (CellIndex& p : *points) p = {p.col + dc, p.row + dr};
}

// The map's cells of the block whose first cell is (x0, y0), at most
// kLayerBlockCells a side.
Grid BlockOf(const Grid& grid, int x0, int y0) {
  const int w = std::min(kLayerBlockCells, grid.width() - x0);
  const int h = std::min(kLayerBlockCells, grid.height() - y0);
  Grid block(w, h);
  block.meta = grid.meta;
  for (int r = 0; r < h; ++r) {
    std::copy_n(grid.cells().begin() + static_cast<std::ptrdiff_t>(grid.Index(x0, y0 + r)), w,
                block.mutable_cells().begin() + static_cast<std::ptrdiff_t>(r) * w);
  }
  return block;
}

// Drops the rooms' chains and the objects' outlines, storage included
// (`chain = {}` would keep it: on the 282-Mcell office map 106 MB of
// chains stayed allocated that way); their polygons stay, which is all the
// encoder needs.
void DropChains(VectorLayers* layers) {
  for (RoomOutline& room : layers->rooms) std::vector<CellIndex>().swap(room.chain);
  for (FurnitureObject& object : layers->furniture) {
    std::vector<CellIndex>().swap(object.outline);
  }
}

// Whether every point of `points` lies in the box [x0, x1) x [y0, y1).
bool PointsWithin(const std::vector<CellIndex>& points, int x0, int y0, int x1, int y1) {
  return std::all_of(points.begin(), points.end(), [&](const CellIndex& p) {
    return p.col >= x0 && p.col < x1 && p.row >= y0 && p.row < y1;
  });
}

// Whether every item of `layers` lies in the block's box (polygons and
// walls are drawn inside their points' box, so their hints do too).
bool LayersWithin(const VectorLayers& layers, int x0, int y0, int x1, int y1) {
  for (const WallPolyline& wall : layers.walls) {
    if (!PointsWithin(wall.points, x0, y0, x1, y1)) return false;
  }
  for (const RoomOutline& room : layers.rooms) {
    if (!PointsWithin(room.polygon, x0, y0, x1, y1)) return false;
  }
  for (const FurnitureObject& object : layers.furniture) {
    if (!PointsWithin(object.polygon, x0, y0, x1, y1)) return false;
  }
  return true;
}

}  // namespace

StatusOr<VectorLayers> ExtractBlockLayers(const Grid& block, int x0, int y0,
                                          const EncodeOptions& options, bool with_chains) {
  LINEMAP_ASSIGN_OR_RETURN(VectorLayers layers, ExtractWholeMapLayers(block, options, false));
  DropRepeatedWallPoints(&layers.walls);
  if (!with_chains) DropChains(&layers);
  if (!LayersWithin(layers, 0, 0, block.width(), block.height())) {
    return InternalError("a layer item leaves its block at (" + std::to_string(x0) + ", " +
                         std::to_string(y0) + ")");
  }
  for (RoomOutline& room : layers.rooms) {
    Shift(&room.polygon, x0, y0);
    Shift(&room.chain, x0, y0);
  }
  for (FurnitureObject& object : layers.furniture) {
    Shift(&object.polygon, x0, y0);
    Shift(&object.outline, x0, y0);
  }
  for (WallPolyline& wall : layers.walls) Shift(&wall.points, x0, y0);
  return layers;
}

void AppendBlockLayers(VectorLayers block, VectorLayers* all) {
  std::uint32_t first_id = all->rooms.empty() ? 1 : all->rooms.back().id + 1;
  const std::uint32_t base = first_id;
  for (RoomOutline& room : block.rooms) {
    room.id += base;
    first_id = room.id + 1;
    all->rooms.push_back(std::move(room));
  }
  for (FurnitureObject& object : block.furniture) {
    if (object.room_id >= 0) object.room_id += static_cast<std::int32_t>(base);
    all->furniture.push_back(std::move(object));
  }
  std::move(block.walls.begin(), block.walls.end(), std::back_inserter(all->walls));
}

StatusOr<VectorLayers> ExtractVectorLayers(const Grid& grid, const EncodeOptions& options,
                                           bool with_chains) {
  if (grid.empty()) return VectorLayers{};
  if (grid.width() <= kLayerBlockCells && grid.height() <= kLayerBlockCells) {
    return ExtractWholeMapLayers(grid, options, true);
  }
  // A map larger than a block: the line extractor and the segmentation need
  // tens of bytes per cell, so they run block by block, and walls, rooms and
  // furniture end at the block borders. The blocks are extracted
  // kMaxBlocksAtOnce at a time (one with options.max_threads 1), each
  // block's walls and rooms one after the other on its thread: two blocks
  // at a time hold about what one block held with its walls and rooms on
  // two threads, and keep both cores busy (on the 282-Mcell office map the
  // walls task ended long before the rooms).
  // They are appended in block order, so the result does not depend on the
  // threads.
  const int blocks_x = (grid.width() + kLayerBlockCells - 1) / kLayerBlockCells;
  const int blocks_y = (grid.height() + kLayerBlockCells - 1) / kLayerBlockCells;
  const std::uint64_t blocks = static_cast<std::uint64_t>(blocks_x) * blocks_y;
  EncodeOptions block_options = options;
  block_options.max_threads = 1;
  std::vector<StatusOr<VectorLayers>> block_layers(blocks, VectorLayers{});
  const int threads = options.max_threads == 1 ? 1 : kMaxBlocksAtOnce;
  ForEachIndexParallel(blocks, threads, [&](std::uint64_t k) {
    const int x0 = static_cast<int>(k % blocks_x) * kLayerBlockCells;
    const int y0 = static_cast<int>(k / blocks_x) * kLayerBlockCells;
    block_layers[k] = ExtractBlockLayers(BlockOf(grid, x0, y0), x0, y0, block_options, with_chains);
  });
  VectorLayers all;
  for (StatusOr<VectorLayers>& layers : block_layers) {
    if (!layers.ok()) return layers.status();
    AppendBlockLayers(std::move(*layers), &all);
  }
  CanonicalizeWalls(&all.walls);
  OrderFurnitureForCoding(&all.furniture);  // which makes each object's outline anew
  if (!with_chains) DropChains(&all);
  return all;
}

std::vector<std::pair<std::string, std::string>> MetadataOf(const EncodeOptions& options) {
  std::vector<std::pair<std::string, std::string>> entries;
  if (!options.creator.empty()) entries.emplace_back("creator", options.creator);
  if (!options.time.empty()) entries.emplace_back("time", options.time);
  if (!options.frame_id.empty()) entries.emplace_back("frame_id", options.frame_id);
  if (options.robot_pose) {
    // Each number the shortest decimal that reads back as the same double
    // ("30.19", not "30.190000000000001").
    std::string text;
    for (const double v : {options.robot_pose->x, options.robot_pose->y, options.robot_pose->yaw}) {
      char number[32];
      const std::to_chars_result end = std::to_chars(number, number + sizeof(number), v);
      text += (text.empty() ? "" : " ") + std::string(number, end.ptr);
    }
    entries.emplace_back("robot_pose", text);
  }
  return entries;
}

}  // namespace linemap
