// Stage 2 of the trajectory planner: the Lee wave (Kosteley et al., section
// 3.2 D; Table 1 stage 7 "wave algorithm"). A breadth-first flood from the
// start over the safe zone whose label is the reachability index (the fewest
// 8-connected steps, no corner cutting: SafeZone::CanStep). With a goal set in advance the wave
// stops as soon as the goal is labelled: the goal is labelled from a cell of index k - 1, and by
// then every cell of index <= k - 1 is labelled, which is all the backward pass (stage 3) reads.
#include <vector>

#include "linemap/plan.h"

namespace linemap {

LeeWave RunLeeWave(const SafeZone& zone, CellIndex start, CellIndex goal) {
  LeeWave wave;
  wave.width = zone.width;
  wave.height = zone.height;
  wave.index.assign(zone.safe.size(), -1);
  if (!zone.IsSafe(start.col, start.row) || !zone.IsSafe(goal.col, goal.row)) return wave;

  const auto at = [&](int col, int row) {
    return static_cast<std::size_t>(row) * zone.width + col;
  };
  std::vector<CellIndex> queue;  // FIFO: a vector with a read position
  queue.reserve(1024);
  queue.push_back(start);
  wave.index[at(start.col, start.row)] = 0;
  if (start == goal) {
    wave.goal_index = 0;
    return wave;
  }
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const CellIndex cell = queue[head];
    const std::int32_t next = wave.index[at(cell.col, cell.row)] + 1;
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        const int c = cell.col + dx, r = cell.row + dy;
        if ((dx == 0 && dy == 0) || !zone.CanStep(cell.col, cell.row, dx, dy) ||
            wave.index[at(c, r)] >= 0) {
          continue;
        }
        wave.index[at(c, r)] = next;
        if (c == goal.col && r == goal.row) {
          wave.goal_index = next;
          return wave;
        }
        queue.push_back({c, r});
      }
    }
  }
  return wave;
}

}  // namespace linemap
