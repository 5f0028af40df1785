// Turn-and-move trajectory planning on an occupancy grid, after Kosteley et
// al., "Local navigation map processing algorithm..." section 3.2 D:
//
//   1. safe zone: free cells farther than d_save (Eq. 1) from every obstacle,
//      found by stamping the circular "impassable area mask" (Eq. 2);
//   2. Lee wave: breadth-first reachability index from the start over the
//      safe zone, stopped once the goal's index is settled;
//   3. trajectory regions (M_tb): the cells on some shortest path, found by
//      the backward depth-first pass with a stack;
//   4. turn-and-move generation: straight moves taken from a neighbourhood
//      template up to D_max, ending at terminal points (Node_Max / Node_Opt),
//      expanded breadth-first from a queue of nodes (what linemap adds to
//      the paper is listed at the top of codec/plan/turn_and_move.cc).
//
// Stages 1-4 are free functions so that tests and benchmarks can run and
// time them one by one; Planner ties them together and keeps the two
// templates (built once per robot, as the paper's Table 1 stages 5 and 9).
//
// Units: the stage functions work in CELL UNITS (cell (col, row) is the
// point (col, row)); PlanRequest and the commands are in map-frame metres
// and radians / degrees.
#ifndef LINEMAP_PLAN_H_
#define LINEMAP_PLAN_H_

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "linemap/cells.h"
#include "linemap/grid.h"
#include "linemap/status.h"

namespace linemap {

// ---------------------------------------------------------------------------
// Robot and options.

struct RobotFootprint {
  double width_m = 0.4;    // robot width w_robot, metres (> 0). Default 0.4.
  double length_m = 0.4;   // robot length h_robot, metres (> 0). Default 0.4.
  double margin_m = 0.05;  // d_extra, deviation while turning on the spot, metres (>= 0).
};

// Eq. (1): d_save = max(w / 2, h / 2) + d_extra, in metres.
double SafeDistanceMetres(const RobotFootprint& robot);

struct PlanOptions {
  RobotFootprint robot;
  // D_min: the node queue generates no straight move shorter than this
  // (except the final move onto the goal), metres (>= 0). The straightened
  // shortest-path alternatives do not obey it. Default 0.1.
  double d_min_m = 0.1;
  // D_max: the longest single straight move, metres (> 0). Default 5.0.
  double d_max_m = 5.0;
  // Nodes beyond (fewest nodes found so far + this) are not expanded: the
  // paper's "significantly higher number of nodes" cut. Default 2.
  int max_extra_nodes = 2;
  // Ranking: fewest moves first (the paper's criterion), except that a
  // trajectory longer than (1 + this) x the shortest one found ranks after
  // every trajectory that is not. 0.01 = 1 %. Default 0.01: fewer turns win
  // only near-ties, so the best trajectory is (nearly) the shortest found
  // and small map changes cannot swap it for a much longer one.
  double max_length_excess = 0.01;
  // Safety valves for pathological maps; generation stops at either.
  std::size_t max_expansions = 20000;  // nodes taken from the queue. Default 20000.
  std::size_t max_trajectories = 32;   // trajectories kept. Default 32.
};

// ---------------------------------------------------------------------------
// Stage 1: safe zone.

struct CellOffset {
  int dx = 0;
  int dy = 0;
  bool operator==(const CellOffset&) const = default;
};

// The "impassable area mask": every cell offset within radius_cells of the
// centre (dx^2 + dy^2 <= radius^2), the centre included. Built once per robot.
// The paper samples R cos(phi), R sin(phi) over phi = 0..359 degrees; the
// exact integer disk holds the same cells without sampling gaps.
struct ImpassableAreaMask {
  double radius_cells = 0.0;
  std::vector<CellOffset> offsets;
  // The same disk as row spans: row dy (from -reach to reach) covers
  // dx in [-half_widths[dy + reach], half_widths[dy + reach]].
  int reach = 0;
  std::vector<int> half_widths;

  static ImpassableAreaMask Build(double radius_cells);
};

// 1 = safe (free and farther than the mask radius from every obstacle cell
// and from the map border), 0 = unsafe. Occupied and unknown cells are both
// obstacles; the area outside the map counts as obstacle too.
struct SafeZone {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> safe;

  bool Contains(int col, int row) const {
    return col >= 0 && row >= 0 && col < width && row < height;
  }
  bool IsSafe(int col, int row) const {
    return Contains(col, row) && safe[static_cast<std::size_t>(row) * width + col] != 0;
  }
  // One 8-connected step from a cell to its neighbour (dx, dy): the target
  // is safe and, for a diagonal step, so are both cells beside the corner
  // it passes (no corner cutting), so the step's segment crosses only safe
  // cells.
  bool CanStep(int col, int row, int dx, int dy) const {
    return IsSafe(col + dx, row + dy) &&
           (dx == 0 || dy == 0 || (IsSafe(col + dx, row) && IsSafe(col, row + dy)));
  }
};

// Stamps the mask around every obstacle cell that touches a non-obstacle
// cell (the nearest obstacle of any free cell is such a cell, so the result
// is exact) and around the map border.
SafeZone ComputeSafeZone(const Grid& grid, const ImpassableAreaMask& mask);

// ---------------------------------------------------------------------------
// Stage 2: Lee wave.

struct LeeWave {
  int width = 0;
  int height = 0;
  // Reachability index: the fewest 8-connected steps from the start through
  // safe cells; -1 where the wave did not arrive (unsafe, unreachable, or
  // beyond the goal's index when the wave stopped early).
  std::vector<std::int32_t> index;
  std::int32_t goal_index = -1;  // -1: the goal is unreachable

  std::int32_t At(int col, int row) const {
    return (col >= 0 && row >= 0 && col < width && row < height)
               ? index[static_cast<std::size_t>(row) * width + col]
               : -1;
  }
};

// Breadth-first wave from `start` by SafeZone::CanStep steps; stops as soon as `goal` gets its
// index (every cell with a lower index is then final). Start and goal must be safe cells for a wave
// to run; otherwise goal_index stays -1.
LeeWave RunLeeWave(const SafeZone& zone, CellIndex start, CellIndex goal);

// ---------------------------------------------------------------------------
// Stage 3: trajectory regions.

struct TrajectoryRegion {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> in_region;  // M_tb: 1 = on some shortest path
  // For region cells: how many of the 8 neighbours are virgin (outside the
  // region or outside the map). 0 for cells outside the region.
  std::vector<std::uint8_t> virgin_neighbours;
  std::size_t cell_count = 0;

  bool In(int col, int row) const {
    return col >= 0 && row >= 0 && col < width && row < height &&
           in_region[static_cast<std::size_t>(row) * width + col] != 0;
  }
};

// The paper's backward pass: a depth-first search with a stack from the
// goal, stepping to neighbours whose index is one lower. Empty region when
// the wave did not reach the goal. `zone` is the one the wave ran on (the
// backward steps obey the same SafeZone::CanStep rule).
TrajectoryRegion MarkTrajectoryRegion(const SafeZone& zone, const LeeWave& wave, CellIndex goal);

// ---------------------------------------------------------------------------
// Stage 4: turn-and-move generation.

// One straight ray of the neighbourhood template: the distinct cells met by
// the ray at `angle_rad`, nearest first, up to D_max.
struct TemplateRay {
  double angle_rad = 0.0;
  std::vector<CellOffset> cells;
  std::vector<float> lengths;  // Euclidean length of each offset, cells
};

// The neighbourhood template of straight moves: rays at an angular step of
// at most 1 / D_max radians (so neighbouring rays are at most one cell apart
// at D_max and every cell within D_max lies on some ray, to rounding), a
// multiple of 8 rays so the axes and diagonals are exact. Built once.
struct MoveTemplate {
  double d_max_cells = 0.0;
  std::vector<TemplateRay> rays;
  std::size_t cell_count = 0;  // sum of ray lengths

  static MoveTemplate Build(double d_max_cells);
};

struct GenerationOptions {
  double d_min_cells = 0.0;  // see PlanOptions::d_min_m, in cells
  int max_extra_nodes = 2;
  double max_length_excess = 0.01;
  std::size_t max_expansions = 20000;
  std::size_t max_trajectories = 32;
};

// A trajectory in cell units: waypoints[0] is the start, back() the goal;
// each pair is one straight move.
struct CellTrajectory {
  std::vector<CellIndex> waypoints;
  double length_cells = 0.0;
  // True when it is a shortest path straightened greedily (one of the
  // region's two, or the octile-shortest path of the safe zone; added to the
  // node queue's results as alternatives) rather than a result of the queue.
  bool straightened = false;
};

// Every trajectory found (the node queue's, the region's two shortest paths
// straightened and, when the best is not the straight line, the octile-
// shortest path of the safe zone straightened), best first: fewest moves,
// then shortest, except that trajectories more than max_length_excess
// longer than the shortest found come after all the others. Each
// straight move's segment (centre to centre) only crosses safe cells.
std::vector<CellTrajectory> GenerateTrajectories(const SafeZone& zone, const LeeWave& wave,
                                                 const TrajectoryRegion& region,
                                                 const MoveTemplate& moves, CellIndex start,
                                                 CellIndex goal, const GenerationOptions& options);

// Every cell the segment between two cell centres passes through, the cells
// it only touches at a corner included (a "supercover" line).
std::vector<CellIndex> SegmentCells(CellIndex from, CellIndex to);
// True when every cell of SegmentCells(from, to) is safe.
bool SegmentIsSafe(const SafeZone& zone, CellIndex from, CellIndex to);

// ---------------------------------------------------------------------------
// The planner: templates built once per robot, then one call per request.

struct PlanCommand {
  enum class Kind { kTurn, kMove };
  Kind kind = Kind::kMove;
  double value = 0.0;  // turn: degrees, counter-clockwise positive, (-180, 180]; move: metres
};

struct PlannedTrajectory {
  std::vector<PlanCommand> commands;  // from the start heading
  std::vector<Pose2D> waypoints;      // map-frame metres; yaw = heading on arrival
  std::vector<CellIndex> cells;       // the same waypoints in cells
  double length_m = 0.0;
  bool straightened = false;
};

struct PlanRequest {
  double start_x = 0.0, start_y = 0.0;  // map-frame metres
  double start_heading_rad = 0.0;       // map frame, counter-clockwise from +x
  double goal_x = 0.0, goal_y = 0.0;    // map-frame metres
};

enum class PlanOutcome {
  kFound,
  kStartOutsideMap,
  kGoalOutsideMap,
  kStartInObstacle,  // occupied or unknown cell
  kGoalInObstacle,
  kStartUnsafe,  // free, but within d_save of an obstacle
  kGoalUnsafe,
  kUnreachable,  // no path through the safe zone
};

struct PlanStageTimes {
  double safe_zone_ms = 0.0;
  double wave_ms = 0.0;
  double regions_ms = 0.0;
  double generation_ms = 0.0;
};

struct PlanResult {
  PlanOutcome outcome = PlanOutcome::kUnreachable;
  std::string message;  // one line, for the user, when not found
  CellIndex start_cell, goal_cell;
  std::vector<PlannedTrajectory> trajectories;  // best first; empty unless kFound
  SafeZone safe_zone;
  PlanStageTimes times;

  bool found() const { return outcome == PlanOutcome::kFound; }
};

class Planner {
 public:
  // Checks the options and builds both templates for maps of the given
  // resolution (metres per cell).
  static StatusOr<Planner> Create(const PlanOptions& options, double resolution_m);

  // Plans on `grid`, whose resolution must be the one given to Create().
  StatusOr<PlanResult> Plan(const Grid& grid, const PlanRequest& request) const;

  const PlanOptions& options() const { return options_; }
  const ImpassableAreaMask& mask() const { return mask_; }
  const MoveTemplate& move_template() const { return moves_; }
  double mask_build_ms() const { return mask_build_ms_; }
  double template_build_ms() const { return template_build_ms_; }

 private:
  PlanOptions options_;
  double resolution_m_ = 0.0;
  ImpassableAreaMask mask_;
  MoveTemplate moves_;
  double mask_build_ms_ = 0.0;
  double template_build_ms_ = 0.0;
};

// Turn-and-move commands and map-frame waypoints for a cell trajectory.
PlannedTrajectory ToPlannedTrajectory(const Grid& grid, const CellTrajectory& trajectory,
                                      double start_heading_rad);

}  // namespace linemap

#endif  // LINEMAP_PLAN_H_
