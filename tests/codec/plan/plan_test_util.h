// Small helpers for the planner tests: grids drawn as text, cells as
// printable pairs, an independent brute-force safe zone, and a
// dense-sampling segment check.
#ifndef LINEMAP_TESTS_CODEC_PLAN_PLAN_TEST_UTIL_H_
#define LINEMAP_TESTS_CODEC_PLAN_PLAN_TEST_UTIL_H_

#include <cmath>
#include <deque>
#include <string>
#include <utility>
#include <vector>

#include "linemap/grid.h"
#include "linemap/plan.h"

namespace linemap::plan_test {

// '#' occupied, '.' free, '?' unknown. The LAST string is grid row 0 (the
// picture reads like the map image, row 0 at the bottom).
inline Grid GridFromText(const std::vector<std::string>& lines, double resolution = 1.0) {
  const int height = static_cast<int>(lines.size());
  const int width = static_cast<int>(lines.front().size());
  Grid grid(width, height, Cell::kFree);
  grid.meta.resolution = resolution;
  for (int r = 0; r < height; ++r) {
    const std::string& line = lines[height - 1 - r];
    for (int c = 0; c < width; ++c) {
      grid.set(c, r,
               line[c] == '#'   ? Cell::kOccupied
               : line[c] == '?' ? Cell::kUnknown
                                : Cell::kFree);
    }
  }
  return grid;
}

// Walls with gaps, shared by the wave and region tests that compare with a
// full search.
inline Grid GappedWallsGrid() {
  return GridFromText({
      "..........#.....",
      "..####....#..#..",
      ".....#....#..#..",
      ".....#.......#..",
      "..####..######..",
      "................",
  });
}

// (col, row) pairs, which EXPECT_EQ prints when cells differ.
inline std::vector<std::pair<int, int>> Pairs(const std::vector<CellIndex>& cells) {
  std::vector<std::pair<int, int>> out;
  for (const CellIndex& c : cells) out.emplace_back(c.col, c.row);
  return out;
}

// Independent of the planner: 8-connected breadth-first step counts from
// `from` over the free cells of `grid`, never stepping diagonally past a
// non-free cell (the zero-radius safe zone's rule); -1 where unreached.
inline std::vector<int> FreeStepCounts(const Grid& grid, CellIndex from) {
  std::vector<int> steps(grid.size(), -1);
  std::deque<CellIndex> queue = {from};
  steps[grid.Index(from.col, from.row)] = 0;
  const auto free = [&grid](int c, int r) {
    return grid.Contains(c, r) && grid.at(c, r) == Cell::kFree;
  };
  while (!queue.empty()) {
    const CellIndex c = queue.front();
    queue.pop_front();
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        const int x = c.col + dx, y = c.row + dy;
        if ((dx == 0 && dy == 0) || !free(x, y) || steps[grid.Index(x, y)] >= 0) continue;
        if (dx != 0 && dy != 0 && (!free(c.col + dx, c.row) || !free(c.col, c.row + dy))) {
          continue;
        }
        steps[grid.Index(x, y)] = steps[grid.Index(c.col, c.row)] + 1;
        queue.push_back({x, y});
      }
    }
  }
  return steps;
}

// Safe iff free and every obstacle cell (occupied, unknown, or the ring of
// cells just outside the map) is at a squared distance > radius^2.
inline std::vector<std::uint8_t> BruteForceSafe(const Grid& grid, double radius) {
  std::vector<std::pair<int, int>> obstacles;
  for (int r = -1; r <= grid.height(); ++r) {
    for (int c = -1; c <= grid.width(); ++c) {
      if (!grid.Contains(c, r) || grid.at(c, r) != Cell::kFree) obstacles.emplace_back(c, r);
    }
  }
  std::vector<std::uint8_t> safe(grid.size(), 0);
  const double limit = radius * radius + 1e-6;
  for (int r = 0; r < grid.height(); ++r) {
    for (int c = 0; c < grid.width(); ++c) {
      if (grid.at(c, r) != Cell::kFree) continue;
      bool ok = true;
      for (const auto& [oc, orow] : obstacles) {
        const double d2 = double(oc - c) * (oc - c) + double(orow - r) * (orow - r);
        if (d2 <= limit) {
          ok = false;
          break;
        }
      }
      safe[grid.Index(c, r)] = ok ? 1 : 0;
    }
  }
  return safe;
}

// Samples the segment every 1/64 cell (end points included, exact half-cell
// ties nudged by a tiny offset both ways) and checks each sampled cell.
inline bool SampledSegmentSafe(const SafeZone& zone, CellIndex a, CellIndex b) {
  const double len = std::hypot(b.col - a.col, b.row - a.row);
  const int steps = std::max(1, static_cast<int>(std::ceil(len * 64)));
  for (int i = 0; i <= steps; ++i) {
    const double t = static_cast<double>(i) / steps;
    const double x = a.col + t * (b.col - a.col), y = a.row + t * (b.row - a.row);
    for (double e : {-1e-7, 1e-7}) {
      const int c = static_cast<int>(std::floor(x + 0.5 + e));
      const int r = static_cast<int>(std::floor(y + 0.5 + e));
      if (!zone.IsSafe(c, r)) return false;
    }
  }
  return true;
}

}  // namespace linemap::plan_test

#endif  // LINEMAP_TESTS_CODEC_PLAN_PLAN_TEST_UTIL_H_
