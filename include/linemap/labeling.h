// Connected components of a binary mask by the paper's two-pass algorithm
// with a union-find equivalence table (Kosteley et al., section 3.2 B for
// 4-connectivity, 3.2 C for 8-connectivity), and outer-contour tracing.
#ifndef LINEMAP_LABELING_H_
#define LINEMAP_LABELING_H_

#include <cstddef>
#include <cstdint>
#include <vector>

#include "linemap/cells.h"
#include "linemap/morphology.h"

namespace linemap {

enum class Connectivity { kFour, kEight };

struct ComponentStats {
  std::size_t cell_count = 0;
  CellIndex first_cell;  // first cell in raster order (row 0 first, then col)
  BoundingBox box;
};

struct Labeling {
  int width = 0;
  int height = 0;
  // 0 = background; components are numbered 1..n in the raster order of
  // their first cells, so components[label - 1] describes label `label`.
  std::vector<std::int32_t> labels;
  std::vector<ComponentStats> components;

  std::int32_t at(int col, int row) const {
    return labels[static_cast<std::size_t>(row) * width + col];
  }
  // 0 outside the grid.
  std::int32_t get(int col, int row) const {
    return (col >= 0 && row >= 0 && col < width && row < height) ? at(col, row) : 0;
  }
};

Labeling LabelComponents(const BinaryMask& mask, Connectivity connectivity);

// The closed outer boundary of the 8-connected component with label `label`
// (Moore-neighbour tracing from its first cell): consecutive cells are
// 8-adjacent and the last is 8-adjacent to the first; a cell may repeat where
// the component is one cell thin. A single-cell component gives one cell.
std::vector<CellIndex> TraceOuterContour(const Labeling& labeling, std::int32_t label);

}  // namespace linemap

#endif  // LINEMAP_LABELING_H_
