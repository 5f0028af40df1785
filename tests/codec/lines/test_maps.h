// Small hand-made maps shared by the line-extraction tests.
#ifndef LINEMAP_TESTS_CODEC_LINES_TEST_MAPS_H_
#define LINEMAP_TESTS_CODEC_LINES_TEST_MAPS_H_

#include <cmath>
#include <numbers>

#include "linemap/grid.h"
#include "linemap/lines.h"

namespace linemap::testing {

// Sets every cell of the inclusive box to `value`.
inline void FillBox(Grid* grid, int col0, int row0, int col1, int row1, Cell value) {
  for (int row = row0; row <= row1; ++row) {
    for (int col = col0; col <= col1; ++col) grid->set(col, row, value);
  }
}

// A room with one-cell-thick walls on the border of the inclusive box
// [col0, col1] x [row0, row1], free inside. Cells outside are left as they are.
inline void DrawRoom(Grid* grid, int col0, int row0, int col1, int row1) {
  FillBox(grid, col0, row0, col1, row1, Cell::kOccupied);
  FillBox(grid, col0 + 1, row0 + 1, col1 - 1, row1 - 1, Cell::kFree);
}

inline bool IsEdgeCell(const EdgeMap& edges, int col, int row) {
  return edges.is_edge[static_cast<std::size_t>(row) * edges.width + col] != 0;
}

inline double SegmentAngleDeg(const LineSegment& s) {
  double angle = std::atan2(s.y2 - s.y1, s.x2 - s.x1) * 180.0 / std::numbers::pi;
  if (angle < 0) angle += 180.0;
  if (angle >= 180.0) angle -= 180.0;
  return angle;
}

inline double SegmentLength(const LineSegment& s) { return std::hypot(s.x2 - s.x1, s.y2 - s.y1); }

}  // namespace linemap::testing

#endif  // LINEMAP_TESTS_CODEC_LINES_TEST_MAPS_H_
