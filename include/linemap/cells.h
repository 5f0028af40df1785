// Small value types for cell positions and rectangles, shared by the
// morphology, labelling and segmentation modules. Cell units, grid rows
// (row 0 at the map origin), as everywhere in the library (see grid.h).
#ifndef LINEMAP_CELLS_H_
#define LINEMAP_CELLS_H_

#include <algorithm>
#include <vector>

namespace linemap {

struct CellIndex {
  int col = 0;
  int row = 0;
  bool operator==(const CellIndex&) const = default;
};

struct BoundingBox {
  int min_col = 0, min_row = 0, max_col = -1, max_row = -1;  // inclusive
  bool operator==(const BoundingBox&) const = default;
};

// The smallest box holding every cell (the empty box for no cells).
inline BoundingBox BoxOfCells(const std::vector<CellIndex>& cells) {
  if (cells.empty()) return BoundingBox{};
  BoundingBox box{cells[0].col, cells[0].row, cells[0].col, cells[0].row};
  for (const CellIndex& c : cells) {
    box.min_col = std::min(box.min_col, c.col);
    box.max_col = std::max(box.max_col, c.col);
    box.min_row = std::min(box.min_row, c.row);
    box.max_row = std::max(box.max_row, c.row);
  }
  return box;
}

// Whether a closed ring of cells (its last point joined to its first) runs
// clockwise, columns east and rows north as in the map frame: its signed
// area by the shoelace formula is below zero, summed exactly. A ring
// enclosing nothing (out and back along a line) is not clockwise. The turn
// is the same in map-frame metres: an origin's yaw rotates the grid, it
// never mirrors it.
bool RunsClockwise(const std::vector<CellIndex>& ring);

}  // namespace linemap

#endif  // LINEMAP_CELLS_H_
