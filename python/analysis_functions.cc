// linemap.lines / segment / plan / eval: the figures the CLI prints as JSON
// (`linemap lines --json`, `segment -o OUT.json`, `plan --json`,
// `eval --json`), as Python dicts, lists and numpy arrays in map-frame metres.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <chrono>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "linemap/codec.h"
#include "linemap/lines.h"
#include "linemap/lmap_vectors.h"
#include "linemap/plan.h"
#include "linemap/segmentation.h"
#include "linemap/tolerance.h"
#include "linemap/vector_layers.h"
#include "python/arrays.h"
#include "python/bindings.h"
#include "python/decode_limits.h"
#include "python/errors.h"
#include "python/map_files.h"
#include "python/map_object.h"

namespace linemap::python {

namespace {

using Clock = std::chrono::steady_clock;

double MillisecondsSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// A position (x, y) in map-frame metres as cell units of `grid`.
std::optional<CellPoint> PoseArgument(const Grid& grid, const py::object& pose) {
  if (pose.is_none()) return std::nullopt;
  const std::vector<double> xy = FiniteFloats(pose, "pose (x, y)", 2, 2);
  return RobotCellPoint(grid, xy[0], xy[1]);
}

// ---------------------------------------------------------------------------
// lines

py::array_t<double> SegmentRows(const Grid& grid, const std::vector<LineSegment>& segments) {
  std::vector<double> rows(segments.size() * 4);
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const LineSegment& s = segments[i];
    grid.CellToWorld(s.x1, s.y1, &rows[4 * i], &rows[4 * i + 1]);
    grid.CellToWorld(s.x2, s.y2, &rows[4 * i + 2], &rows[4 * i + 3]);
  }
  return ArrayOwning(std::move(rows), {static_cast<py::ssize_t>(segments.size()), 4});
}

py::dict Lines(const Map& map, const std::string& method, const std::optional<double>& epsilon,
               bool straight_walls, const py::object& pose) {
  const Grid grid = GridFromMap(map);
  LineExtractionOptions options;
  if (method == "linemap") {
    options.method = LineMethod::kLinemap;
  } else if (method == "rmline") {
    options.method = LineMethod::kRmLine;
    // The linemap extractor's options would be ignored without a word, as
    // `linemap lines --method rmline` refuses them.
    if (epsilon)
      throw py::value_error("epsilon is an option of the linemap extractor, not of rmline");
    if (straight_walls) {
      throw py::value_error("straight_walls is an option of the linemap extractor, not of rmline");
    }
  } else {
    throw py::value_error("method must be 'linemap' or 'rmline', not '" + method + "'");
  }
  if (straight_walls) options = StraightWalls(options);
  if (epsilon) {
    if (!(*epsilon >= 0.5)) throw py::value_error("epsilon must be at least 0.5 cells");
    options.epsilon_cells = *epsilon;
  }
  options.robot = PoseArgument(grid, pose);

  StatusOr<LineExtraction> extraction = InternalError("not extracted");
  LineFidelity fidelity;
  double ms = 0;
  {
    py::gil_scoped_release release;
    const Clock::time_point start = Clock::now();
    extraction = ExtractLines(grid, options);
    ms = MillisecondsSince(start);
    if (extraction.ok()) fidelity = MeasureLineFidelity(extraction->edges, extraction->segments);
  }
  const LineExtraction lines = ValueOrRaise(std::move(extraction));
  py::dict out;
  out["lines"] = lines.segments.size();
  out["displ_cm"] = fidelity.displ_ave_cells * (grid.meta.resolution * 100.0);
  out["displ_cells"] = fidelity.displ_ave_cells;
  out["displ_max_cells"] = fidelity.displ_max_cells;
  out["ms"] = ms;
  out["edge_cells"] = fidelity.edge_cells;
  out["share_within_1"] = fidelity.share_within_1;
  out["cells_left_to_blobs"] = lines.cells_left_to_blobs;
  out["segments"] = SegmentRows(grid, lines.segments);
  return out;
}

// ---------------------------------------------------------------------------
// segment

// The box's outer cell edges: (x0, y0, x1, y1) in metres, as the CLI's bbox.
py::tuple BoxTuple(const Grid& grid, const BoundingBox& box) {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  grid.CellToWorld(box.min_col - 0.5, box.min_row - 0.5, &x0, &y0);
  grid.CellToWorld(box.max_col + 0.5, box.max_row + 0.5, &x1, &y1);
  return py::make_tuple(x0, y0, x1, y1);
}

// One room as `linemap segment` writes it: with the rooms method its id,
// kind, area and width; with the paper's border its free cells, those the
// chain encloses and whether the Lee wave closed it.
py::dict RoomDict(const Grid& grid, const RoomBorder& room, bool by_rooms) {
  py::dict r;
  if (by_rooms) {
    r["id"] = room.id;
    r["kind"] = RoomKindName(room.kind);
    r["area_m2"] = room.area_m2;
    r["cells"] = room.cells;
    r["free_cells"] = room.free_cells;
    r["width_m"] = room.width_m;
  } else {
    r["free_cells"] = room.free_cells;
    r["enclosed_free_cells"] = room.enclosed_free_cells;
    r["closed_by_lee"] = room.closed_by_lee;
  }
  r["chain_cells"] = room.chain.size();
  r["chain"] = WorldPoints(grid, room.chain);
  return r;
}

// segment()'s options as `linemap segment` reads its flags: the paper's
// method when asked for or implied by a pose or paper_border, else rooms
// split at doorways (whose widths and area limit the library checks).
SegmentationOptions SegmentOptionsFor(const Grid& grid, const py::object& method_arg,
                                      const py::object& pose, const py::object& doors,
                                      const py::object& max_room_area, bool paper_border) {
  SegmentationOptions options;
  options.robot = PoseArgument(grid, pose);
  const bool implied = options.robot.has_value() || paper_border;
  std::string method = implied ? "paper" : "rooms";
  if (!method_arg.is_none()) {
    if (!py::isinstance<py::str>(method_arg)) {
      throw py::type_error("method must be \"rooms\", \"paper\" or None");
    }
    method = method_arg.cast<std::string>();
  }
  if (method != "rooms" && method != "paper") {
    throw py::value_error("method must be \"rooms\" or \"paper\", not \"" + method + "\"");
  }
  if (method == "rooms" && implied) {
    throw py::value_error("pose and paper_border need method=\"paper\"");
  }
  options.method =
      method == "paper" ? SegmentationMethod::kPaperBorder : SegmentationMethod::kRooms;
  // The rooms method's options would be ignored by the paper's (None:
  // not given, the defaults).
  if (method == "paper" && (!doors.is_none() || !max_room_area.is_none())) {
    throw py::value_error(
        std::string(!doors.is_none() ? "doors" : "max_room_area") +
        " is an option of method=\"rooms\"; method=\"paper\" (which pose and paper_border "
        "imply) has no doorways");
  }
  if (!doors.is_none()) {
    const std::vector<double> widths = FiniteFloats(doors, "doors (min, max) in metres", 2, 2);
    options.min_door_width_m = widths[0];
    options.max_door_width_m = widths[1];
  }
  if (!max_room_area.is_none()) {
    // A number, as the other float options take (a bool or a str is no area).
    if (py::isinstance<py::bool_>(max_room_area) ||
        !(py::isinstance<py::float_>(max_room_area) || py::isinstance<py::int_>(max_room_area))) {
      throw py::type_error("max_room_area must be a number of square metres or None");
    }
    options.max_room_area_m2 = max_room_area.cast<double>();
  }
  options.protect_room_interior = !paper_border;
  return options;
}

py::dict Segment(const Map& map, const py::object& method, const py::object& pose,
                 const py::object& door_widths, const py::object& max_room_area,
                 bool paper_border) {
  const Grid grid = GridFromMap(map);
  const SegmentationOptions options =
      SegmentOptionsFor(grid, method, pose, door_widths, max_room_area, paper_border);
  StatusOr<Segmentation> segmentation = InternalError("not segmented");
  {
    py::gil_scoped_release release;
    segmentation = SegmentMap(grid, options);
  }
  const Segmentation seg = ValueOrRaise(std::move(segmentation));
  const bool by_rooms = options.method == SegmentationMethod::kRooms;
  py::list rooms;
  for (const RoomBorder& room : seg.rooms) rooms.append(RoomDict(grid, room, by_rooms));
  py::list doors;
  for (const Doorway& door : seg.doors) {
    py::dict d;
    d["rooms"] = py::make_tuple(door.room_a, door.room_b);
    d["width_m"] = door.width_m;
    d["at"] = WorldPoint(grid, door.cell);
    doors.append(d);
  }
  py::list blobs;
  for (const FurnitureBlob& blob : seg.blobs) {
    py::dict b;
    if (by_rooms) b["room"] = blob.room;
    b["cell_count"] = blob.cells.size();
    b["against_wall"] = blob.against_wall;
    // Cells are in raster order, so the first is the CLI's first_cell.
    b["first_cell"] = blob.cells.empty() ? py::object(py::none()) : WorldPoint(grid, blob.cells[0]);
    b["bbox"] = BoxTuple(grid, blob.box);
    b["outline"] = WorldPoints(grid, blob.outline);
    b["cells"] = WorldPoints(grid, blob.cells);
    blobs.append(b);
  }
  py::dict out;
  out["resolution"] = grid.meta.resolution;
  out["method"] = by_rooms ? "rooms" : "paper";
  out["rooms"] = rooms;
  if (by_rooms) out["doors"] = doors;
  out["blobs"] = blobs;
  return out;
}

// ---------------------------------------------------------------------------
// plan

py::list CommandList(const PlannedTrajectory& t) {
  py::list commands;
  for (const PlanCommand& c : t.commands) {
    py::dict command;
    command[c.kind == PlanCommand::Kind::kTurn ? "turn_deg" : "move_m"] = c.value;
    commands.append(command);
  }
  return commands;
}

py::array_t<double> WaypointArray(const PlannedTrajectory& t) {
  std::vector<double> xy;
  for (const Pose2D& p : t.waypoints) xy.insert(xy.end(), {p.x, p.y});
  return ArrayOwning(std::move(xy), {static_cast<py::ssize_t>(t.waypoints.size()), 2});
}

py::dict Plan(const Map& map, const py::object& start, const py::object& goal, double robot_width,
              double robot_length, double margin, double d_min, double d_max) {
  const std::vector<double> from = FiniteFloats(start, "start (x, y[, heading])", 2, 3);
  const std::vector<double> to = FiniteFloats(goal, "goal (x, y)", 2, 2);
  PlanRequest request;
  request.start_x = from[0];
  request.start_y = from[1];
  request.start_heading_rad = from.size() > 2 ? from[2] : 0.0;
  request.goal_x = to[0];
  request.goal_y = to[1];
  PlanOptions options;
  options.robot.width_m = robot_width;
  options.robot.length_m = robot_length;
  options.robot.margin_m = margin;
  options.d_min_m = d_min;
  options.d_max_m = d_max;
  const Grid grid = GridFromMap(map);

  StatusOr<PlanResult> planned = InternalError("not planned");
  double ms = 0;
  {
    py::gil_scoped_release release;
    const Clock::time_point t0 = Clock::now();
    StatusOr<Planner> planner = Planner::Create(options, grid.meta.resolution);
    planned = planner.ok() ? planner->Plan(grid, request) : StatusOr<PlanResult>(planner.status());
    ms = MillisecondsSince(t0);
  }
  const PlanResult result = ValueOrRaise(std::move(planned));
  // A point off the map is bad input (the CLI's exit status 2); a start in
  // an obstacle or a goal out of reach is the planner's answer: a result.
  if (result.outcome == PlanOutcome::kStartOutsideMap ||
      result.outcome == PlanOutcome::kGoalOutsideMap) {
    throw py::value_error(result.message);
  }
  py::list all;
  for (const PlannedTrajectory& t : result.trajectories) {
    py::dict one;
    one["length_m"] = t.length_m;
    one["commands"] = CommandList(t);
    one["waypoints"] = WaypointArray(t);
    one["straightened"] = t.straightened;
    all.append(one);
  }
  py::dict stages;
  stages["safe_zone"] = result.times.safe_zone_ms;
  stages["wave"] = result.times.wave_ms;
  stages["regions"] = result.times.regions_ms;
  stages["generation"] = result.times.generation_ms;
  // The same keys whether found or not, so that a caller can read
  // route["commands"] before testing route["found"]: a route not found is an
  // empty one (the CLI's JSON leaves these keys out instead).
  const bool found = result.found();  // then trajectories holds at least one
  py::dict out;
  out["found"] = found;
  out["error"] = found ? py::object(py::none()) : py::str(result.message);
  out["length_m"] =
      found ? py::object(py::float_(result.trajectories.front().length_m)) : py::none();
  out["commands"] = found ? CommandList(result.trajectories.front()) : py::list();
  out["waypoints"] = WaypointArray(found ? result.trajectories.front() : PlannedTrajectory{});
  out["alternatives"] = result.trajectories.size();
  out["ms"] = ms;
  out["stages_ms"] = stages;
  out["trajectories"] = all;
  return out;
}

// ---------------------------------------------------------------------------
// eval

// A Map, or a path loaded as linemap.load() does.
Grid GridArgument(const py::object& value, const DecodeLimits& limits) {
  if (py::isinstance<Map>(value)) return GridFromMap(value.cast<const Map&>());
  const std::string path = PathArgument(value);
  StatusOr<Grid> grid = InternalError("not loaded");
  {
    py::gil_scoped_release release;
    grid = LoadMapFile(path, limits);
  }
  return ValueOrRaise(std::move(grid));
}

// The vector layers of an .lmap file; nullopt unless `decoded` is a path to
// an .lmap file.
std::optional<LmapVectors> StoredLayers(const py::object& decoded, const DecodeLimits& limits) {
  if (py::isinstance<Map>(decoded)) return std::nullopt;
  const std::string path = PathArgument(decoded);
  if (!IsLmapPath(path)) return std::nullopt;
  StatusOr<LmapVectors> vectors = InternalError("not read");
  {
    py::gil_scoped_release release;
    vectors = LoadLmapVectors(path, limits);
  }
  return ValueOrRaise(std::move(vectors));
}

// The T an .lmap file at `decoded` names (saved within a tolerance), or
// that of the file a Map was loaded from (Map.tolerance); nullopt for
// another file or map, or an exact one.
std::optional<int> NamedTolerance(const py::object& decoded, const DecodeLimits& limits) {
  if (py::isinstance<Map>(decoded)) return decoded.cast<const Map&>().tolerance;
  const std::string path = PathArgument(decoded);
  if (!IsLmapPath(path)) return std::nullopt;
  StatusOr<std::optional<int>> named = InternalError("not read");
  {
    py::gil_scoped_release release;
    named = LoadLmapToleranceCells(path, limits);
  }
  return ValueOrRaise(std::move(named));
}

// eval()'s tolerance: None, or a whole number of cells 0..kMaxToleranceCells.
std::optional<int> ToleranceArgument(const py::object& tolerance) {
  if (tolerance.is_none()) return std::nullopt;
  return ToleranceCellsArgument(tolerance);
}

py::dict Eval(const py::object& original_arg, const py::object& decoded_arg,
              const py::object& max_cells_arg, const py::object& tolerance_arg,
              const py::object& limits_arg) {
  const std::optional<int> tolerance = ToleranceArgument(tolerance_arg);
  const DecodeLimits limits = LimitsArgument(limits_arg, max_cells_arg);
  const Grid original = GridArgument(original_arg, limits);
  const Grid decoded = GridArgument(decoded_arg, limits);
  if (original.width() != decoded.width() || original.height() != decoded.height()) {
    throw py::value_error("the original is " + std::to_string(original.width()) + " x " +
                          std::to_string(original.height()) + " cells but the decoded map is " +
                          std::to_string(decoded.width()) + " x " +
                          std::to_string(decoded.height()) +
                          ": eval compares maps of the same size");
  }
  const std::optional<LmapVectors> layers = StoredLayers(decoded_arg, limits);
  // Without `tolerance`, an .lmap file saved within one is checked at the T
  // it names, as `linemap eval` does: T up to 4, maps up to the default
  // memory bound of a save within a tolerance.
  const std::optional<int> named = NamedTolerance(decoded_arg, limits);
  const bool from_file = !tolerance && named && *named <= kMaxToleranceCells &&
                         original.size() <= EncodeOptions{}.max_tolerance_cells;
  // The T the guarantees are checked at; -1 for none.
  const int check_at = tolerance ? *tolerance : from_file ? *named : -1;
  GridComparison m;
  StatusOr<LayerFidelity> fidelity = InternalError("not measured");
  std::optional<ToleranceReport> guarantees;
  {
    py::gil_scoped_release release;
    m = CompareGrids(original, decoded);
    if (layers) fidelity = MeasureLayerFidelity(original, *layers);
    if (check_at >= 0) guarantees = CheckTolerance(original, decoded, check_at);
  }
  py::dict out;
  out["same_geometry"] = m.same_geometry;
  out["cells"] = m.cells;
  out["cells_equal"] = m.cells_equal;
  out["obstacle_recall_1"] = m.obstacle_recall_1;
  out["obstacle_precision_1"] = m.obstacle_precision_1;
  out["free_iou"] = m.free_iou;
  out["leaks"] = m.leaks;
  out["unknown_turned_free"] = m.unknown_turned_free;
  out["unknown_turned_free_share"] = m.unknown_turned_free_share;
  if (layers) {
    // The same keys as `linemap eval --json`.
    const LayerFidelity& f = ValueOrRaise(std::move(fidelity));
    const auto share = [&](std::size_t n) {
      return f.edge_cells > 0 ? static_cast<double>(n) / static_cast<double>(f.edge_cells) : 1.0;
    };
    out["edge_cells"] = f.edge_cells;
    if (f.displ_ave_cells) {
      out["displ_ave_cells"] = *f.displ_ave_cells;
      // The CLI multiplies by centimetres per cell; the same order gives the
      // same last digit.
      const double cm_per_cell = original.meta.resolution * 100;
      out["displ_ave_cm"] = *f.displ_ave_cells * cm_per_cell;
      out["displ_max_cells"] = *f.displ_max_cells;
    } else {
      out["displ_ave_cells"] = py::none();
      out["displ_ave_cm"] = py::none();
      out["displ_max_cells"] = py::none();
    }
    // None without walls to be within 1 cell of, as the CLI's null.
    out["edge_share_within_1"] =
        f.displ_ave_cells ? py::object(py::float_(share(f.within_1_of_wall))) : py::none();
    out["edge_share_in_furniture"] = share(f.in_furniture);
    out["edge_share_within_1_or_furniture"] = share(f.covered);
  }
  if (guarantees) {
    VisitToleranceFigures(*guarantees, [&out](const char* key, auto value) { out[key] = value; });
    out["tolerance_from_file"] = from_file;
  }
  if (named) out["tolerance_named_cells"] = *named;
  return out;
}

}  // namespace

void BindAnalysis(py::module_& module) {
  module.def("lines", &Lines, py::arg("map"), py::arg("method") = "linemap", py::kw_only(),
             py::arg("epsilon") = py::none(), py::arg("straight_walls") = false,
             py::arg("pose") = py::none(), R"doc(
Wall line segments of ``map`` and the RM-Line paper's measures, as
``linemap lines --json``: lines, displ_cm, displ_cells, displ_max_cells, ms,
edge_cells, share_within_1, cells_left_to_blobs, plus ``segments``, an (N, 4)
float64 array x1, y1, x2, y2 in map-frame metres. ``method`` is "linemap"
(default) or "rmline"; ``epsilon`` (cells, >= 0.5; None: 1.0) the linemap
extractor's tolerance; ``straight_walls`` one segment per straight wall; both
are options of the linemap extractor, and given with "rmline" they raise
ValueError; ``pose`` (x, y) in metres floods only the robot's free space (a
point on a cell's lower or left edge is in that cell).
)doc");
  module.def("segment", &Segment, py::arg("map"), py::kw_only(), py::arg("method") = py::none(),
             py::arg("pose") = py::none(), py::arg("doors") = py::none(),
             py::arg("max_room_area") = py::none(), py::arg("paper_border") = false, R"doc(
Rooms, doorways and furniture blobs, as ``linemap segment -o OUT.json``
writes them (without its timings), in map-frame metres. Without ``pose`` the
free space is split into rooms and corridors at doorways:
{resolution, method: "rooms", rooms: [{id, kind ("room" or "corridor"),
area_m2, cells, free_cells, width_m, chain: (K, 2) closed chain of cell
centres, chain_cells}], doors: [{rooms: (id, id), width_m, at: (x, y)}],
blobs: [{room, cell_count, against_wall (a cabinet or shelf standing against
a wall, else free-standing), first_cell, bbox (x0, y0, x1, y1 cell edges),
outline: (K, 2), cells: (M, 2)}]}. With ``pose`` (x, y), the paper's border
of the robot's free component (``linemap segment --pose``): method "paper",
rooms [{free_cells, enclosed_free_cells, closed_by_lee, chain, chain_cells}],
no doors, blobs without room. Options as ``linemap segment``'s flags:
``method`` "rooms" or "paper" (default rooms, paper with ``pose`` or
``paper_border``); ``doors`` (min, max) doorway widths in metres (None: the
default (0.5, 1.2)); ``max_room_area`` square metres above which spaces
joined by a wide opening stay apart (None or 0: no limit); both are options
of the rooms method, and given with the paper's they raise ValueError;
``paper_border`` the paper's heavy border exactly (its shortest path may cut
across narrow parts of a room). Values the library refuses raise ValueError.
)doc");
  module.def("plan", &Plan, py::arg("map"), py::arg("start"), py::arg("goal"), py::kw_only(),
             py::arg("robot_width") = 0.4, py::arg("robot_length") = 0.4, py::arg("margin") = 0.05,
             py::arg("d_min") = 0.1, py::arg("d_max") = 5.0, R"doc(
A turn-and-move trajectory from ``start`` (x, y[, heading]) to ``goal``
(x, y), metres and radians, as ``linemap plan --json``: found, length_m,
commands ([{"turn_deg": d} | {"move_m": m}]), waypoints ((K, 2) array),
alternatives, ms, stages_ms, trajectories (every trajectory, best first)
and error (None). A start or goal in an obstacle or too close to one, or a
goal that cannot be reached, is no exception: found is False, error says
why, length_m is None, commands and trajectories are empty lists,
waypoints a (0, 2) array and stages_ms 0 for the stages that did not run
(the dict has the same keys either way). Robot size, margin and the
shortest / longest move are in metres; options the planner refuses, and a
start or goal outside the map, raise ValueError (the CLI's exit status 2).
)doc");
  module.def("eval", &Eval, py::arg("original"), py::arg("decoded"), py::kw_only(),
             py::arg("max_cells") = py::none(), py::arg("tolerance") = py::none(),
             py::arg("limits") = py::none(), R"doc(
The quality figures of ``decoded`` against ``original``, as
``linemap eval --json``. Each is a Map or a path (loaded as load() does);
when ``decoded`` is the path of an .lmap file with vector layers, also
edge_cells, displ_ave_cells, displ_ave_cm, displ_max_cells and the
edge_share_* figures. With ``tolerance`` (cells, 0..4) also the guarantees
of a save within that tolerance, as ``linemap eval --tolerance T --json``:
the Hausdorff distances both ways, the wall surface kept, free cells moved
or lost beyond T, unknown turned free beyond T, leaks and splits, sampled
and local plans that disagree, and tolerance_holds; with ``tolerance`` None,
an .lmap file saved within a tolerance, or a Map loaded from one
(``Map.tolerance``), is checked at the T it names (then
``tolerance_from_file`` is True). ``tolerance_named_cells`` is the T such
a file names, whether checked at it or not (``tolerance`` given, a T above
4, a map over 2^26 cells).
``max_cells`` and
``limits`` as for load(). Maps of different sizes raise ValueError.
)doc");
}

}  // namespace linemap::python
