// Map-frame metres into cell units with the rounding the doubles bring: the
// one rule by which a window in metres takes the cells whose centres lie on
// its edges (CellWindowOfMetres) and a point on a cell's lower or left edge
// is in that cell (CellHoldingPoint), whatever the decimal number typed.
#ifndef LINEMAP_FORMAT_METRE_CELLS_H_
#define LINEMAP_FORMAT_METRE_CELLS_H_

#include "linemap/grid.h"

namespace linemap {

// A map-frame point in cell units (Grid::WorldToCell: the centre of cell
// (c, r) at (c, r)), and for each coordinate the slack (cells) within which
// the exact value of the decimal metres typed may lie: 0.025 m at 0.05
// m/cell is 0.49999999999999994 cells in doubles, and -6.9 m from an origin
// at -7 m is 1.4999999999999929, not 1.5. 1e-9 cell, plus a few units in the
// last place of the terms that coordinate is computed from (the point's and
// the origin's metres, weighted by the yaw's cosine and sine), in cells:
// an origin at a UTM northing of 5,412,345.67 m puts a centre typed in
// decimal 2e-8 cells off at 0.05 m/cell, while far-off metres on one axis
// leave the other axis's slack alone (without a yaw).
struct CellPosition {
  double col = 0, row = 0;
  double col_slack = 0, row_slack = 0;
};
CellPosition CellPositionOf(const MapMetadata& meta, double x, double y);

}  // namespace linemap

#endif  // LINEMAP_FORMAT_METRE_CELLS_H_
