// The edge cells the walls are measured against (layer_extraction_internal.h).
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "codec/layers/layer_extraction_internal.h"
#include "codec/layers/raster.h"

namespace linemap::layer_extraction_internal {

// One pass over the map's rows through plain pointers; the columns off
// the map's sides are tested apart, so the loop over the others has no
// branch (most cells are not occupied and decide nothing).
EdgeCells::EdgeCells(const Grid& grid) : grid_(grid), edge_(grid.cells().size(), 0) {
  const int w = grid.width(), h = grid.height();
  const std::vector<Cell> outside(static_cast<std::size_t>(w), Cell::kUnknown);  // never free
  for (int r = 0; r < h; ++r) {
    const Cell* row = grid.cells().data() + grid.Index(0, r);
    const Cell* up = r > 0 ? row - w : outside.data();
    const Cell* down = r + 1 < h ? row + w : outside.data();
    std::uint8_t* out = edge_.data() + grid.Index(0, r);
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

std::vector<std::pair<std::size_t, double>> EdgeCells::Near(const LatticeSegment& s) const {
  // Each candidate once (neighbourhoods of consecutive raster cells
  // overlap in 20 of their 25 cells): marked in the edge bytes while the
  // call runs, rather than sorted.
  std::vector<std::size_t> candidates;
  std::uint8_t* edge = edge_.data();
  const auto take = [&](std::size_t i) {
    if (edge[i] == kEdge) {
      edge[i] = kEdgeSeen;
      candidates.push_back(i);
    }
  };
  const int w = grid_.width(), h = grid_.height();
  RasterizeSegment(s.a, s.b, [&](int c, int r) {
    // Away from the map's sides the 5 x 5 cells are read row by row
    // without a test per cell (in the same order): this search was 4-5 %
    // of an encode.
    if (c >= 2 && r >= 2 && c + 2 < w && r + 2 < h) {
      for (int dr = -2; dr <= 2; ++dr) {
        const std::size_t row = grid_.Index(c - 2, r + dr);
        for (std::size_t k = 0; k < 5; ++k) take(row + k);
      }
      return;
    }
    for (int dr = -2; dr <= 2; ++dr) {
      for (int dc = -2; dc <= 2; ++dc) {
        const int x = c + dc, y = r + dr;
        if (grid_.Contains(x, y)) take(grid_.Index(x, y));
      }
    }
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
