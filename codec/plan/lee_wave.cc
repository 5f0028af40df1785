// Stage 2 of the trajectory planner: the Lee wave (Kosteley et al., section
// 3.2 D; Table 1 stage 7 "wave algorithm"). A breadth-first flood from the
// start over the safe zone whose label is the reachability index (the fewest
// 8-connected steps, no corner cutting: SafeZone::CanStep). With a goal set
// in advance the wave stops as soon as the goal is labelled: the goal is
// labelled from a cell of index k - 1, and by then every cell of index
// <= k - 1 is labelled, which is all the backward pass (stage 3) reads.
#include <vector>

#include "linemap/plan.h"

namespace linemap {
namespace {

// The 8 steps; a diagonal step also needs both cells beside its corner.
constexpr int kDx[8] = {1, -1, 0, 0, 1, -1, 1, -1};
constexpr int kDy[8] = {0, 0, 1, -1, 1, 1, -1, -1};

}  // namespace

LeeWave RunLeeWave(const SafeZone& zone, CellIndex start, CellIndex goal) {
  LeeWave wave;
  wave.width = zone.width;
  wave.height = zone.height;
  wave.index.assign(zone.safe.size(), -1);
  if (!zone.IsSafe(start.col, start.row) || !zone.IsSafe(goal.col, goal.row)) return wave;

  const int w = zone.width, h = zone.height;
  const std::uint8_t* safe = zone.safe.data();
  std::int32_t* index = wave.index.data();
  const std::size_t goal_at = static_cast<std::size_t>(goal.row) * w + goal.col;
  std::vector<CellIndex> queue;  // FIFO: a vector with a read position
  queue.reserve(4096);
  queue.push_back(start);
  index[static_cast<std::size_t>(start.row) * w + start.col] = 0;
  if (start == goal) {
    wave.goal_index = 0;
    return wave;
  }
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const CellIndex cell = queue[head];
    const std::size_t at = static_cast<std::size_t>(cell.row) * w + cell.col;
    const std::int32_t next = index[at] + 1;
    // Away from the map edge, neighbours are plain index offsets.
    const bool inner = cell.col > 0 && cell.row > 0 && cell.col < w - 1 && cell.row < h - 1;
    for (int k = 0; k < 8; ++k) {
      const int dx = kDx[k], dy = kDy[k];
      bool ok;
      std::size_t to;
      if (inner) {
        to = at + dx + static_cast<std::ptrdiff_t>(dy) * w;
        ok = safe[to] &&
             (k < 4 || (safe[at + dx] && safe[at + static_cast<std::ptrdiff_t>(dy) * w]));
      } else {
        ok = zone.CanStep(cell.col, cell.row, dx, dy);
        to = ok ? static_cast<std::size_t>(cell.row + dy) * w + (cell.col + dx) : 0;
      }
      if (!ok || index[to] >= 0) continue;
      index[to] = next;
      if (to == goal_at) {
        wave.goal_index = next;
        return wave;
      }
      queue.push_back({cell.col + dx, cell.row + dy});
    }
  }
  return wave;
}

}  // namespace linemap
