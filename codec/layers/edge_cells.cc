// The edge cells the walls are measured against (layer_extraction_internal.h).
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "codec/layers/layer_extraction_internal.h"
#include "codec/layers/raster.h"

namespace linemap::layer_extraction_internal {

// One pass over the map's rows through plain pointers; the columns off
// the map's sides are tested apart, so the loop over the others has no
// branch (most cells are not occupied and decide nothing).
// Every byte is written below, so the array is not zeroed first.
EdgeCells::EdgeCells(const Grid& grid)
    : grid_(grid), edge_(std::make_unique_for_overwrite<std::uint8_t[]>(grid.cells().size())) {
  const int w = grid.width(), h = grid.height();
  const std::vector<Cell> outside(static_cast<std::size_t>(w), Cell::kUnknown);  // never free
  for (int r = 0; r < h; ++r) {
    const Cell* row = grid.cells().data() + grid.Index(0, r);
    const Cell* up = r > 0 ? row - w : outside.data();
    const Cell* down = r + 1 < h ? row + w : outside.data();
    std::uint8_t* out = edge_.get() + grid.Index(0, r);
    const auto edge = [&](int c, bool left_free, bool right_free) {
      const bool free_beside =
          left_free | right_free | (up[c] == Cell::kFree) | (down[c] == Cell::kFree);
      return static_cast<std::uint8_t>(((row[c] == Cell::kOccupied) & free_beside) ? kEdge : 0);
    };
    for (int c = 1; c + 1 < w; ++c) {
      out[c] = edge(c, row[c - 1] == Cell::kFree, row[c + 1] == Cell::kFree);
    }
    out[0] = edge(0, false, w > 1 && row[1] == Cell::kFree);
    if (w > 1) out[w - 1] = edge(w - 1, row[w - 2] == Cell::kFree, false);
  }
}

// Calls take(index) for the cells within two cells (Chebyshev) of `at` on
// the map that are not within two cells of `previous`, row by row.
template <typename Take>
void EdgeCells::ForEachNewNeighbour(std::optional<CellIndex> previous, CellIndex at,
                                    Take&& take) const {
  const int w = grid_.width(), h = grid_.height();
  const int c0 = std::max(at.col - 2, 0), c1 = std::min(at.col + 2, w - 1);
  const int r0 = std::max(at.row - 2, 0), r1 = std::min(at.row + 2, h - 1);
  // The previous neighbourhood's columns and rows (empty without one).
  int pc0 = 1, pc1 = 0, pr0 = 1, pr1 = 0;
  if (previous) {
    pc0 = previous->col - 2;
    pc1 = previous->col + 2;
    pr0 = previous->row - 2;
    pr1 = previous->row + 2;
  }
  for (int r = r0; r <= r1; ++r) {
    const std::size_t row = grid_.Index(0, r);
    if (r < pr0 || r > pr1) {
      for (int c = c0; c <= c1; ++c) take(row + c);
      continue;
    }
    // A row both hold: only the columns outside the previous ones, on
    // either side.
    for (int c = c0; c <= std::min(c1, pc0 - 1); ++c) take(row + c);
    for (int c = std::max(c0, pc1 + 1); c <= c1; ++c) take(row + c);
  }
}

std::vector<std::pair<std::size_t, double>> EdgeCells::Near(const LatticeSegment& s) {
  // Each candidate once (neighbourhoods of consecutive raster cells
  // overlap in 20 of their 25 cells): marked in the edge bytes while the
  // call runs, rather than sorted.
  std::vector<std::size_t> candidates;
  std::uint8_t* edge = edge_.get();
  const auto take = [&](std::size_t i) {
    if (edge[i] == kEdge) {
      edge[i] = kEdgeSeen;
      candidates.push_back(i);
    }
  };
  // Only the cells of each 5 x 5 neighbourhood that the previous one did
  // not hold are read: away from the map's sides, the column of 5 cells a
  // step across the columns brings in and the row of 5 a step across the
  // rows does (a diagonal step brings both; their shared corner is read
  // twice, and taken once). All 25 each step were 4 % of an encode. The
  // cells come in another order than row by row, which neither caller
  // reads: StraightenSegments tests every cell, DropRedundantSegments
  // orders its pairs by cell.
  const int w = grid_.width(), h = grid_.height();
  const std::size_t stride = static_cast<std::size_t>(w);
  bool first = true;
  CellIndex last{0, 0};
  RasterizeSegment(s.a, s.b, [&](int c, int r) {
    const int dc = c - last.col, dr = r - last.row;
    const bool inside = c >= 2 && r >= 2 && c + 2 < w && r + 2 < h;
    if (!first && inside && std::abs(dc) <= 1 && std::abs(dr) <= 1) {
      if (dc != 0) {
        const std::size_t column = grid_.Index(c + 2 * dc, r - 2);
        for (std::size_t k = 0; k < 5; ++k) take(column + k * stride);
      }
      if (dr != 0) {
        const std::size_t row = grid_.Index(c - 2, r + 2 * dr);
        for (std::size_t k = 0; k < 5; ++k) take(row + k);
      }
    } else if (inside) {
      // A segment's first cell: all 25, row by row without a test per cell.
      for (int k = -2; k <= 2; ++k) {
        const std::size_t row = grid_.Index(c - 2, r + k);
        for (std::size_t j = 0; j < 5; ++j) take(row + j);
      }
    } else {
      ForEachNewNeighbour(first ? std::nullopt : std::optional<CellIndex>(last), {c, r}, take);
    }
    first = false;
    last = {c, r};
  });
  std::vector<std::pair<std::size_t, double>> cells;
  const auto width = static_cast<std::size_t>(grid_.width());
  for (std::size_t i : candidates) {
    edge[i] = kEdge;
    const CellIndex p{static_cast<int>(i % width), static_cast<int>(i / width)};
    const double d = PointSegmentDistance(p, s.a, s.b);
    if (d <= kNearCells) cells.push_back({i, d});
  }
  return cells;
}

}  // namespace linemap::layer_extraction_internal
