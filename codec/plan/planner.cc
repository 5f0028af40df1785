// The trajectory planner of Kosteley et al., section 3.2 D, end to end: the
// two templates are built once per robot (Table 1 stages 5 and 9), each
// call runs safe zone, Lee wave, trajectory regions and generation (stages
// 6, 7, 8 and 10) and turns the cell trajectories into turn-and-move
// commands in map-frame metres.
//
// Start and goal snap to the cell that holds them; the waypoints are cell
// centres. Headings are map-frame radians, counter-clockwise from +x; turns
// are in degrees in (-180, 180], positive to the left; a zero turn is not
// emitted.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "linemap/plan.h"

namespace linemap {
namespace {

using Clock = std::chrono::steady_clock;

double MsSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// Angle in (-pi, pi].
double WrapAngle(double a) {
  a = std::remainder(a, 2.0 * std::numbers::pi);
  if (a <= -std::numbers::pi) a += 2.0 * std::numbers::pi;
  return a;
}

bool Finite(double v) { return std::isfinite(v); }

Status CheckOptions(const PlanOptions& o, double resolution_m) {
  const RobotFootprint& r = o.robot;
  if (!Finite(resolution_m) || resolution_m <= 0) {
    return InvalidArgumentError("map resolution must be > 0 m/cell");
  }
  if (!Finite(r.width_m) || r.width_m <= 0)
    return InvalidArgumentError("robot width must be > 0 m");
  if (!Finite(r.length_m) || r.length_m <= 0) {
    return InvalidArgumentError("robot length must be > 0 m");
  }
  if (!Finite(r.margin_m) || r.margin_m < 0) {
    return InvalidArgumentError("turning margin must be >= 0 m");
  }
  if (!Finite(o.d_max_m) || o.d_max_m <= 0) return InvalidArgumentError("D_max must be > 0 m");
  if (!Finite(o.d_min_m) || o.d_min_m < 0 || o.d_min_m > o.d_max_m) {
    return InvalidArgumentError("D_min must be >= 0 m and <= D_max");
  }
  if (o.d_max_m / resolution_m > 500.0) {
    return InvalidArgumentError("D_max must be at most 500 cells (" +
                                std::to_string(500.0 * resolution_m) + " m at this resolution)");
  }
  if (o.max_extra_nodes < 0) return InvalidArgumentError("max_extra_nodes must be >= 0");
  if (!Finite(o.max_length_excess) || o.max_length_excess < 0) {
    return InvalidArgumentError("max_length_excess must be >= 0");
  }
  return Status::Ok();
}

// Where a map-frame point falls, and whether the planner may use it.
PlanOutcome CheckEndpoint(const Grid& grid, const SafeZone& zone, double x, double y, bool is_start,
                          CellIndex* cell) {
  // The cell whose square holds the point, as the edge map and the line
  // extractor round (a point on the map's lower edge is in).
  const std::optional<CellIndex> holding = grid.CellHolding(x, y);
  if (!holding) return is_start ? PlanOutcome::kStartOutsideMap : PlanOutcome::kGoalOutsideMap;
  *cell = *holding;
  if (grid.at(cell->col, cell->row) != Cell::kFree) {
    return is_start ? PlanOutcome::kStartInObstacle : PlanOutcome::kGoalInObstacle;
  }
  if (!zone.IsSafe(cell->col, cell->row)) {
    return is_start ? PlanOutcome::kStartUnsafe : PlanOutcome::kGoalUnsafe;
  }
  return PlanOutcome::kFound;
}

std::string OutcomeMessage(PlanOutcome outcome, const PlanRequest& q, double d_save_m) {
  char where[128];
  const bool start = outcome == PlanOutcome::kStartOutsideMap ||
                     outcome == PlanOutcome::kStartInObstacle ||
                     outcome == PlanOutcome::kStartUnsafe;
  std::snprintf(where, sizeof(where), "%s %.3f,%.3f", start ? "start" : "goal",
                start ? q.start_x : q.goal_x, start ? q.start_y : q.goal_y);
  switch (outcome) {
    case PlanOutcome::kFound:
      return "";
    case PlanOutcome::kStartOutsideMap:
    case PlanOutcome::kGoalOutsideMap:
      return std::string(where) + " is outside the map";
    case PlanOutcome::kStartInObstacle:
    case PlanOutcome::kGoalInObstacle:
      return std::string(where) + " is in an obstacle (occupied or unknown cell)";
    case PlanOutcome::kStartUnsafe:
    case PlanOutcome::kGoalUnsafe: {
      char text[96];
      std::snprintf(text, sizeof(text),
                    " is within the safe distance d_save = %.3f m of an obstacle, an "
                    "unknown cell or the map's edge",
                    d_save_m);
      return std::string(where) + text;
    }
    case PlanOutcome::kUnreachable:
      return "the goal cannot be reached from the start through the safe zone";
  }
  return "";
}

}  // namespace

StatusOr<Planner> Planner::Create(const PlanOptions& options, double resolution_m) {
  LINEMAP_RETURN_IF_ERROR(CheckOptions(options, resolution_m));
  Planner planner;
  planner.options_ = options;
  planner.resolution_m_ = resolution_m;
  Clock::time_point t = Clock::now();
  planner.mask_ = ImpassableAreaMask::Build(SafeDistanceMetres(options.robot) / resolution_m);
  planner.mask_build_ms_ = MsSince(t);
  t = Clock::now();
  planner.moves_ = MoveTemplate::Build(options.d_max_m / resolution_m);
  planner.template_build_ms_ = MsSince(t);
  return planner;
}

StatusOr<PlanResult> Planner::Plan(const Grid& grid, const PlanRequest& request) const {
  if (std::abs(grid.meta.resolution - resolution_m_) > 1e-9 * resolution_m_) {
    return InvalidArgumentError("the map's resolution differs from the planner's");
  }
  if (!Finite(request.start_heading_rad))
    return InvalidArgumentError("start heading is not finite");
  PlanResult result;
  Clock::time_point t = Clock::now();
  result.safe_zone = ComputeSafeZone(grid, mask_);
  result.times.safe_zone_ms = MsSince(t);

  const double d_save_m = SafeDistanceMetres(options_.robot);
  for (bool is_start : {true, false}) {
    const PlanOutcome outcome =
        CheckEndpoint(grid, result.safe_zone, is_start ? request.start_x : request.goal_x,
                      is_start ? request.start_y : request.goal_y, is_start,
                      is_start ? &result.start_cell : &result.goal_cell);
    if (outcome != PlanOutcome::kFound) {
      result.outcome = outcome;
      result.message = OutcomeMessage(outcome, request, d_save_m);
      return result;
    }
  }

  t = Clock::now();
  const LeeWave wave = RunLeeWave(result.safe_zone, result.start_cell, result.goal_cell);
  result.times.wave_ms = MsSince(t);
  t = Clock::now();
  const TrajectoryRegion region = MarkTrajectoryRegion(result.safe_zone, wave, result.goal_cell);
  result.times.regions_ms = MsSince(t);
  t = Clock::now();
  GenerationOptions generation;
  generation.d_min_cells = options_.d_min_m / resolution_m_;
  generation.max_extra_nodes = options_.max_extra_nodes;
  generation.max_length_excess = options_.max_length_excess;
  generation.max_expansions = options_.max_expansions;
  generation.max_trajectories = options_.max_trajectories;
  const std::vector<CellTrajectory> found = GenerateTrajectories(
      result.safe_zone, wave, region, moves_, result.start_cell, result.goal_cell, generation);
  result.times.generation_ms = MsSince(t);

  if (found.empty()) {
    result.outcome = PlanOutcome::kUnreachable;
    result.message = OutcomeMessage(PlanOutcome::kUnreachable, request, d_save_m);
    return result;
  }
  result.outcome = PlanOutcome::kFound;
  for (const CellTrajectory& trajectory : found) {
    result.trajectories.push_back(ToPlannedTrajectory(grid, trajectory, request.start_heading_rad));
  }
  return result;
}

PlannedTrajectory ToPlannedTrajectory(const Grid& grid, const CellTrajectory& trajectory,
                                      double start_heading_rad) {
  PlannedTrajectory out;
  out.cells = trajectory.waypoints;
  out.straightened = trajectory.straightened;
  double heading = WrapAngle(start_heading_rad);
  for (std::size_t i = 0; i < trajectory.waypoints.size(); ++i) {
    Pose2D pose;
    grid.CellToWorld(trajectory.waypoints[i].col, trajectory.waypoints[i].row, &pose.x, &pose.y);
    if (i > 0) {
      const Pose2D& prev = out.waypoints.back();
      const double dx = pose.x - prev.x, dy = pose.y - prev.y;
      const double bearing = std::atan2(dy, dx);
      const double turn_deg = WrapAngle(bearing - heading) * 180.0 / std::numbers::pi;
      if (std::abs(turn_deg) > 1e-9) out.commands.push_back({PlanCommand::Kind::kTurn, turn_deg});
      const double distance = std::hypot(dx, dy);
      out.commands.push_back({PlanCommand::Kind::kMove, distance});
      out.length_m += distance;
      heading = bearing;
    }
    pose.yaw = heading;
    out.waypoints.push_back(pose);
  }
  return out;
}

}  // namespace linemap
