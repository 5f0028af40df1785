// The room layout M_r and furniture blobs (Kosteley et al., section 3.2 A
// and B). On a ROS grid there are no wall and furniture height intervals, so
// the layout is read from the topology of the free space instead: what the
// room's free component encloses is furniture (the paper's proposed point-in-
// polygon test, on cells), occupied cells next to it outside that are walls.
// Nearby furniture pieces are joined by a closing with the 3x3 cross (3.2 A)
// and the blobs come from the 8-connected labelling of the result (3.2 B
// uses 4-connectivity on furniture that is already joined; 8 keeps a
// diagonal-only chair leg with its chair).
#include <algorithm>

#include "codec/segment/segment_internal.h"

namespace linemap::segment_internal {
namespace {

bool HasFreeNeighbour(const BinaryMask& free, int col, int row) {
  for (int dr = -1; dr <= 1; ++dr) {
    for (int dc = -1; dc <= 1; ++dc) {
      if ((dr || dc) && free.get(col + dc, row + dr)) return true;
    }
  }
  return false;
}

bool TouchesEdge(const BoundingBox& box, int width, int height) {
  return box.min_col == 0 || box.min_row == 0 || box.max_col == width - 1 ||
         box.max_row == height - 1;
}

}  // namespace

RoomLayout BuildRoomLayout(const Grid& grid, const Labeling& free_labels, std::int32_t label,
                           int margin, std::optional<CellIndex> robot) {
  const ComponentStats& stats = free_labels.components[label - 1];
  RoomLayout layout;
  layout.col0 = stats.box.min_col - margin;
  layout.row0 = stats.box.min_row - margin;
  const int w = stats.box.max_col - stats.box.min_col + 1 + 2 * margin;
  const int h = stats.box.max_row - stats.box.min_row + 1 + 2 * margin;
  layout.in_grid = BinaryMask(w, h);
  layout.free = BinaryMask(w, h);
  BinaryMask occupied(w, h);
  // The crop's columns that are grid columns.
  const int c_begin = std::max(0, -layout.col0);
  const int c_end = std::min(w, grid.width() - layout.col0);
  for (int r = 0; r < h; ++r) {
    const int gr = r + layout.row0;
    if (gr < 0 || gr >= grid.height() || c_begin >= c_end) continue;
    const std::size_t g = grid.Index(c_begin + layout.col0, gr);
    const std::size_t m = layout.free.Index(c_begin, r);
    for (int k = 0; k < c_end - c_begin; ++k) {
      layout.in_grid.bits[m + k] = 1;
      layout.free.bits[m + k] = free_labels.labels[g + k] == label;
      occupied.bits[m + k] = grid.cells()[g + k] == Cell::kOccupied;
    }
  }
  layout.free_cells = stats.cell_count;
  // The complement's 8-connected components that stay off the crop edge are
  // enclosed by the free space.
  BinaryMask complement(w, h);
  for (std::size_t i = 0; i < complement.bits.size(); ++i)
    complement.bits[i] = !layout.free.bits[i];
  const Labeling outside = LabelComponents(complement, Connectivity::kEight);
  std::vector<std::uint8_t> enclosed(outside.components.size() + 1, 0);
  for (std::size_t k = 0; k < outside.components.size(); ++k) {
    enclosed[k + 1] = !TouchesEdge(outside.components[k].box, w, h);
  }
  layout.holes = BinaryMask(w, h);
  layout.walls = BinaryMask(w, h);
  layout.room = BinaryMask(w, h);
  for (int r = 0; r < h; ++r) {
    for (int c = 0; c < w; ++c) {
      const std::size_t i = layout.room.Index(c, r);
      const bool hole = enclosed[outside.labels[i]] != 0;
      layout.holes.bits[i] = hole;
      if (hole || layout.free.bits[i]) {
        layout.room.bits[i] = 1;
      } else if (occupied.bits[i] && HasFreeNeighbour(layout.free, c, r)) {
        layout.walls.bits[i] = 1;
        layout.room.bits[i] = 1;
      }
    }
  }
  if (robot) layout.robot = CellIndex{robot->col - layout.col0, robot->row - layout.row0};
  return layout;
}

std::vector<FurnitureBlob> ExtractBlobs(const Grid& grid, const RoomLayout& layout,
                                        const std::optional<StructuringElement>& closing,
                                        std::vector<std::uint8_t>* claimed) {
  const int w = layout.room.width;
  const int h = layout.room.height;
  BinaryMask pieces(w, h);  // occupied cells inside the holes
  for (int r = 0; r < h; ++r) {
    for (int c = 0; c < w; ++c) {
      pieces.set(c, r,
                 layout.holes.at(c, r) && layout.in_grid.at(c, r) &&
                     grid.at(c + layout.col0, r + layout.row0) == Cell::kOccupied);
    }
  }
  const BinaryMask grouped = closing ? Union(Close(pieces, *closing), pieces) : pieces;
  const Labeling groups = LabelComponents(grouped, Connectivity::kEight);
  std::vector<FurnitureBlob> blobs;
  for (std::size_t k = 0; k < groups.components.size(); ++k) {
    const std::int32_t label = static_cast<std::int32_t>(k + 1);
    const BoundingBox& box = groups.components[k].box;
    FurnitureBlob blob;
    for (int r = box.min_row; r <= box.max_row; ++r) {
      for (int c = box.min_col; c <= box.max_col; ++c) {
        if (groups.at(c, r) != label || !pieces.at(c, r)) continue;
        const CellIndex cell{c + layout.col0, r + layout.row0};
        if ((*claimed)[grid.Index(cell.col, cell.row)]) continue;
        blob.cells.push_back(cell);
      }
    }
    if (blob.cells.empty()) continue;
    blob.cell_count = blob.cells.size();
    blob.first_cell = blob.cells.front();
    blob.box = {blob.cells.front().col, blob.cells.front().row, blob.cells.front().col,
                blob.cells.back().row};
    for (const CellIndex& cell : blob.cells) {
      (*claimed)[grid.Index(cell.col, cell.row)] = 1;
      blob.box.min_col = std::min(blob.box.min_col, cell.col);
      blob.box.max_col = std::max(blob.box.max_col, cell.col);
    }
    for (const CellIndex& cell : TraceOuterContour(groups, label)) {
      blob.outline.push_back({cell.col + layout.col0, cell.row + layout.row0});
    }
    blobs.push_back(std::move(blob));
  }
  return blobs;
}

}  // namespace linemap::segment_internal
