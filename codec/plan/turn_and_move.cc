// Stage 4 of the trajectory planner: turn-and-move generation (Kosteley et
// al., section 3.2 D, the node-queue algorithm after Figure 9; Table 1 stage
// 9 "neighbourhood template" and stage 10 "trajectory scenario generation").
//
// The stage runs in these files:
//  - node_queue.cc: the paper's node queue, the trajectories of straight
//    moves along the neighbourhood template (move_template.cc);
//  - straightened_paths.cc: the region's and the octile-shortest path,
//    straightened, as alternatives;
//  - tighten.cc: every trajectory pulled tight;
//  - segment_cells.cc: the cells a straight move crosses;
//  - here: the alternatives gathered, tightened and ranked.
//
// Additions to the paper:
//  - the exact segment of every move is checked cell by cell against the
//    safe zone, and the passability matrix is marked along that segment
//    (the ray's rounded staircase is not the segment and would hide corners);
//  - the queue is cut by max_extra_nodes, max_expansions, max_trajectories
//    and a per-cell visit limit, so that wide regions cannot explode;
//  - two shortest paths of the region (backtracked bottom-up and top-down)
//    are straightened greedily and always added as alternatives: they are
//    the only trajectories when the queue finds nothing (possible with a
//    large D_min), so a reachable goal always yields a trajectory;
//  - so is the Euclidean-shortest 8-connected path (octile A*): the wave
//    counts steps, and a route with more steps can be shorter in metres;
//  - every trajectory is tightened: waypoints that a direct safe move
//    (<= D_max) can skip are dropped, and inner waypoints slide to shorten
//    their two moves;
//  - ranking: fewest moves, then shortest, with trajectories more than
//    max_length_excess longer than the shortest found ranked last.
#include <algorithm>
#include <limits>
#include <numbers>
#include <set>
#include <utility>
#include <vector>

#include "codec/plan/turn_and_move_internal.h"
#include "linemap/plan.h"

namespace linemap {
namespace {

using plan_internal::Length;
using plan_internal::OctileShortestPath;
using plan_internal::RunNodeQueue;
using plan_internal::Straightened;
using plan_internal::StraightenPath;
using plan_internal::Tighten;

}  // namespace

std::vector<CellTrajectory> GenerateTrajectories(const SafeZone& zone, const LeeWave& wave,
                                                 const TrajectoryRegion& region,
                                                 const MoveTemplate& moves, CellIndex start,
                                                 CellIndex goal, const GenerationOptions& options) {
  if (wave.goal_index < 0 || !region.In(goal.col, goal.row)) return {};
  if (start == goal) return {CellTrajectory{{start}, 0.0, false}};
  std::vector<CellTrajectory> found = RunNodeQueue(zone, wave, region, moves, start, goal, options);
  // Two more alternatives, always: shortest paths of the region, straightened.
  // It is the only one when the queue found nothing, and often the shortest.
  for (bool top_down : {false, true}) {
    CellTrajectory straightened =
        Straightened(zone, wave, region, goal, top_down, moves.d_max_cells);
    if (!straightened.waypoints.empty()) found.push_back(std::move(straightened));
  }
  std::set<std::vector<std::pair<int, int>>> seen;
  std::vector<CellTrajectory> shortened;
  double shortest = std::numeric_limits<double>::infinity();
  const auto add_tightened = [&](const CellTrajectory& t) {
    CellTrajectory s = Tighten(zone, t, options.d_min_cells, moves.d_max_cells);
    std::vector<std::pair<int, int>> key;
    for (const CellIndex& c : s.waypoints) key.emplace_back(c.col, c.row);
    if (!seen.insert(key).second) return;
    shortest = std::min(shortest, s.length_cells);
    shortened.push_back(std::move(s));
  };
  for (const CellTrajectory& t : found) add_tightened(t);
  // The octile path, when a shorter trajectory may exist (the best is not
  // already the straight line). A safe polyline of length E has a
  // 4-connected cell path of length <= sqrt 2 * E, and octile lengths are at
  // most 4-connected ones, so octile paths longer than sqrt 2 times the
  // shortest so far cannot lead to a shorter trajectory and are not searched.
  constexpr double kOctileExcess = std::numbers::sqrt2;
  const double direct = Length(goal.col - start.col, goal.row - start.row);
  if (shortest > direct * (1.0 + options.max_length_excess)) {
    const std::vector<CellIndex> octile =
        OctileShortestPath(zone, start, goal, kOctileExcess * shortest);
    if (octile.size() >= 2) add_tightened(StraightenPath(zone, octile, moves.d_max_cells));
  }
  found = std::move(shortened);
  const double too_long = shortest * (1.0 + options.max_length_excess) + 1e-9;
  std::stable_sort(
      found.begin(), found.end(), [&](const CellTrajectory& a, const CellTrajectory& b) {
        const bool a_long = a.length_cells > too_long, b_long = b.length_cells > too_long;
        if (a_long != b_long) return b_long;
        if (a.waypoints.size() != b.waypoints.size())
          return a.waypoints.size() < b.waypoints.size();
        return a.length_cells < b.length_cells;
      });
  return found;
}

}  // namespace linemap
