// Stage 4 of the trajectory planner, linemap's additions to the paper
// (Kosteley et al., section 3.2 D): shortest paths straightened into
// turn-and-move trajectories. They are alternatives to the node queue's
// trajectories, and the only ones when the queue finds nothing.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <numbers>
#include <queue>
#include <utility>
#include <vector>

#include "codec/plan/turn_and_move_internal.h"
#include "linemap/plan.h"

namespace linemap::plan_internal {

CellTrajectory StraightenPath(const SafeZone& zone, const std::vector<CellIndex>& path,
                              double d_max_cells) {
  CellTrajectory t;
  t.straightened = true;
  t.waypoints.push_back(path.front());
  const auto fits = [&](std::size_t i, std::size_t j) {
    return Length(path[j].col - path[i].col, path[j].row - path[i].row) <= d_max_cells + 1e-9 &&
           SegmentIsSafe(zone, path[i], path[j]);
  };
  std::size_t i = 0;
  while (i + 1 < path.size()) {
    std::size_t j = i + 1;
    while (j + 1 < path.size() && fits(i, j + 1)) ++j;
    t.length_cells += Length(path[j].col - path[i].col, path[j].row - path[i].row);
    t.waypoints.push_back(path[j]);
    i = j;
  }
  return t;
}

std::vector<CellIndex> OctileShortestPath(const SafeZone& zone, CellIndex start, CellIndex goal,
                                          double max_length) {
  const int w = zone.width;
  const auto at = [w](int c, int r) { return static_cast<std::size_t>(r) * w + c; };
  const auto heuristic = [&](int c, int r) {
    const double dx = std::abs(c - goal.col), dy = std::abs(r - goal.row);
    return std::max(dx, dy) + (std::numbers::sqrt2 - 1) * std::min(dx, dy);
  };
  std::vector<double> cost(zone.safe.size(), std::numeric_limits<double>::infinity());
  std::vector<std::int32_t> parent(zone.safe.size(), -1);
  using Item = std::pair<double, std::size_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> open;
  cost[at(start.col, start.row)] = 0;
  open.push({heuristic(start.col, start.row), at(start.col, start.row)});
  const std::size_t target = at(goal.col, goal.row);
  while (!open.empty()) {
    const auto [key, i] = open.top();
    open.pop();
    const int c = static_cast<int>(i % w), r = static_cast<int>(i / w);
    if (key > cost[i] + heuristic(c, r) + 1e-9) continue;  // stale entry
    if (i == target || key > max_length) break;
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        if ((dx == 0 && dy == 0) || !zone.CanStep(c, r, dx, dy)) continue;
        const std::size_t j = at(c + dx, r + dy);
        const double next = cost[i] + ((dx && dy) ? std::numbers::sqrt2 : 1.0);
        if (next < cost[j] - 1e-12) {
          cost[j] = next;
          parent[j] = static_cast<std::int32_t>(i);
          open.push({next + heuristic(c + dx, r + dy), j});
        }
      }
    }
  }
  std::vector<CellIndex> path;
  if (!(cost[target] <= max_length)) return path;
  for (std::int64_t i = static_cast<std::int64_t>(target); i >= 0; i = parent[i]) {
    path.push_back({static_cast<int>(i % w), static_cast<int>(i / w)});
  }
  std::reverse(path.begin(), path.end());
  return path;
}

CellTrajectory Straightened(const SafeZone& zone, const LeeWave& wave,
                            const TrajectoryRegion& region, CellIndex goal, bool top_down,
                            double d_max_cells) {
  std::vector<CellIndex> path = {goal};
  const int first_dy = top_down ? 1 : -1;
  while (wave.At(path.back().col, path.back().row) > 0) {
    const CellIndex cell = path.back();
    const std::int32_t lower = wave.At(cell.col, cell.row) - 1;
    CellIndex next = cell;
    for (int k = 0; k < 9 && next == cell; ++k) {
      const int dy = first_dy * (k / 3 - 1), dx = k % 3 - 1;
      if (region.In(cell.col + dx, cell.row + dy) &&
          wave.At(cell.col + dx, cell.row + dy) == lower &&
          zone.CanStep(cell.col, cell.row, dx, dy)) {
        next = {cell.col + dx, cell.row + dy};
      }
    }
    if (next == cell) return {};  // cannot happen for a region built from this wave
    path.push_back(next);
  }
  std::reverse(path.begin(), path.end());
  return StraightenPath(zone, path, d_max_cells);
}

}  // namespace linemap::plan_internal
