// Stage 3 of the trajectory planner: the trajectory regions M_tb (Kosteley et
// al., section 3.2 D, the depth-first backward pass; Table 1 stage 8). A
// cell of index k is on some shortest start-goal path exactly when it can be
// reached from the goal by steps that lower the index by one each time, so
// the pass pushes the goal on a stack and, for every popped cell, pushes its
// not-yet-marked 8-neighbours of index one lower. It then counts, for every
// region cell, its virgin (unmarked) 8-neighbours: the terminal-point test
// of stage 4 reads that count.
#include <vector>

#include "linemap/plan.h"

namespace linemap {
namespace {

void CountVirginNeighbours(TrajectoryRegion* region) {
  for (int row = 0; row < region->height; ++row) {
    for (int col = 0; col < region->width; ++col) {
      if (!region->In(col, row)) continue;
      int virgin = 0;
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
          if ((dx != 0 || dy != 0) && !region->In(col + dx, row + dy)) ++virgin;
        }
      }
      region->virgin_neighbours[static_cast<std::size_t>(row) * region->width + col] =
          static_cast<std::uint8_t>(virgin);
    }
  }
}

}  // namespace

TrajectoryRegion MarkTrajectoryRegion(const SafeZone& zone, const LeeWave& wave, CellIndex goal) {
  TrajectoryRegion region;
  region.width = wave.width;
  region.height = wave.height;
  region.in_region.assign(wave.index.size(), 0);
  region.virgin_neighbours.assign(wave.index.size(), 0);
  if (wave.goal_index < 0) return region;

  const auto at = [&](int col, int row) {
    return static_cast<std::size_t>(row) * wave.width + col;
  };
  std::vector<CellIndex> stack = {goal};
  region.in_region[at(goal.col, goal.row)] = 1;
  region.cell_count = 1;
  while (!stack.empty()) {
    const CellIndex cell = stack.back();
    stack.pop_back();
    const std::int32_t lower = wave.At(cell.col, cell.row) - 1;
    if (lower < 0) continue;  // the start
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        const int c = cell.col + dx, r = cell.row + dy;
        if (wave.At(c, r) != lower || region.in_region[at(c, r)] != 0 ||
            !zone.CanStep(cell.col, cell.row, dx, dy)) {
          continue;
        }
        region.in_region[at(c, r)] = 1;
        ++region.cell_count;
        stack.push_back({c, r});
      }
    }
  }
  CountVirginNeighbours(&region);
  return region;
}

}  // namespace linemap
