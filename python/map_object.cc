#include "python/map_object.h"

#include <climits>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "linemap/map_io.h"
#include "linemap/occupancy_grid.h"
#include "python/arrays.h"
#include "python/errors.h"
#include "python/pickling.h"

namespace linemap::python {

namespace {

constexpr std::uint8_t kLargestCellValue = static_cast<std::uint8_t>(Cell::kUnknown);

// The first cell (in grid-row order) whose value is not a Cell, if any.
std::optional<std::pair<CellIndex, std::uint8_t>> FirstBadCell(const py::array& cells) {
  const auto view = py::reinterpret_borrow<py::array_t<std::uint8_t>>(cells).unchecked<2>();
  for (py::ssize_t r = 0; r < view.shape(0); ++r) {
    for (py::ssize_t c = 0; c < view.shape(1); ++c) {
      if (view(r, c) > kLargestCellValue) {
        return std::make_pair(CellIndex{static_cast<int>(c), static_cast<int>(r)}, view(r, c));
      }
    }
  }
  return std::nullopt;
}

void CheckCellValues(const py::array& cells) {
  if (const auto bad = FirstBadCell(cells)) {
    throw py::value_error("Map.cells[" + std::to_string(bad->first.row) + ", " +
                          std::to_string(bad->first.col) + "] is " + std::to_string(bad->second) +
                          ": cells must be linemap.FREE (0), OCCUPIED (1) or UNKNOWN (2)");
  }
}

void CheckResolution(double resolution) {
  if (!(resolution > 0) || !std::isfinite(resolution)) {
    throw py::value_error("resolution must be a positive finite number of metres per cell, not " +
                          std::to_string(resolution));
  }
}

Pose2D OriginArgument(const py::handle& origin) {
  const std::vector<double> v = FiniteFloats(origin, "origin (x, y[, yaw])", 2, 3);
  return Pose2D{v[0], v[1], v.size() > 2 ? v[2] : 0.0};
}

py::tuple OriginTuple(const Pose2D& origin) {
  return py::make_tuple(origin.x, origin.y, origin.yaw);
}

// A width or height argument: an int in 0 .. 2^32-1 (the message's uint32).
std::uint32_t DimensionArgument(const py::handle& value, const char* name) {
  if (!py::isinstance<py::int_>(value) || py::isinstance<py::bool_>(value)) {
    throw py::type_error(std::string(name) + " must be an int");
  }
  const auto v = py::reinterpret_borrow<py::int_>(value);
  if (v < py::int_(0) || v > py::int_(std::numeric_limits<std::uint32_t>::max())) {
    throw py::value_error(std::string(name) + " must be in 0 .. 2^32-1");
  }
  return v.cast<std::uint32_t>();
}

// The message's data: an int8 numpy array of width * height values (flat or
// (height, width)), or a sequence of ints in -128..127 (rospy's tuple,
// rclpy's array.array('b')). Other numpy dtypes are refused, not converted.
std::vector<std::int8_t> OccupancyData(const py::handle& data, std::uint32_t width,
                                       std::uint32_t height) {
  const py::module_ numpy = py::module_::import("numpy");
  py::array values;
  if (py::isinstance<py::array>(data)) {
    if (!py::isinstance<py::array_t<std::int8_t>>(data)) {
      throw py::type_error("occupancy grid data must have dtype int8, not " +
                           py::str(data.attr("dtype")).cast<std::string>());
    }
    values = py::reinterpret_borrow<py::array>(data);
  } else {
    values = numpy.attr("asarray")(data);
    const char kind = values.dtype().kind();
    if (values.size() > 0 && kind != 'i' && kind != 'u') {
      throw py::type_error("occupancy grid data must be int8 values (-1 unknown, 0..100)");
    }
    if (values.size() > 0 && (py::int_(numpy.attr("min")(values)) < py::int_(-128) ||
                              py::int_(numpy.attr("max")(values)) > py::int_(127))) {
      throw py::value_error("occupancy grid data must lie in -128..127 (int8)");
    }
    values = values.attr("astype")(numpy.attr("int8"));
  }
  const std::uint64_t cells = std::uint64_t{width} * height;
  const bool flat = values.ndim() == 1 && static_cast<std::uint64_t>(values.shape(0)) == cells;
  const bool rows = values.ndim() == 2 && static_cast<std::uint64_t>(values.shape(0)) == height &&
                    static_cast<std::uint64_t>(values.shape(1)) == width;
  if (!flat && !rows) {
    throw py::value_error("occupancy grid data has shape " +
                          py::str(values.attr("shape")).cast<std::string>() + ", expected (" +
                          std::to_string(cells) + ",) or (" + std::to_string(height) + ", " +
                          std::to_string(width) + ")");
  }
  const auto contiguous = py::array_t<std::int8_t, py::array::c_style>::ensure(values);
  std::vector<std::int8_t> out(cells);
  if (cells > 0) std::memcpy(out.data(), contiguous.data(), cells);
  return out;
}

Map FromOccupancyGrid(const py::handle& data, const py::handle& width, const py::handle& height,
                      double resolution, const py::handle& origin, double occupied_thresh,
                      double free_thresh, const py::object& max_cells) {
  OccupancyGridMessage message;
  message.width = DimensionArgument(width, "width");
  message.height = DimensionArgument(height, "height");
  // load()'s default (MapLoadOptions), so that a message is refused at the
  // size a map file is.
  const std::uint64_t limit = MaxCellsArgument(max_cells, MapLoadOptions{}.max_cells);
  // Checked before the data are copied (a 2^30-cell message is 1 GB), as
  // GridFromOccupancyGrid words it.
  if (std::uint64_t{message.width} * message.height > limit) {
    RaiseStatus(OverLimitError(Limit::kCells, "occupancy grid: " + std::to_string(message.width) +
                                                  " x " + std::to_string(message.height) +
                                                  " cells exceed the limit of " +
                                                  std::to_string(limit) + " (max_cells)"));
  }
  message.resolution = static_cast<float>(resolution);
  const Pose2D pose = OriginArgument(origin);
  message.origin_x = pose.x;
  message.origin_y = pose.y;
  message.origin_orientation = QuaternionFromYaw(pose.yaw);
  message.data = OccupancyData(data, message.width, message.height);
  const OccupancyThresholds thresholds{occupied_thresh, free_thresh};
  return MapFromGrid(ValueOrRaise(GridFromOccupancyGrid(message, thresholds, limit)));
}

py::dict ToOccupancyGrid(const Map& map, const std::string& frame_id) {
  OccupancyGridMessage message = OccupancyGridFromGrid(GridFromMap(map), frame_id);
  const Quaternion& q = message.origin_orientation;
  py::dict out;
  out["frame_id"] = message.frame_id;
  out["width"] = message.width;
  out["height"] = message.height;
  out["resolution"] = static_cast<double>(message.resolution);
  out["origin"] = OriginTuple(map.meta.origin);
  out["orientation"] = py::make_tuple(q.x, q.y, q.z, q.w);
  const auto size = static_cast<py::ssize_t>(message.data.size());
  out["data"] = ArrayOwning(std::move(message.data), {size});
  return out;
}

// Both thresholds at once (one at a time, a move from one valid pair to
// another could pass through an invalid one), with the rule of the CLI's
// threshold options (format/ros_map.cc, ApplyOverrides).
void SetThresholds(Map& map, double occupied, double free) {
  const auto in_range = [](double t) { return std::isfinite(t) && t >= 0.0 && t <= 1.0; };
  if (!in_range(occupied) || !in_range(free)) {
    throw py::value_error("thresholds must be in 0..1, not occupied_thresh " +
                          py::repr(py::float_(occupied)).cast<std::string>() + ", free_thresh " +
                          py::repr(py::float_(free)).cast<std::string>());
  }
  if (!(free < occupied)) {
    throw py::value_error("free_thresh " + py::repr(py::float_(free)).cast<std::string>() +
                          " must be below occupied_thresh " +
                          py::repr(py::float_(occupied)).cast<std::string>());
  }
  map.meta.occupied_thresh = occupied;
  map.meta.free_thresh = free;
}

// Pickled as a dict of the cells (numpy pickles the array) and every
// metadata field, so that a map sent to a worker process saves the same
// YAML there.
py::dict MapState(const Map& map) {
  py::dict state;
  state["cells"] = map.cells;
  state["resolution"] = map.meta.resolution;
  state["origin"] = OriginTuple(map.meta.origin);
  state["mode"] = MapModeName(map.meta.mode);
  state["negate"] = map.meta.negate;
  state["occupied_thresh"] = map.meta.occupied_thresh;
  state["free_thresh"] = map.meta.free_thresh;
  state["tolerance"] = map.tolerance ? py::object(py::int_(*map.tolerance)) : py::none();
  state["simplified_without_tolerance"] = map.simplified_without_tolerance;
  return state;
}

MapMode ModeFromName(const std::string& name) {
  if (std::optional<MapMode> mode = MapModeFromName(name)) return *mode;
  throw py::value_error("cannot unpickle a linemap.Map of mode '" + name +
                        "': modes are 'trinary', 'scale' and 'raw'");
}

// Unpickling checks the state as the constructor and the properties check
// their arguments: a pickle is input like any other.
Map MapFromState(const py::dict& state) {
  for (const char* key :
       {"cells", "resolution", "origin", "mode", "negate", "occupied_thresh", "free_thresh"}) {
    if (!state.contains(key)) {
      throw py::value_error(std::string("cannot unpickle a linemap.Map without '") + key + "'");
    }
  }
  const py::object cells = state["cells"];
  CheckCellsArray(cells);
  Map map;
  map.cells = py::reinterpret_borrow<py::array>(cells);
  CheckCellValues(map.cells);
  map.meta.resolution = state["resolution"].cast<double>();
  CheckResolution(map.meta.resolution);
  map.meta.origin = OriginArgument(state["origin"]);
  map.meta.mode = ModeFromName(state["mode"].cast<std::string>());
  map.meta.negate = state["negate"].cast<bool>();
  // As an .lmap header holds them: finite, in any order (load() keeps a
  // YAML's pair as map_server reads it, even one set_thresholds() refuses).
  for (const char* key : {"occupied_thresh", "free_thresh"}) {
    if (!std::isfinite(state[key].cast<double>())) {
      throw py::value_error(std::string("cannot unpickle a linemap.Map whose ") + key +
                            " is not finite");
    }
  }
  map.meta.occupied_thresh = state["occupied_thresh"].cast<double>();
  map.meta.free_thresh = state["free_thresh"].cast<double>();
  // Pickles made before maps kept their tolerance have no such key.
  if (state.contains("tolerance") && !state["tolerance"].is_none()) {
    const py::object t = state["tolerance"];
    if (!py::isinstance<py::int_>(t) || py::isinstance<py::bool_>(t) || t < py::int_(1) ||
        t > py::int_(INT_MAX)) {
      throw py::value_error(
          "cannot unpickle a linemap.Map whose tolerance is not None or a "
          "whole number of cells from 1");
    }
    map.tolerance = t.cast<int>();
  }
  if (state.contains("simplified_without_tolerance")) {
    map.simplified_without_tolerance = state["simplified_without_tolerance"].cast<bool>();
  }
  return map;
}

std::string Repr(const Map& map) {
  const Pose2D& o = map.meta.origin;
  return "<linemap.Map " + std::to_string(map.cells.shape(1)) + " x " +
         std::to_string(map.cells.shape(0)) + " cells, " +
         py::repr(py::float_(map.meta.resolution)).cast<std::string>() + " m/cell, origin (" +
         py::repr(py::float_(o.x)).cast<std::string>() + ", " +
         py::repr(py::float_(o.y)).cast<std::string>() + ", " +
         py::repr(py::float_(o.yaw)).cast<std::string>() + ")>";
}

}  // namespace

void CheckCellsArray(const py::handle& cells) {
  if (!py::isinstance<py::array>(cells)) {
    throw py::type_error("cells must be a numpy array of dtype uint8, not " +
                         py::str(py::type::of(cells)).cast<std::string>());
  }
  if (!py::isinstance<py::array_t<std::uint8_t>>(cells)) {
    throw py::type_error("cells must have dtype uint8, not " +
                         py::str(cells.attr("dtype")).cast<std::string>() +
                         " (values linemap.FREE, OCCUPIED, UNKNOWN)");
  }
  const auto array = py::reinterpret_borrow<py::array>(cells);
  if (array.ndim() != 2) {
    throw py::value_error("cells must be 2-D (height, width), not " + std::to_string(array.ndim()) +
                          "-D");
  }
  if (array.shape(0) > std::numeric_limits<int>::max() ||
      array.shape(1) > std::numeric_limits<int>::max()) {
    throw py::value_error("cells: height and width must be below 2^31");
  }
}

Map MapFromGrid(Grid grid) {
  const int width = grid.width();
  const int height = grid.height();
  std::vector<Cell> cells = std::move(grid.mutable_cells());
  auto* owned = new std::vector<Cell>(std::move(cells));
  py::capsule owner(owned, [](void* p) { delete static_cast<std::vector<Cell>*>(p); });
  static_assert(sizeof(Cell) == sizeof(std::uint8_t));
  Map map;
  map.cells =
      py::array_t<std::uint8_t>({static_cast<py::ssize_t>(height), static_cast<py::ssize_t>(width)},
                                reinterpret_cast<const std::uint8_t*>(owned->data()), owner);
  map.meta = grid.meta;
  return map;
}

Grid GridFromMap(const Map& map) {
  CheckCellsArray(map.cells);
  CheckCellValues(map.cells);
  const auto cells = py::reinterpret_borrow<py::array_t<std::uint8_t>>(map.cells);
  const auto view = cells.unchecked<2>();
  Grid grid(static_cast<int>(view.shape(1)), static_cast<int>(view.shape(0)));
  std::vector<Cell>& out = grid.mutable_cells();
  if (cells.flags() & py::array::c_style) {
    if (!out.empty()) std::memcpy(out.data(), cells.data(), out.size());
  } else {  // a strided view, e.g. a slice: element by element
    for (py::ssize_t r = 0; r < view.shape(0); ++r) {
      for (py::ssize_t c = 0; c < view.shape(1); ++c) {
        out[grid.Index(static_cast<int>(c), static_cast<int>(r))] = static_cast<Cell>(view(r, c));
      }
    }
  }
  grid.meta = map.meta;
  return grid;
}

void BindMap(py::module_& module) {
  py::class_<Map> cls(module, "Map", R"doc(
A trinary occupancy grid in the map frame.

``cells`` is a numpy ``uint8`` array of shape (height, width); row 0 is the
row at the map origin (the bottom of the map image), as in
nav_msgs/OccupancyGrid. Values are ``linemap.FREE`` (0), ``OCCUPIED`` (1) and
``UNKNOWN`` (2). ``resolution`` is in metres per cell, ``origin`` is the pose
(x, y, yaw) of the lower-left corner of cell (0, 0) in metres and radians.
)doc");
  cls.def(py::init([](const py::object& cells, double resolution, const py::object& origin) {
            CheckCellsArray(cells);
            CheckResolution(resolution);
            Map map;
            map.cells = py::reinterpret_borrow<py::array>(cells);
            CheckCellValues(map.cells);
            map.meta.resolution = resolution;
            map.meta.origin = OriginArgument(origin);
            return map;
          }),
          py::arg("cells"), py::arg("resolution") = kDefaultResolution,
          py::arg("origin") = py::make_tuple(0.0, 0.0, 0.0),
          "Map(cells, resolution=0.05, origin=(0, 0, 0)). `cells` is kept, not copied; "
          "an array of another dtype raises TypeError, of another shape or with values "
          "other than 0, 1, 2 ValueError. An array of 0 rows or columns is a map of no "
          "cells, as the library's Grid: save() writes it as .lmap, not as .yaml.")
      .def_property(
          "cells", [](const Map& map) { return map.cells; },
          [](Map& map, const py::object& cells) {
            CheckCellsArray(cells);
            CheckCellValues(py::reinterpret_borrow<py::array>(cells));
            map.cells = py::reinterpret_borrow<py::array>(cells);
          },
          "(height, width) uint8 array, row 0 at the origin; values FREE, OCCUPIED, UNKNOWN.")
      .def_property_readonly(
          "width", [](const Map& map) { return map.cells.shape(1); }, "cells per row")
      .def_property_readonly(
          "height", [](const Map& map) { return map.cells.shape(0); }, "rows")
      .def_property(
          "resolution", [](const Map& map) { return map.meta.resolution; },
          [](Map& map, double resolution) {
            CheckResolution(resolution);
            map.meta.resolution = resolution;
          },
          "metres per cell (> 0)")
      .def_property(
          "origin", [](const Map& map) { return OriginTuple(map.meta.origin); },
          [](Map& map, const py::object& origin) { map.meta.origin = OriginArgument(origin); },
          "(x, y, yaw): pose of the lower-left corner of cell (0, 0), metres and radians")
      .def_property_readonly(
          "occupied_thresh", [](const Map& map) { return map.meta.occupied_thresh; },
          "occupancy probability at or above which a YAML's pixel is occupied: the value of "
          "the YAML or .lmap file the map was loaded from, else map_saver's 0.65. Metadata "
          "only (the cells are not classified again); set_thresholds() changes it. An .lmap "
          "file stores it; a .yaml save writes it only when map_saver's grey values "
          "(0, 254, 205) read back as free, occupied and unknown under the pair, else "
          "map_saver's 0.65 / 0.196.")
      .def_property_readonly(
          "free_thresh", [](const Map& map) { return map.meta.free_thresh; },
          "occupancy probability at or below which a YAML's pixel is free: as "
          "occupied_thresh, map_saver's 0.196 by default")
      .def_property_readonly(
          "negate", [](const Map& map) { return map.meta.negate; },
          "the YAML's negate as loaded (False for a Map made from cells); an .lmap file "
          "stores it, a .yaml save writes False (its PGM holds map_saver's grey values)")
      .def_property_readonly(
          "mode", [](const Map& map) { return std::string(MapModeName(map.meta.mode)); },
          "the YAML's mode as loaded: 'trinary' (for a Map made from cells too), 'scale' or "
          "'raw'; an .lmap file stores it, a .yaml save writes 'trinary'")
      .def_property_readonly(
          "tolerance",
          [](const Map& map) {
            return map.tolerance ? py::object(py::int_(*map.tolerance)) : py::none();
          },
          "cells: the T of the .lmap file (or bytes) the map was loaded from when it was "
          "saved within a tolerance (its cells are the robot's map simplified within T, whose "
          "guarantees hold against that map); None for an exact file and any other map. "
          "save() and encode() keep it: the file is the map's cells, marked as simplified "
          "within T (info()'s tolerance), and a tolerance= above 0 raises ValueError; a "
          ".yaml save has no place for it.")
      .def("set_thresholds", &SetThresholds, py::arg("occupied_thresh"), py::arg("free_thresh"),
           "Sets both thresholds, checked as the CLI's --occupied-thresh / --free-thresh are: "
           "each in 0..1 and free_thresh below occupied_thresh, else ValueError (and the map "
           "keeps its pair).")
      .def("to_occupancy_grid", &ToOccupancyGrid, py::arg("frame_id") = "map", R"doc(
The map as nav_msgs/OccupancyGrid fields (map_server's trinary convention):
a dict with ``data`` (flat int8 array, row 0 at the origin; free 0,
occupied 100, unknown -1), ``width``, ``height``, ``resolution`` (the
message's float32 value), ``origin`` (x, y, yaw), ``orientation`` (the yaw
as a quaternion x, y, z, w) and ``frame_id``.
)doc")
      .def_static("from_occupancy_grid", &FromOccupancyGrid, py::arg("data"), py::arg("width"),
                  py::arg("height"), py::arg("resolution"),
                  py::arg("origin") = py::make_tuple(0.0, 0.0, 0.0), py::kw_only(),
                  py::arg("occupied_thresh") = OccupancyThresholds{}.occupied,
                  py::arg("free_thresh") = OccupancyThresholds{}.free,
                  py::arg("max_cells") = py::none(), R"doc(
A map from nav_msgs/OccupancyGrid fields, read as map_saver reads them: a
value v in 0..100 is free when v <= free_thresh * 100, occupied when
v >= occupied_thresh * 100, else unknown; -1 and values outside 0..100 are
unknown. ``data`` is an int8 numpy array of width * height values (flat or
(height, width)), or a sequence of ints (msg.data); ``origin`` is (x, y[, yaw])
in metres and radians. Another dtype raises TypeError; a wrong size, a
resolution that is not positive or an origin that is not finite ValueError;
more than ``max_cells`` cells (default 2^30, as load()) MemoryError, before
the data are copied.
)doc")
      .def("__repr__", &Repr);
  cls.def(py::pickle(&MapState, &MapFromState));
  ReduceAsProtocolTwoAtLeast(cls);
}

}  // namespace linemap::python
