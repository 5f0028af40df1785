// Stage 4 of the trajectory planner, linemap's addition to the paper
// (Kosteley et al., section 3.2 D): every trajectory, the node queue's and
// the straightened shortest paths, is pulled tight before ranking.
#include <cstddef>
#include <vector>

#include "codec/plan/turn_and_move_internal.h"
#include "linemap/plan.h"

namespace linemap::plan_internal {
namespace {

// Drops waypoints that a direct safe move no longer than D_max can skip
// (farthest first). The queue's moves end where rays leave the region, so a
// later move can often start earlier: this only removes turns.
CellTrajectory Shortcut(const SafeZone& zone, const CellTrajectory& in, double d_max_cells) {
  const std::vector<CellIndex>& w = in.waypoints;
  CellTrajectory out;
  out.straightened = in.straightened;
  out.waypoints.push_back(w.front());
  std::size_t i = 0;
  while (i + 1 < w.size()) {
    std::size_t j = w.size() - 1;
    for (; j > i + 1; --j) {
      const double length = Length(w[j].col - w[i].col, w[j].row - w[i].row);
      if (length <= d_max_cells + 1e-9 && SegmentIsSafe(zone, w[i], w[j])) break;
    }
    out.length_cells += Length(w[j].col - w[i].col, w[j].row - w[i].row);
    out.waypoints.push_back(w[j]);
    i = j;
  }
  return out;
}

double PathLength(const std::vector<CellIndex>& w) {
  double length = 0.0;
  for (std::size_t i = 1; i < w.size(); ++i) {
    length += Length(w[i].col - w[i - 1].col, w[i].row - w[i - 1].row);
  }
  return length;
}

// Pulls the trajectory taut: each inner waypoint moves to a neighbouring
// cell (steps of 8, 4, 2, 1 cells) whenever that shortens its two moves and
// both stay safe, no longer than D_max and no shorter than D_min (unless
// already shorter). The queue's waypoints sit on the region's corners, which
// for an 8-connected wave lie off the Euclidean shortest line.
void Slide(const SafeZone& zone, double d_min, double d_max, std::vector<CellIndex>* w) {
  static constexpr int kDx[8] = {1, 1, 0, -1, -1, -1, 0, 1};
  static constexpr int kDy[8] = {0, 1, 1, 1, 0, -1, -1, -1};
  const auto fits = [&](CellIndex a, CellIndex b, double old_length) {
    const double length = Length(b.col - a.col, b.row - a.row);
    return length <= d_max + 1e-9 && (length >= d_min || length >= old_length) &&
           SegmentIsSafe(zone, a, b);
  };
  constexpr int kMaxRounds = 64;
  for (int step : {8, 4, 2, 1}) {
    for (int round = 0; round < kMaxRounds; ++round) {
      bool moved = false;
      for (std::size_t i = 1; i + 1 < w->size(); ++i) {
        const CellIndex prev = (*w)[i - 1], next = (*w)[i + 1];
        CellIndex& at = (*w)[i];
        const double before = Length(at.col - prev.col, at.row - prev.row);
        const double after = Length(next.col - at.col, next.row - at.row);
        for (int d = 0; d < 8; ++d) {
          const CellIndex p{at.col + step * kDx[d], at.row + step * kDy[d]};
          if (!zone.IsSafe(p.col, p.row) || p == prev || p == next) continue;
          const double total = Length(p.col - prev.col, p.row - prev.row) +
                               Length(next.col - p.col, next.row - p.row);
          if (total < before + after - 1e-9 && fits(prev, p, before) && fits(p, next, after)) {
            at = p;
            moved = true;
            break;
          }
        }
      }
      if (!moved) break;
    }
  }
}

}  // namespace

CellTrajectory Tighten(const SafeZone& zone, const CellTrajectory& in, double d_min, double d_max) {
  CellTrajectory t = Shortcut(zone, in, d_max);
  Slide(zone, d_min, d_max, &t.waypoints);
  t = Shortcut(zone, t, d_max);
  t.length_cells = PathLength(t.waypoints);
  return t;
}

}  // namespace linemap::plan_internal
