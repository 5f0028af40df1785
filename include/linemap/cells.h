// Small value types for cell positions and rectangles, shared by the
// morphology, labelling and segmentation modules. Cell units, grid rows
// (row 0 at the map origin), as everywhere in the library (see grid.h).
#ifndef LINEMAP_CELLS_H_
#define LINEMAP_CELLS_H_

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

}  // namespace linemap

#endif  // LINEMAP_CELLS_H_
