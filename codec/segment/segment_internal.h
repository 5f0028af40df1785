// Internal pieces of SegmentMap() (codec/segment/*.cc), one room at a time,
// in a crop of the grid around the room's free component.
#ifndef LINEMAP_CODEC_SEGMENT_SEGMENT_INTERNAL_H_
#define LINEMAP_CODEC_SEGMENT_SEGMENT_INTERNAL_H_

#include <cstdint>
#include <optional>
#include <vector>

#include "linemap/segmentation.h"

namespace linemap::segment_internal {

// The paper's M_r for one room, in crop-local cells (local (0,0) is grid
// cell (col0, row0); the crop may reach past the grid, such cells are
// virgin).
struct RoomLayout {
  int col0 = 0;
  int row0 = 0;
  BinaryMask in_grid;              // 1 where the crop cell is a grid cell
  BinaryMask free;                 // mark 3: the room's free component
  BinaryMask holes;                // mark 2: enclosed by the free space (furniture, pillars)
  BinaryMask walls;                // mark 1: occupied cells next to the free space
  BinaryMask room;                 // M_H: free | holes | walls
  std::optional<CellIndex> robot;  // local cell, when given
  std::size_t free_cells = 0;
};

// `margin` cells are added around the component's box on every side.
RoomLayout BuildRoomLayout(const Grid& grid, const Labeling& free_labels, std::int32_t label,
                           int margin, std::optional<CellIndex> robot);

// Stage 2: blobs from the occupied cells of layout.holes, in grid cells.
// Cells already in `claimed` (grid-sized) are skipped; new ones are added.
std::vector<FurnitureBlob> ExtractBlobs(const Grid& grid, const RoomLayout& layout,
                                        const std::optional<StructuringElement>& closing,
                                        std::vector<std::uint8_t>* claimed);

// Stage 1: D = room dilated by each of `dilate`, E = D eroded by each of
// `erode`, band = D \ E (the heavy border). D and the band are clipped to
// the grid after E is computed. With `protect_room_interior`, E also holds
// the room's own interior cells (M_H eroded by the 3x3 cross).
struct HeavyBorder {
  BinaryMask dilated;
  BinaryMask eroded;
  BinaryMask band;
};
HeavyBorder ComputeHeavyBorder(const RoomLayout& layout,
                               const std::vector<StructuringElement>& dilate,
                               const std::vector<StructuringElement>& erode,
                               bool protect_room_interior);

// Stages 3 and 4: the room's closed chain (crop-local cells).
struct BorderClosure {
  std::vector<CellIndex> chain;
  bool closed_by_lee = false;
  int border_components = 0;
  int ring_components = 0;
  double border_ms = 0;
  double lee_ms = 0;
};
BorderClosure CloseRoomBorder(const RoomLayout& layout, const HeavyBorder& border,
                              int max_cut_rows);

// The paper's mid-line rule (section 3.2 C): how many times the row through
// the middle of the component's box switches from other cells into the
// component, left to right. Two or more = a room border for the paper.
int MidLineEntries(const Labeling& labels, std::int32_t label);

// Cells in the boxes of the components flagged in `flagged`, or 0 when
// those boxes hold more cells than the map: then a pass over the whole map
// reads less.
inline std::size_t CellsInFlaggedBoxes(const Labeling& labels,
                                       const std::vector<std::uint8_t>& flagged) {
  std::size_t cells = 0;
  for (std::size_t k = 1; k < flagged.size(); ++k) {
    if (!flagged[k]) continue;
    const BoundingBox& box = labels.components[k - 1].box;
    cells += static_cast<std::size_t>(box.max_col - box.min_col + 1) *
             static_cast<std::size_t>(box.max_row - box.min_row + 1);
    if (cells > labels.labels.size()) return 0;
  }
  return cells;
}

// Calls visit(index) for every cell of the components flagged in
// `flagged`, component by component (by their boxes) when their boxes are
// small against the map (furniture candidates mostly are), else in one pass
// over the map. Either way each such cell is visited once.
template <typename Visit>
void ForEachFlaggedCell(const Labeling& labels, const std::vector<std::uint8_t>& flagged,
                        Visit visit) {
  const std::int32_t* l = labels.labels.data();
  if (CellsInFlaggedBoxes(labels, flagged) == 0) {
    for (std::size_t i = 0; i < labels.labels.size(); ++i) {
      if (l[i] && flagged[l[i]]) visit(i);
    }
    return;
  }
  const std::size_t w = static_cast<std::size_t>(labels.width);
  for (std::size_t k = 1; k < flagged.size(); ++k) {
    if (!flagged[k]) continue;
    const BoundingBox& box = labels.components[k - 1].box;
    const std::int32_t label = static_cast<std::int32_t>(k);
    for (int r = box.min_row; r <= box.max_row; ++r) {
      for (std::size_t i = r * w + box.min_col; i <= r * w + box.max_col; ++i) {
        if (l[i] == label) visit(i);
      }
    }
  }
}

// --- SegmentationMethod::kRooms ---

// Rooms from flooding the clearance (room_flood.cc).
struct RoomFlood {
  int width = 0;
  int height = 0;
  // 8-connected components of the non-free cells, and which of them are
  // furniture candidates (enclosed, small, not a wall piece), by label.
  Labeling enclosed;
  std::vector<std::uint8_t> furniture_candidate;
  std::vector<std::int32_t> room_of_cell;  // grid cells, 0 = no room
  std::int32_t room_count = 0;
  std::vector<std::uint16_t> peak;  // by room id: largest clearance (chamfer units)
  std::vector<Doorway> doors;
};
// `join_plateaus` false floods every clearance level cell by cell instead
// of joining the levels above a door's in one raster pass: the same rooms,
// doors and peaks, more slowly (the reference the tests hold the pass to).
RoomFlood FloodRooms(const Grid& grid, const SegmentationOptions& options,
                     SegmentationTimings* timings, bool join_plateaus = true);
// Chamfer units to cells.
double ClearanceCells(std::uint16_t chamfer);

// Furniture against walls (wall_furniture.cc): compact bumps of a wall into
// a room, found from the rooms' cells (grid-sized, 0 = no room). `occupied`
// holds the bump's occupied cells in raster order, `outline` the closed
// outer boundary of all its cells (occupied and unknown).
struct WallPiece {
  std::int32_t room = 0;
  BoundingBox box;
  std::vector<CellIndex> occupied;
  std::vector<CellIndex> outline;
};
// The search's grid-sized arrays of marks and flags reuse the storage of
// `mark_storage` and `flag_storage` (any contents; arrays the caller is
// done with): on a large map fresh arrays cost a page fault every 4 kB.
struct WallFurnitureScratch {
  std::vector<std::int32_t> mark_storage;
  std::vector<std::uint8_t> flag_storage;
};
std::vector<WallPiece> FindWallFurniture(const Grid& grid,
                                         const std::vector<std::int32_t>& room_of_cell,
                                         const SegmentationOptions& options,
                                         WallFurnitureScratch scratch = {});

// Room chains, kinds and furniture blobs from the flood (room_chains.cc).
void BuildRooms(const Grid& grid, const SegmentationOptions& options, RoomFlood flood,
                Segmentation* result);

// CPU time of the calling thread in milliseconds, for the stage timers: on
// an idle machine it equals wall time, on a shared one it is not inflated by
// waiting for a core.
double ThreadCpuMs();

// Even-odd test of the point (col, row) against the polygon through the
// chain's cell centres (half-open rule on rows, so vertices on the scan row
// are counted once).
bool PolygonContains(const std::vector<CellIndex>& chain, double col, double row);

}  // namespace linemap::segment_internal

#endif  // LINEMAP_CODEC_SEGMENT_SEGMENT_INTERNAL_H_
