// Room-border chains and furniture blobs (Kosteley et al., "Local navigation
// map processing algorithm...", sections 3.2 B and C): binary morphology,
// two-pass union-find labelling, and Lee-algorithm closure of room borders.
//
// CONTRACT (fixed by the lead; extend, do not rename): the codec calls
// SegmentMap() and stores rooms[i].chain and blobs[i].cells.
#ifndef LINEMAP_SEGMENTATION_H_
#define LINEMAP_SEGMENTATION_H_

#include <cstdint>
#include <optional>
#include <vector>

#include "linemap/grid.h"
#include "linemap/lines.h"
#include "linemap/status.h"

namespace linemap {

struct CellIndex {
  int col = 0;
  int row = 0;
  bool operator==(const CellIndex&) const = default;
};

struct BoundingBox {
  int min_col = 0, min_row = 0, max_col = -1, max_row = -1;  // inclusive
};

struct RoomBorder {
  // Closed chain of border cells in traversal order: each cell is 8-adjacent
  // to the next, and the last to the first.
  std::vector<CellIndex> chain;
};

struct FurnitureBlob {
  std::vector<CellIndex> cells;  // the blob's exact occupied cells, raster order
  std::size_t cell_count = 0;
  CellIndex first_cell;  // first cell in raster order (row-major from row 0)
  BoundingBox box;
  std::vector<CellIndex> outline;  // closed boundary chain of the blob
};

struct SegmentationOptions {
  std::optional<CellPoint> robot;  // cell units
};

struct Segmentation {
  std::vector<RoomBorder> rooms;
  std::vector<FurnitureBlob> blobs;
};

StatusOr<Segmentation> SegmentMap(const Grid& grid, const SegmentationOptions& options = {});

}  // namespace linemap

#endif  // LINEMAP_SEGMENTATION_H_
