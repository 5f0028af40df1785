// Internal pieces of GenerateTrajectories() (codec/plan/turn_and_move.cc),
// stage 4 of the trajectory planner, in cell units: the paper's node queue
// and linemap's additions to it (straightened shortest paths, tightening).
#ifndef LINEMAP_CODEC_PLAN_TURN_AND_MOVE_INTERNAL_H_
#define LINEMAP_CODEC_PLAN_TURN_AND_MOVE_INTERNAL_H_

#include <cmath>
#include <vector>

#include "linemap/cells.h"
#include "linemap/plan.h"

namespace linemap::plan_internal {

// Euclidean length of the offset (dx, dy), cells.
inline double Length(int dx, int dy) { return std::sqrt(static_cast<double>(dx) * dx + dy * dy); }

// The paper's node queue (codec/plan/node_queue.cc): every distinct
// trajectory whose nodes reached the goal, in the order found, at most
// options.max_trajectories of them. Empty when the queue found none (a large
// D_min can forbid every move).
std::vector<CellTrajectory> RunNodeQueue(const SafeZone& zone, const LeeWave& wave,
                                         const TrajectoryRegion& region, const MoveTemplate& moves,
                                         CellIndex start, CellIndex goal,
                                         const GenerationOptions& options);

// A cell path (start first, consecutive cells 8-adjacent) straightened
// greedily: from each waypoint, the farthest path cell reachable by a safe
// straight move no longer than D_max, before the first one that is not.
CellTrajectory StraightenPath(const SafeZone& zone, const std::vector<CellIndex>& path,
                              double d_max_cells);

// The Euclidean-shortest 8-connected path (octile costs: 1 and sqrt 2; A*
// with the octile heuristic; SafeZone::CanStep steps), or an empty path. The
// Lee wave counts a diagonal step as 1, so the region's paths are shortest
// in steps, and around obstacles a route with more steps can be shorter in
// metres; this one covers that case.
// Paths longer than `max_length` cells (octile) are not searched.
std::vector<CellIndex> OctileShortestPath(const SafeZone& zone, CellIndex start, CellIndex goal,
                                          double max_length);

// One shortest path of the region (goal back to start by index steps; at a
// choice, the first neighbour in row order, bottom-up or top-down as asked,
// so the two calls give mirror-image paths in symmetric rooms), then
// straightened (StraightenPath).
CellTrajectory Straightened(const SafeZone& zone, const LeeWave& wave,
                            const TrajectoryRegion& region, CellIndex goal, bool top_down,
                            double d_max_cells);

// The trajectory pulled tight (codec/plan/tighten.cc): waypoints that a
// direct safe move (<= d_max) can skip are dropped, inner waypoints slide to
// shorten their two moves, then skippable ones are dropped again; the length
// is recomputed.
CellTrajectory Tighten(const SafeZone& zone, const CellTrajectory& in, double d_min, double d_max);

}  // namespace linemap::plan_internal

#endif  // LINEMAP_CODEC_PLAN_TURN_AND_MOVE_INTERNAL_H_
