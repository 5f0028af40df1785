// The cells of a straight move (a supercover line): every straight move of
// stage 4 (Kosteley et al., section 3.2 D) is checked cell by cell against
// the safe zone, a check the paper leaves to the ray's rounded cells.
#include <cstdlib>
#include <vector>

#include "linemap/plan.h"

namespace linemap {
namespace {

// Visits the supercover cells of the segment in order; stops early when
// `visit` returns false. Returns false iff it stopped early.
template <typename Visit>
bool WalkSegment(CellIndex from, CellIndex to, Visit visit) {
  const int nx = std::abs(to.col - from.col), ny = std::abs(to.row - from.row);
  const int sx = to.col > from.col ? 1 : -1, sy = to.row > from.row ? 1 : -1;
  CellIndex at = from;
  if (!visit(at)) return false;
  int ix = 0, iy = 0;
  while (ix < nx || iy < ny) {
    // Which cell border the segment crosses next: compare (ix + 0.5) / nx
    // with (iy + 0.5) / ny without division.
    const long long side =
        static_cast<long long>(1 + 2 * ix) * ny - static_cast<long long>(1 + 2 * iy) * nx;
    if (side == 0) {  // through a corner: both side cells are touched
      if (!visit(CellIndex{at.col + sx, at.row}) || !visit(CellIndex{at.col, at.row + sy})) {
        return false;
      }
      at.col += sx;
      at.row += sy;
      ++ix;
      ++iy;
    } else if (side < 0) {
      at.col += sx;
      ++ix;
    } else {
      at.row += sy;
      ++iy;
    }
    if (!visit(at)) return false;
  }
  return true;
}

}  // namespace

std::vector<CellIndex> SegmentCells(CellIndex from, CellIndex to) {
  std::vector<CellIndex> cells;
  WalkSegment(from, to, [&](CellIndex c) {
    cells.push_back(c);
    return true;
  });
  return cells;
}

bool SegmentIsSafe(const SafeZone& zone, CellIndex from, CellIndex to) {
  return WalkSegment(from, to, [&](CellIndex c) { return zone.IsSafe(c.col, c.row); });
}

}  // namespace linemap
