// EdgeCells (layer_extraction_internal.h) against plain loops: the edge
// cells of a map read cell by cell, and the edge cells near a segment found
// by reading the whole 5 x 5 neighbourhood of every raster cell.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "codec/layers/layer_extraction_internal.h"
#include "codec/layers/raster.h"

namespace linemap::layer_extraction_internal {
namespace {

Grid RandomGrid(int w, int h, std::mt19937* rng) {
  Grid grid(w, h, Cell::kFree);
  std::uniform_int_distribution<int> pick(0, 9);
  for (int r = 0; r < h; ++r) {
    for (int c = 0; c < w; ++c) {
      const int k = pick(*rng);
      grid.set(c, r, k < 4 ? Cell::kOccupied : k < 6 ? Cell::kUnknown : Cell::kFree);
    }
  }
  return grid;
}

// An occupied cell with a free 4-neighbour on the map.
bool IsEdge(const Grid& grid, int c, int r) {
  if (grid.at(c, r) != Cell::kOccupied) return false;
  for (const auto& [dc, dr] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
    if (grid.Contains(c + dc, r + dr) && grid.at(c + dc, r + dr) == Cell::kFree) return true;
  }
  return false;
}

// The edge cells within two cells (Chebyshev) of a raster cell of s and
// within kNearCells of s, with their distances, by index.
std::vector<std::pair<std::size_t, double>> PlainNear(const Grid& grid, const LatticeSegment& s) {
  std::set<std::size_t> seen;
  RasterizeSegment(s.a, s.b, [&](int c, int r) {
    for (int dr = -2; dr <= 2; ++dr) {
      for (int dc = -2; dc <= 2; ++dc) {
        if (grid.Contains(c + dc, r + dr) && IsEdge(grid, c + dc, r + dr)) {
          seen.insert(grid.Index(c + dc, r + dr));
        }
      }
    }
  });
  std::vector<std::pair<std::size_t, double>> near;
  for (const std::size_t i : seen) {
    const CellIndex p{static_cast<int>(i % grid.width()), static_cast<int>(i / grid.width())};
    const double d = PointSegmentDistance(p, s.a, s.b);
    if (d <= kNearCells) near.push_back({i, d});
  }
  return near;
}

TEST(EdgeCellsTest, BytesMarkTheEdgeCells) {
  std::mt19937 rng(7);
  for (const auto& [w, h] : {std::pair{1, 1}, {1, 9}, {9, 1}, {2, 2}, {17, 11}}) {
    const Grid grid = RandomGrid(w, h, &rng);
    const EdgeCells edges(grid);
    for (int r = 0; r < h; ++r) {
      for (int c = 0; c < w; ++c) {
        EXPECT_EQ(edges.bytes()[grid.Index(c, r)] != 0, IsEdge(grid, c, r)) << c << "," << r;
      }
    }
  }
}

TEST(EdgeCellsTest, NearFindsWhatTheWholeNeighbourhoodsHold) {
  std::mt19937 rng(11);
  for (const auto& [w, h] : {std::pair{1, 1}, {3, 14}, {14, 3}, {23, 19}}) {
    const Grid grid = RandomGrid(w, h, &rng);
    EdgeCells edges(grid);
    const std::vector<std::uint8_t> before(edges.bytes(), edges.bytes() + grid.size());
    std::uniform_int_distribution<int> col(0, w - 1), row(0, h - 1);
    for (int k = 0; k < 200; ++k) {
      const LatticeSegment s{{col(rng), row(rng)}, {col(rng), row(rng)}};
      std::vector<std::pair<std::size_t, double>> near = edges.Near(s);
      std::sort(near.begin(), near.end());
      EXPECT_EQ(near, PlainNear(grid, s))
          << "(" << s.a.col << "," << s.a.row << ") -> (" << s.b.col << "," << s.b.row << ")";
      // The marks Near() makes while it runs are gone after it.
      EXPECT_TRUE(std::equal(before.begin(), before.end(), edges.bytes()));
    }
  }
}

}  // namespace
}  // namespace linemap::layer_extraction_internal
