// linemap plan MAP --from X,Y[,HEADING] --to X,Y: a turn-and-move trajectory
// (Kosteley et al., section 3.2 D) in map-frame metres, as text, JSON or SVG.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "format/file_io.h"
#include "linemap/plan.h"
#include "tools/linemap/commands.h"
#include "tools/linemap/json.h"
#include "tools/linemap/map_input.h"

namespace linemap::cli {

const CommandSpec kPlanSpec = {
    "plan",
    "MAP_OR_LMAP --from X,Y[,HEADING] --to X,Y [--robot-width W --robot-length L --margin M "
    "--dmin A --dmax B] [--json] [--svg OUT.svg]",
    "plan a turn-and-move trajectory on a map",
    "Positions are map-frame metres; HEADING is the robot's start heading in radians\n"
    "(counter-clockwise from the map's +x axis, default 0). Start and goal snap to the\n"
    "centre of their cell. The safe zone keeps the robot centre farther than\n"
    "d_save = max(W/2, L/2) + M from every occupied or unknown cell and from the map\n"
    "edge. Every trajectory found is printed, best first: fewest moves, then\n"
    "shortest, except that one more than 1 % longer than the shortest found\n"
    "comes after all the others (fewer turns win only near-ties). Besides the\n"
    "planner's own trajectories, the shortest paths straightened (marked\n"
    "'straightened') are candidates too; they keep --dmax and the safe zone but\n"
    "not --dmin. Commands are `turn <degrees>` (positive = left) and\n"
    "`move <metres>`.\n"
    "A start or goal outside the map is bad input (exit code 2); one in an obstacle,\n"
    "too close to one, or a goal that cannot be reached gives a message and exit\n"
    "code 1.",
    WithMapLoadOptions({
        {"--from", "X,Y[,HEADING]", "start position in metres, heading in radians (default 0)"},
        {"--to", "X,Y", "goal position in metres"},
        {"--robot-width", "W", "robot width in metres (default 0.4)"},
        {"--robot-length", "L", "robot length in metres (default 0.4)"},
        {"--margin", "M", "extra turning margin d_extra in metres (default 0.05)"},
        {"--dmin", "A",
         "shortest straight move in metres, except the last and in straightened paths "
         "(default 0.1)"},
        {"--dmax", "B", "longest straight move in metres (default 5.0)"},
        {"--json", "",
         "print one JSON object: found, error, length_m, commands, waypoints, "
         "alternatives, ms, stages_ms, and every trajectory (the same keys when "
         "none is found: error says why, length_m null, the lists empty)"},
        {"--svg", "OUT.svg",
         "draw the map, the safe zone and the trajectories as SVG (the name ends in .svg; "
         "written also when the goal cannot be reached, without trajectories)"},
    }),
    1,
    1,
};

namespace {

using Clock = std::chrono::steady_clock;

StatusOr<PlanOptions> OptionsFrom(const ParsedArgs& args) {
  PlanOptions o;
  LINEMAP_ASSIGN_OR_RETURN(o.robot.width_m, args.GetDouble("--robot-width", o.robot.width_m));
  LINEMAP_ASSIGN_OR_RETURN(o.robot.length_m, args.GetDouble("--robot-length", o.robot.length_m));
  LINEMAP_ASSIGN_OR_RETURN(o.robot.margin_m, args.GetDouble("--margin", o.robot.margin_m));
  LINEMAP_ASSIGN_OR_RETURN(o.d_min_m, args.GetDouble("--dmin", o.d_min_m));
  LINEMAP_ASSIGN_OR_RETURN(o.d_max_m, args.GetDouble("--dmax", o.d_max_m));
  return o;
}

StatusOr<PlanRequest> RequestFrom(const ParsedArgs& args) {
  if (!args.Get("--from") || !args.Get("--to")) {
    return InvalidArgumentError("--from X,Y[,HEADING] and --to X,Y are required");
  }
  LINEMAP_ASSIGN_OR_RETURN(std::vector<double> from, args.GetDoubleList("--from", 2, 3));
  LINEMAP_ASSIGN_OR_RETURN(std::vector<double> to, args.GetDoubleList("--to", 2));
  PlanRequest q;
  q.start_x = from[0];
  q.start_y = from[1];
  q.start_heading_rad = from.size() > 2 ? from[2] : 0.0;
  q.goal_x = to[0];
  q.goal_y = to[1];
  for (double v : {q.start_x, q.start_y, q.start_heading_rad, q.goal_x, q.goal_y}) {
    if (!std::isfinite(v)) return InvalidArgumentError("--from and --to need finite numbers");
  }
  return q;
}

std::string CommandsJson(const PlannedTrajectory& t) {
  std::string out = "[";
  for (const PlanCommand& c : t.commands) {
    if (out.size() > 1) out += ",";
    out += c.kind == PlanCommand::Kind::kTurn ? "{\"turn_deg\":" : "{\"move_m\":";
    out += JsonNumber(c.value) + "}";
  }
  return out + "]";
}

std::string WaypointsJson(const PlannedTrajectory& t) {
  std::string out = "[";
  for (const Pose2D& p : t.waypoints) {
    if (out.size() > 1) out += ",";
    out += "[" + JsonNumber(p.x) + "," + JsonNumber(p.y) + "]";
  }
  return out + "]";
}

std::string ResultJson(const PlanResult& r, double ms) {
  JsonObject json;
  // The same keys whether found or not, as the Python module's plan(): a
  // script reads "commands" before testing "found".
  json.Add("found", r.found());
  if (r.found()) {
    json.AddRaw("error", "null");
  } else {
    json.Add("error", r.message);
  }
  const PlannedTrajectory none;
  const PlannedTrajectory& best = r.found() ? r.trajectories.front() : none;
  std::string all = "[";
  for (const PlannedTrajectory& t : r.trajectories) {
    if (all.size() > 1) all += ",";
    JsonObject one;
    one.Add("length_m", t.length_m)
        .AddRaw("commands", CommandsJson(t))
        .AddRaw("waypoints", WaypointsJson(t))
        .Add("straightened", t.straightened);
    all += one.str();
  }
  all += "]";
  JsonObject stages;
  stages.Add("safe_zone", r.times.safe_zone_ms)
      .Add("wave", r.times.wave_ms)
      .Add("regions", r.times.regions_ms)
      .Add("generation", r.times.generation_ms);
  if (r.found()) {
    json.Add("length_m", best.length_m);
  } else {
    json.AddRaw("length_m", "null");
  }
  json.AddRaw("commands", CommandsJson(best))
      .AddRaw("waypoints", WaypointsJson(best))
      .Add("alternatives", static_cast<std::uint64_t>(r.trajectories.size()))
      .Add("ms", ms)
      .AddRaw("stages_ms", stages.str())
      .AddRaw("trajectories", all);
  return json.str();
}

void PrintText(const PlanResult& r, double ms) {
  std::printf("trajectories: %zu (best first), %.2f ms\n", r.trajectories.size(), ms);
  for (std::size_t i = 0; i < r.trajectories.size(); ++i) {
    const PlannedTrajectory& t = r.trajectories[i];
    std::printf("trajectory %zu: %zu moves, %.3f m%s\n", i + 1, t.waypoints.size() - 1, t.length_m,
                t.straightened ? " (straightened shortest path of the region)" : "");
    for (const PlanCommand& c : t.commands) {
      if (c.kind == PlanCommand::Kind::kTurn) {
        std::printf("  turn %.2f\n", c.value);
      } else {
        std::printf("  move %.3f\n", c.value);
      }
    }
    std::printf("  waypoints:");
    for (const Pose2D& p : t.waypoints) std::printf(" %.3f,%.3f", p.x, p.y);
    std::printf("\n");
  }
}

// One <rect> per horizontal run of cells of the same class; SVG y grows
// downwards, so grid row r is drawn at y = height - 1 - r.
std::string SvgRuns(const Grid& grid, const SafeZone& zone) {
  const auto klass = [&](int c, int r) {
    const Cell cell = grid.at(c, r);
    if (cell == Cell::kOccupied) return 0;
    if (cell == Cell::kUnknown) return 1;
    return zone.IsSafe(c, r) ? 3 : 2;
  };
  static const char* kFill[4] = {"#222", "#bbb", "#f4c7c3", "#e6f4ea"};
  std::string out;
  char buf[160];
  for (int r = 0; r < grid.height(); ++r) {
    int c = 0;
    while (c < grid.width()) {
      const int k = klass(c, r);
      int end = c + 1;
      while (end < grid.width() && klass(end, r) == k) ++end;
      std::snprintf(buf, sizeof(buf),
                    "<rect x=\"%d\" y=\"%d\" width=\"%d\" height=\"1\" fill=\"%s\"/>\n", c,
                    grid.height() - 1 - r, end - c, kFill[k]);
      out += buf;
      c = end;
    }
  }
  return out;
}

std::string SvgPath(const Grid& grid, const PlannedTrajectory& t, const char* colour,
                    double width) {
  std::string points;
  char buf[64];
  for (const CellIndex& c : t.cells) {
    std::snprintf(buf, sizeof(buf), "%d.5,%d.5 ", c.col, grid.height() - 1 - c.row);
    points += buf;
  }
  std::snprintf(buf, sizeof(buf), "\" fill=\"none\" stroke=\"%s\" stroke-width=\"%g\"/>\n", colour,
                width);
  return "<polyline points=\"" + points + buf;
}

std::string Svg(const Grid& grid, const PlanResult& r) {
  char head[256];
  std::snprintf(head, sizeof(head),
                "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 %d %d\" width=\"%d\" "
                "height=\"%d\" shape-rendering=\"crispEdges\">\n",
                grid.width(), grid.height(), grid.width() * 2, grid.height() * 2);
  std::string svg = head;
  svg +=
      "<!-- dark: occupied, grey: unknown, pink: free but unsafe, green: safe zone; "
      "blue: best trajectory, orange: alternatives -->\n";
  svg += SvgRuns(grid, r.safe_zone);
  for (std::size_t i = r.trajectories.size(); i-- > 1;) {
    svg += SvgPath(grid, r.trajectories[i], "#f29900", 0.4);
  }
  if (!r.trajectories.empty()) svg += SvgPath(grid, r.trajectories.front(), "#1a73e8", 0.8);
  for (const CellIndex& c : {r.start_cell, r.goal_cell}) {
    char buf[128];
    std::snprintf(buf, sizeof(buf), "<circle cx=\"%d.5\" cy=\"%d.5\" r=\"1.5\" fill=\"%s\"/>\n",
                  c.col, grid.height() - 1 - c.row, c == r.start_cell ? "#188038" : "#d93025");
    svg += buf;
  }
  return svg + "</svg>\n";
}

}  // namespace

int RunPlan(const std::vector<std::string>& args) {
  int exit_code = kExitOk;
  std::optional<ParsedArgs> parsed = ParseArgs(kPlanSpec, args, &exit_code);
  if (!parsed) return exit_code;
  if (std::optional<std::string> svg = parsed->Get("--svg")) {
    Status named = CheckOutputExtension(*svg, {".svg"}, "SVG");
    // Before the plan, not after it.
    if (named.ok()) named = CheckOutputWritable(*svg);
    if (!named.ok()) return ReportError("plan", named);
  }
  StatusOr<PlanRequest> request = RequestFrom(*parsed);
  if (!request.ok()) return ReportError("plan", request.status());
  StatusOr<PlanOptions> options = OptionsFrom(*parsed);
  if (!options.ok()) return ReportError("plan", options.status());
  const std::string& map_path = parsed->positional[0];
  StatusOr<Grid> grid = LoadMapArgument(map_path, *parsed);
  if (!grid.ok()) return ReportError("plan", grid.status());

  const Clock::time_point t0 = Clock::now();
  StatusOr<Planner> planner = Planner::Create(*options, grid->meta.resolution);
  if (!planner.ok()) return ReportError("plan", planner.status());
  StatusOr<PlanResult> result = planner->Plan(*grid, *request);
  if (!result.ok()) return ReportError("plan", result.status().WithContext("'" + map_path + "'"));
  const double ms = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();

  if (parsed->Get("--svg") && result->outcome != PlanOutcome::kStartOutsideMap &&
      result->outcome != PlanOutcome::kGoalOutsideMap) {
    const std::string svg_path = *parsed->Get("--svg");
    Status written = WriteFileAtomic(svg_path, Svg(*grid, *result));
    if (!written.ok()) return ReportError("plan", written);  // it names the file
  }
  if (parsed->Has("--json")) std::printf("%s\n", ResultJson(*result, ms).c_str());
  if (!result->found()) {
    std::fprintf(stderr, "linemap plan: '%s': %s\n", map_path.c_str(), result->message.c_str());
    // A point off the map is bad input, as a --pose off the map is for
    // encode and segment; a start in an obstacle or a goal out of reach is
    // the planner's answer about this map.
    const bool off_map = result->outcome == PlanOutcome::kStartOutsideMap ||
                         result->outcome == PlanOutcome::kGoalOutsideMap;
    return off_map ? kExitBadInput : kExitFailure;
  }
  if (!parsed->Has("--json")) PrintText(*result, ms);
  return kExitOk;
}

}  // namespace linemap::cli
