// linemap.load / save / convert / encode / decode / vectors / room_at: maps
// and .lmap files.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <climits>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "format/file_io.h"
#include "format/iso_time.h"
#include "linemap/codec.h"
#include "linemap/lmap_vectors.h"
#include "linemap/map_io.h"
#include "python/arrays.h"
#include "python/bindings.h"
#include "python/decode_limits.h"
#include "python/errors.h"
#include "python/map_files.h"
#include "python/map_object.h"

namespace linemap::python {

namespace {

std::vector<std::uint8_t> BytesArgument(const py::handle& data) {
  if (!PyObject_CheckBuffer(data.ptr()) || py::isinstance<py::str>(data)) {
    throw py::type_error("expected bytes, bytearray or memoryview");
  }
  const py::buffer_info info = py::reinterpret_borrow<py::buffer>(data).request();
  if (info.itemsize != 1 || info.ndim != 1 || info.strides[0] != 1) {
    throw py::type_error("expected a contiguous buffer of bytes");
  }
  const auto* begin = static_cast<const std::uint8_t*>(info.ptr);
  return std::vector<std::uint8_t>(begin, begin + info.size);
}

// linemap.encode()'s keywords as the library's options (tolerance 0: an
// exact file).
EncodeOptions EncodeOptionsFor(int tolerance, bool vectors, bool straight_walls, bool compact,
                               std::uint64_t max_tolerance_cells) {
  EncodeOptions options;
  options.tolerance_cells = tolerance;
  options.max_tolerance_cells = max_tolerance_cells;
  options.vector_layers = vectors;
  options.straight_walls = straight_walls;
  options.compact = compact;
  return options;
}

// metadata=: the format's metadata keys (spec/format.md 4.3) as info()
// returns them, each a str: creator, time (ISO 8601, checked as `linemap
// encode --time` checks it), frame_id, robot_pose ("x y yaw", metres and
// radians, or a sequence of 2 or 3 numbers). `tolerance` is the encoder's
// to write (tolerance=); other keys are refused rather than dropped.
void ApplyMetadataArgument(const py::object& metadata, EncodeOptions* options) {
  if (metadata.is_none()) return;
  if (!py::isinstance<py::dict>(metadata)) {
    throw py::type_error("metadata must be a dict of str (creator, time, frame_id, robot_pose)");
  }
  for (const auto& [key, value] : py::reinterpret_borrow<py::dict>(metadata)) {
    if (!py::isinstance<py::str>(key)) throw py::type_error("metadata keys must be str");
    const std::string name = key.cast<std::string>();
    const std::string what = "metadata['" + name + "']";
    if (name == "robot_pose" && !py::isinstance<py::str>(value)) {
      const std::vector<double> pose = FiniteFloats(value, what.c_str(), 2, 3);
      options->robot_pose = Pose2D{pose[0], pose[1], pose.size() > 2 ? pose[2] : 0.0};
      continue;
    }
    if (name == "tolerance") {
      throw py::value_error("metadata['tolerance'] is written by the encoder: give tolerance=");
    }
    if (name != "creator" && name != "time" && name != "frame_id" && name != "robot_pose") {
      throw py::value_error("metadata key '" + name +
                            "' is none of creator, time, frame_id, robot_pose");
    }
    if (!py::isinstance<py::str>(value)) throw py::type_error(what + " must be a str");
    const std::string text = value.cast<std::string>();
    if (name == "creator") options->creator = text;
    if (name == "frame_id") options->frame_id = text;
    if (name == "time") {
      const Status iso = CheckIso8601Time(what, text);
      if (!iso.ok()) throw py::value_error(iso.message());
      options->time = text;
    }
    if (name == "robot_pose") {
      double x = 0, y = 0, yaw = 0;
      char rest = 0;
      // sscanf would stop at a NUL and drop what follows it.
      const int n = text.find('\0') != std::string::npos
                        ? 0
                        : std::sscanf(text.c_str(), "%lf %lf %lf %c", &x, &y, &yaw, &rest);
      if ((n != 2 && n != 3) || !std::isfinite(x) || !std::isfinite(y) || !std::isfinite(yaw)) {
        throw py::value_error(what + " must be \"x y yaw\" or \"x y\" (metres, radians), not '" +
                              text + "'");
      }
      options->robot_pose = Pose2D{x, y, n == 3 ? yaw : 0.0};
    }
  }
}

// (col0, row0, col1, row1): four whole numbers, as LoadLmapRegion takes
// them.
CellWindow WindowCellsArgument(const py::handle& window) {
  const char* kWhat = "window_cells must be four whole numbers (col0, row0, col1, row1)";
  if (!py::isinstance<py::sequence>(window) || py::isinstance<py::str>(window) ||
      py::isinstance<py::bytes>(window)) {
    throw py::type_error(kWhat);
  }
  const auto items = py::reinterpret_borrow<py::sequence>(window);
  if (items.size() != 4) throw py::value_error(kWhat);
  int v[4];
  for (std::size_t i = 0; i < 4; ++i) {
    const py::handle item = items[i];
    if (py::isinstance<py::float_>(item) || py::isinstance<py::bool_>(item) ||
        !PyIndex_Check(item.ptr())) {
      throw py::type_error(kWhat);
    }
    int overflow = 0;
    const long long x = PyLong_AsLongLongAndOverflow(
        py::int_(py::reinterpret_borrow<py::object>(item)).ptr(), &overflow);
    if (overflow != 0 || x < INT_MIN || x > INT_MAX) {
      throw py::value_error("window_cells: a value is out of range");
    }
    v[i] = static_cast<int>(x);
  }
  return {v[0], v[1], v[2], v[3]};
}

// What the file a map was loaded from says of its cells, kept on the Map.
void SetFidelity(const LmapFidelity& fidelity, Map* map) {
  map->tolerance = fidelity.tolerance;
  map->simplified_without_tolerance = !fidelity.exact && !fidelity.tolerance;
}

Map Load(const py::object& path_arg, const py::object& max_cells_arg,
         const py::object& window_cells_arg, const py::object& limits_arg) {
  const std::string path = PathArgument(path_arg);
  const DecodeLimits limits = LimitsArgument(limits_arg, max_cells_arg);
  std::optional<CellWindow> window;
  if (!window_cells_arg.is_none()) {
    window = WindowCellsArgument(window_cells_arg);
    if (!IsLmapFile(path)) {
      throw py::value_error("'" + path +
                            "': window_cells needs an .lmap file (a map image is "
                            "read whole: load it and slice Map.cells)");
    }
  }
  StatusOr<LoadedMap> loaded = InvalidArgumentError("not loaded");
  {
    py::gil_scoped_release release;
    loaded = LoadMapAndTolerance(path, window, limits);
  }
  LoadedMap map_file = ValueOrRaise(std::move(loaded));
  Map map = MapFromGrid(std::move(map_file.grid));
  SetFidelity(map_file.fidelity, &map);
  return map;
}

// max_tolerance_cells: a whole number of cells, 0 for no limit (as
// EncodeOptions::max_tolerance_cells).
std::uint64_t MaxToleranceCellsArgument(const py::object& value) {
  if (!py::isinstance<py::int_>(value) || py::isinstance<py::bool_>(value)) {
    throw py::type_error("max_tolerance_cells must be an int (cells; 0 for no limit)");
  }
  if (value < py::int_(0)) throw py::value_error("max_tolerance_cells must be at least 0");
  if (value > py::int_(UINT64_MAX)) {
    throw py::value_error("max_tolerance_cells must be below 2^64");
  }
  return value.cast<std::uint64_t>();
}

// A map YAML + PGM is always the exact trinary image: an .lmap option away
// from its default would be dropped without a word, so it is refused.
void CheckNoLmapOptions(const std::string& path, int tolerance, bool vectors, bool straight_walls,
                        bool compact, std::uint64_t max_tolerance_cells,
                        const py::object& metadata) {
  const EncodeOptions defaults;
  std::vector<std::string> given;
  if (tolerance != 0) given.push_back("tolerance");
  if (vectors != defaults.vector_layers) given.push_back("vectors");
  if (straight_walls != defaults.straight_walls) given.push_back("straight_walls");
  if (compact != defaults.compact) given.push_back("compact");
  if (max_tolerance_cells != defaults.max_tolerance_cells) given.push_back("max_tolerance_cells");
  if (!metadata.is_none()) given.push_back("metadata");
  if (given.empty()) return;
  std::string names;
  for (const std::string& name : given) names += (names.empty() ? "" : ", ") + name;
  throw py::value_error("'" + path + "': " + names + (given.size() == 1 ? " applies" : " apply") +
                        " to .lmap files only (a map .yaml is saved exact, as YAML + PGM)");
}

// A map loaded from a file saved within T cells is saved with its cells
// exact and the file marked as simplified within T (lossless flag clear,
// T named), as `linemap encode` saves such an .lmap again; within another
// tolerance it is refused: the guarantees against the robot's map would not
// add up.
void KeepToleranceOf(const Map& map, EncodeOptions* options) {
  if (map.simplified_without_tolerance) {
    throw py::value_error(
        "this map was loaded from a file whose cells are not the robot's map but which names "
        "no tolerance (written before files named their T, or a lossy 1.0 file): a copy "
        "could not say which guarantees hold against the original map; save the original "
        "map");
  }
  if (!map.tolerance) return;
  if (options->tolerance_cells > 0) {
    throw py::value_error("this map was loaded from a file saved within a tolerance of " +
                          std::to_string(*map.tolerance) +
                          " cells: saving it within another tolerance would not keep the "
                          "guarantees against the original map; save the original map with "
                          "tolerance=");
  }
  options->simplified_within_cells = *map.tolerance;
}

// An output named only by its extension ("maps/.yaml") would be written as
// a hidden file; the CLI refuses such names too.
void CheckNameBeforeExtension(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  const std::string base = slash == std::string::npos ? path : path.substr(slash + 1);
  const std::size_t dot = base.find_last_of('.');
  if (dot == 0) {
    throw py::value_error("'" + path + "': no file name before " + base + ": give one, as in 'map" +
                          base + "'");
  }
}

void Save(const py::object& path_arg, const Map& map, const py::object& tolerance_arg, bool vectors,
          bool straight_walls, bool compact, const py::object& max_tolerance_cells_arg,
          const py::object& metadata) {
  const int tolerance = ToleranceCellsArgument(tolerance_arg);
  const std::uint64_t max_tolerance_cells = MaxToleranceCellsArgument(max_tolerance_cells_arg);
  const std::string path = PathArgument(path_arg);
  const bool yaml = IsYamlPath(path);
  if (!yaml && !HasLmapName(path)) {
    throw py::value_error("'" + path + "': linemap.save writes .lmap or map .yaml files");
  }
  CheckNameBeforeExtension(path);
  if (yaml) {
    CheckNoLmapOptions(path, tolerance, vectors, straight_walls, compact, max_tolerance_cells,
                       metadata);
  }
  EncodeOptions options =
      EncodeOptionsFor(tolerance, vectors, straight_walls, compact, max_tolerance_cells);
  ApplyMetadataArgument(metadata, &options);
  if (!yaml) KeepToleranceOf(map, &options);
  const Grid grid = GridFromMap(map);
  // A map of no cells is a valid .lmap file (the format's width and height
  // may be 0), but not a map image: PGM and map_server need a pixel.
  if (yaml && grid.empty()) {
    throw py::value_error("'" + path + "': cannot save a map of " + std::to_string(grid.width()) +
                          " x " + std::to_string(grid.height()) +
                          " cells as YAML + PGM: a map image has at least one row and one "
                          "column (save an empty map as .lmap)");
  }
  Status saved;
  {
    py::gil_scoped_release release;
    saved = yaml ? SaveRosMap(path, grid) : SaveLmap(path, grid, options);
  }
  if (!saved.ok()) {
    RaiseWriteStatus(saved, yaml ? std::vector<std::string>{SavedImagePath(path), path}
                                 : std::vector<std::string>{path});
  }
}

void Convert(const py::object& source_arg, const py::object& path_arg,
             const py::object& tolerance_arg, bool vectors, bool straight_walls, bool compact,
             const py::object& max_tolerance_cells_arg, const py::object& metadata) {
  const int tolerance = ToleranceCellsArgument(tolerance_arg);
  const std::uint64_t max_tolerance_cells = MaxToleranceCellsArgument(max_tolerance_cells_arg);
  const std::string source = PathArgument(source_arg);
  const std::string path = PathArgument(path_arg);
  if (!HasLmapName(path)) {
    throw py::value_error("'" + path + "': linemap.convert writes .lmap files");
  }
  CheckNameBeforeExtension(path);
  EncodeOptions options =
      EncodeOptionsFor(tolerance, vectors, straight_walls, compact, max_tolerance_cells);
  ApplyMetadataArgument(metadata, &options);
  bool lmap_source = false;
  StatusOr<LmapSaveSummary> saved = InvalidArgumentError("not saved");
  {
    py::gil_scoped_release release;
    lmap_source = IsLmapFile(source);
    if (!lmap_source) {
      saved = SaveRosMapAsLmap(source, path, options);
    }
  }
  if (lmap_source) {
    throw py::value_error("'" + source +
                          "': linemap.convert reads a map YAML or a PGM / PNG image, not .lmap "
                          "files; re-encode an .lmap file with save(path, load(source), ...)");
  }
  if (!saved.ok()) RaiseWriteStatus(saved.status(), {path});
}

py::bytes Encode(const Map& map, const py::object& tolerance_arg, bool vectors, bool straight_walls,
                 bool compact, const py::object& max_tolerance_cells_arg,
                 const py::object& metadata) {
  const int tolerance = ToleranceCellsArgument(tolerance_arg);
  const std::uint64_t max_tolerance_cells = MaxToleranceCellsArgument(max_tolerance_cells_arg);
  EncodeOptions options =
      EncodeOptionsFor(tolerance, vectors, straight_walls, compact, max_tolerance_cells);
  ApplyMetadataArgument(metadata, &options);
  KeepToleranceOf(map, &options);
  const Grid grid = GridFromMap(map);
  StatusOr<std::vector<std::uint8_t>> bytes = InvalidArgumentError("not encoded");
  {
    py::gil_scoped_release release;
    bytes = EncodeLmap(grid, options);
  }
  const std::vector<std::uint8_t> out = ValueOrRaise(std::move(bytes));
  return py::bytes(reinterpret_cast<const char*>(out.data()), out.size());
}

Map Decode(const py::object& data, const py::object& max_cells_arg, const py::object& limits_arg) {
  const DecodeLimits limits = LimitsArgument(limits_arg, max_cells_arg);
  const std::vector<std::uint8_t> bytes = BytesArgument(data);
  StatusOr<Grid> grid = InvalidArgumentError("not decoded");
  LmapFidelity fidelity;
  {
    py::gil_scoped_release release;
    grid = DecodeLmap(bytes, limits);
    if (grid.ok()) fidelity = FidelityOfLmapBytes(bytes, limits);
  }
  Map map = MapFromGrid(ValueOrRaise(std::move(grid)));
  SetFidelity(fidelity, &map);
  return map;
}

// The walls' consecutive point pairs as (N, 4) rows x1, y1, x2, y2 (metres).
py::array_t<double> WallSegments(const Grid& frame, const std::vector<WallPolyline>& walls) {
  std::vector<double> rows;
  for (const WallPolyline& wall : walls) {
    for (std::size_t i = 0; i + 1 < wall.points.size(); ++i) {
      double x1 = 0, y1 = 0, x2 = 0, y2 = 0;
      frame.CellToWorld(wall.points[i].col, wall.points[i].row, &x1, &y1);
      frame.CellToWorld(wall.points[i + 1].col, wall.points[i + 1].row, &x2, &y2);
      rows.insert(rows.end(), {x1, y1, x2, y2});
    }
  }
  const auto n = static_cast<py::ssize_t>(rows.size() / 4);
  return ArrayOwning(std::move(rows), {n, 4});
}

py::dict VectorsDict(const LmapVectors& v) {
  Grid frame;  // carries the metadata for CellToWorld
  frame.meta = v.meta;
  py::list polylines;
  for (const WallPolyline& wall : v.walls) polylines.append(WorldPoints(frame, wall.points));
  py::list rooms;
  for (const RoomOutline& room : v.rooms) {
    py::dict r;
    r["id"] = room.id;
    r["kind"] = RoomKindName(room.kind);
    r["outline"] = WorldPoints(frame, room.chain);
    rooms.append(r);
  }
  py::list furniture;
  for (const FurnitureObject& object : v.furniture) {
    py::dict f;
    f["id"] = object.id;
    f["room_id"] = object.room_id < 0 ? py::object(py::none()) : py::int_(object.room_id);
    f["outline"] = WorldPoints(frame, object.outline);
    furniture.append(f);
  }
  py::dict out;
  out["version"] = py::make_tuple(v.major, v.minor);
  out["width"] = v.width;
  out["height"] = v.height;
  out["resolution"] = v.meta.resolution;
  out["origin"] = py::make_tuple(v.meta.origin.x, v.meta.origin.y, v.meta.origin.yaw);
  out["walls"] = WallSegments(frame, v.walls);
  out["wall_polylines"] = polylines;
  // Each polyline's index among the whole file's walls, as `linemap export
  // --window` numbers them: a window's walls keep the ids a viewer knows.
  std::vector<std::int64_t> wall_ids(v.walls.size());
  for (std::size_t i = 0; i < wall_ids.size(); ++i) {
    wall_ids[i] = static_cast<std::int64_t>(v.WallIndex(i));
  }
  const auto walls = static_cast<py::ssize_t>(wall_ids.size());
  out["wall_ids"] = ArrayOwning(std::move(wall_ids), {walls});
  out["rooms"] = rooms;
  out["furniture"] = furniture;
  return out;
}

// The library's .lmap readers by source, .lmap bytes or a path, so that one
// template serves both (Decode* and Load* differ only in their name).
StatusOr<LmapVectors> ReadVectors(const std::vector<std::uint8_t>& bytes,
                                  const std::optional<CellWindow>& window,
                                  const DecodeLimits& limits) {
  return window ? DecodeLmapVectorsInWindow(bytes, *window, limits)
                : DecodeLmapVectors(bytes, limits);
}
StatusOr<LmapVectors> ReadVectors(const std::string& path, const std::optional<CellWindow>& window,
                                  const DecodeLimits& limits) {
  return window ? LoadLmapVectorsInWindow(path, *window, limits) : LoadLmapVectors(path, limits);
}
// Runs `read` on the source (the bytes of a buffer, else a path) without
// the GIL.
template <typename Read>
auto ReadSource(const py::object& source, const Read& read) {
  if (PyObject_CheckBuffer(source.ptr())) {
    const std::vector<std::uint8_t> bytes = BytesArgument(source);
    py::gil_scoped_release release;
    return read(bytes);
  }
  const std::string path = PathArgument(source);
  py::gil_scoped_release release;
  return read(path);
}

py::dict Vectors(const py::object& source, const py::object& max_cells_arg,
                 const py::object& window_cells_arg, const py::object& limits_arg) {
  const DecodeLimits limits = LimitsArgument(limits_arg, max_cells_arg);
  std::optional<CellWindow> window;
  if (!window_cells_arg.is_none()) window = WindowCellsArgument(window_cells_arg);
  StatusOr<LmapVectors> vectors =
      ReadSource(source, [&](const auto& file) { return ReadVectors(file, window, limits); });
  return VectorsDict(ValueOrRaise(std::move(vectors)));
}

struct RoomAtPoint {
  LmapHeader header;  // the frame of the room's outline
  std::optional<LmapRoom> room;
};

// The room at map-frame metres (x, y) of the .lmap `bytes`: the cell whose
// square holds the point (CellHoldingPoint). A point off the map is an
// invalid argument naming it (and `name`, the file, when not empty).
StatusOr<RoomAtPoint> ReadRoomAtPoint(const std::vector<std::uint8_t>& bytes, double x, double y,
                                      const DecodeLimits& limits, const std::string& name) {
  RoomAtPoint out;
  LINEMAP_ASSIGN_OR_RETURN(out.header, DecodeLmapHeader(bytes, limits));
  const std::optional<CellIndex> cell =
      CellHoldingPoint(out.header.meta, out.header.width, out.header.height, x, y);
  if (!cell) {
    char text[160];
    std::snprintf(text, sizeof(text), "room_at: (%g, %g) m lies outside the map's %d x %d cells", x,
                  y, out.header.width, out.header.height);
    return InvalidArgumentError(text + (name.empty() ? "" : " ('" + name + "')"));
  }
  LINEMAP_ASSIGN_OR_RETURN(out.room, DecodeLmapRoomAt(bytes, *cell, limits));
  return out;
}
StatusOr<RoomAtPoint> ReadRoomAtPoint(const std::vector<std::uint8_t>& bytes, double x, double y,
                                      const DecodeLimits& limits) {
  return ReadRoomAtPoint(bytes, x, y, limits, "");
}
// A path is read once: its header and its room come from the same bytes,
// even when a map is saved over the file meanwhile.
StatusOr<RoomAtPoint> ReadRoomAtPoint(const std::string& path, double x, double y,
                                      const DecodeLimits& limits) {
  LINEMAP_ASSIGN_OR_RETURN(std::vector<std::uint8_t> bytes,
                           ReadFileBytes(path, limits.max_file_bytes));
  StatusOr<RoomAtPoint> read = ReadRoomAtPoint(bytes, x, y, limits, path);
  if (!read.ok() && read.status().message().find("'" + path + "'") == std::string::npos) {
    return read.status().WithContext("'" + path + "'");
  }
  return read;
}

py::object RoomAt(const py::object& source, double x, double y, const py::object& max_cells_arg,
                  const py::object& limits_arg) {
  const DecodeLimits limits = LimitsArgument(limits_arg, max_cells_arg);
  StatusOr<RoomAtPoint> read =
      ReadSource(source, [&](const auto& file) { return ReadRoomAtPoint(file, x, y, limits); });
  RoomAtPoint found = ValueOrRaise(std::move(read));
  if (!found.room) return py::none();
  Grid frame;  // the whole map's, which the outline's cells are in
  frame.meta = found.header.meta;
  const CellWindow& w = found.room->window;
  py::dict out;
  out["id"] = found.room->room.id;
  out["kind"] = RoomKindName(found.room->room.kind);
  out["outline"] = WorldPoints(frame, found.room->room.chain);
  out["window_cells"] = py::make_tuple(w.col0, w.row0, w.col1, w.row1);
  Map map = MapFromGrid(std::move(found.room->grid));
  // The room's cells are the file's, and keep what the file says of them.
  const LmapHeader& header = found.header;
  SetFidelity({header.lossless, ToleranceCellsOf(header.major, header.lossless, header.metadata)},
              &map);
  out["map"] = map;
  return out;
}

StatusOr<LmapHeader> ReadLmapHeaderFrom(const std::vector<std::uint8_t>& bytes,
                                        const DecodeLimits& limits) {
  return DecodeLmapHeader(bytes, limits);
}
StatusOr<LmapHeader> ReadLmapHeaderFrom(const std::string& path, const DecodeLimits& limits) {
  return LoadLmapHeader(path, limits);
}

// What `linemap info --json` says of a file's frame and fidelity, read from
// its header and metadata only (no layers, no cells).
py::dict Info(const py::object& source, const py::object& limits_arg) {
  const DecodeLimits limits = LimitsArgument(limits_arg, py::none());
  StatusOr<LmapHeader> read =
      ReadSource(source, [&](const auto& file) { return ReadLmapHeaderFrom(file, limits); });
  const LmapHeader header = ValueOrRaise(std::move(read));
  py::dict out;
  out["version"] = std::to_string(header.major) + "." + std::to_string(header.minor);
  out["width"] = header.width;
  out["height"] = header.height;
  out["resolution"] = header.meta.resolution;
  out["origin"] =
      py::make_tuple(header.meta.origin.x, header.meta.origin.y, header.meta.origin.yaw);
  out["lossless"] = header.lossless;
  const std::optional<int> tolerance =
      ToleranceCellsOf(header.major, header.lossless, header.metadata);
  out["tolerance"] = tolerance ? py::object(py::int_(*tolerance)) : py::object(py::none());
  // Metadata is not validated UTF-8: bytes that are not become U+FFFD.
  const auto text = [](const std::string& bytes) {
    PyObject* decoded =
        PyUnicode_DecodeUTF8(bytes.data(), static_cast<Py_ssize_t>(bytes.size()), "replace");
    if (decoded == nullptr) throw py::error_already_set();
    return py::reinterpret_steal<py::str>(decoded);
  };
  py::dict metadata;  // a repeated key keeps its last value
  for (const auto& [key, value] : header.metadata) metadata[text(key)] = text(value);
  out["metadata"] = metadata;
  return out;
}

}  // namespace

void BindIo(py::module_& module) {
  module.def("load", &Load, py::arg("path"), py::arg("max_cells") = py::none(),
             py::arg("window_cells") = py::none(), py::kw_only(), py::arg("limits") = py::none(),
             R"doc(
Loads a map: an .lmap file (by its name or its signature), a ROS map YAML
naming its image, or a bare PGM / PNG image (0.05 m/cell, origin 0, map_server's
thresholds). ``max_cells`` (default 2^30) refuses larger maps before they are
allocated (MemoryError). ``limits`` (a DecodeLimits) sets every limit of the
.lmap decoder, max_cells among them (give one or the other); lower them for
files from elsewhere. ``window_cells=(col0, row0, col1, row1)`` loads only
the cells of columns col0..col1-1 and rows row0..row1-1 of an .lmap file
(row 0 at the origin), as a map whose origin is the window's lower-left
corner: only the tiles and the layer sections that reach the window are
decoded (a 1 % window of a 282-Mcell map in about 20 ms). A window that is
empty or reaches past the map raises ValueError. A missing file raises FileNotFoundError, an
unreadable one OSError, a corrupt or malformed one ValueError; the message
names the file.
)doc");
  const py::int_ default_max_tolerance_cells(EncodeOptions{}.max_tolerance_cells);
  module.def("save", &Save, py::arg("path"), py::arg("map"), py::arg("tolerance") = 0,
             py::arg("vectors") = true, py::arg("straight_walls") = false,
             py::arg("compact") = false,
             py::arg("max_tolerance_cells") = default_max_tolerance_cells, py::kw_only(),
             py::arg("metadata") = py::none(), R"doc(
Saves ``map`` atomically (temporary file, fsync, rename): as .lmap when
``path`` ends in .lmap, as map_saver's trinary YAML + PGM (same stem, .pgm)
when it ends in .yaml or .yml, extensions in any case; other names raise
ValueError. A map of 0 rows or columns saves as .lmap (the format allows it)
but raises ValueError for a .yaml path (a map image has at least one
pixel). The other options apply to .lmap files only: given other than their
defaults with a .yaml path, they raise ValueError naming them. ``tolerance`` (cells) is how far the decoded
map may differ from ``map``; 0 is exact. ``vectors`` stores the vector
layers (walls, rooms, furniture) besides the cells.
``straight_walls`` draws one wall segment per straight wall (smaller exact
files, walls farther from the wall cells) instead of walls that follow the
pixel steps; files saved within a tolerance always draw straight walls.
``compact`` codes the cells for size (as ``linemap encode --compact``;
version 2.3): on the bench corpus about 4.5 % smaller files (8.5 % with
vectors=False) that decode in about 3x the time at the median (3.0 against 1.1
ms in the last bench; a median 4.8x per map, up to 9.2x).
``max_tolerance_cells`` (cells; 0 for no limit) refuses a save within a
tolerance of a larger map before any work, with MemoryError: its checks need
about 25 bytes a cell (the default, 2^26 cells, about 1.7 GB); exact saves
are not limited. ``metadata`` (keyword only) stores text in the file, the
keys info() returns: ``creator``, ``time`` (ISO 8601, such as
"2024-05-01T12:00:00Z"; other text raises ValueError), ``frame_id`` and
``robot_pose`` ("x y yaw" in metres and radians, or a sequence of 2 or 3
numbers; a point off the map raises ValueError); any other key raises
ValueError (``tolerance`` is written from ``tolerance=``). Options the
library refuses raise ValueError with its message. An output that cannot be written raises the OSError open() would,
with its errno and ``filename``: FileNotFoundError for a missing folder,
PermissionError for a read-only file (mode 0444 is refused even for root)
or folder; other write failures the OSError of the errno the failed call
gave (a full disk: ENOSPC), ``filename`` None when the file of a YAML +
image pair it was about is not known.
)doc");
  module.def("convert", &Convert, py::arg("source"), py::arg("path"), py::arg("tolerance") = 0,
             py::arg("vectors") = true, py::arg("straight_walls") = false,
             py::arg("compact") = false,
             py::arg("max_tolerance_cells") = default_max_tolerance_cells, py::kw_only(),
             py::arg("metadata") = py::none(), R"doc(
Saves the ROS map file ``source`` (a map YAML naming its image, or a bare
PGM / PNG image) as the .lmap file ``path`` (extension in any case),
without making a Map: the bytes ``save(path, load(source), ...)`` writes
(options as for save()). An exact file of a map over 4096 cells a side is
coded as the image is read, a row of 2048-cell blocks at a time, so the
grid is never held whole (a 282-Mcell map in 0.8-0.9 bytes of memory per
cell). An .lmap ``source``
(by name or signature) raises ValueError: re-encode one with
``save(path, load(source), ...)``. Errors as load() and save() raise them,
naming the file.
)doc");
  module.def("encode", &Encode, py::arg("map"), py::arg("tolerance") = 0, py::arg("vectors") = true,
             py::arg("straight_walls") = false, py::arg("compact") = false,
             py::arg("max_tolerance_cells") = default_max_tolerance_cells, py::kw_only(),
             py::arg("metadata") = py::none(),
             "The .lmap bytes of ``map`` (``tolerance``, ``vectors``, ``straight_walls``, "
             "``compact``, ``max_tolerance_cells`` and ``metadata`` as for save()).");
  module.def("decode", &Decode, py::arg("data"), py::arg("max_cells") = py::none(), py::kw_only(),
             py::arg("limits") = py::none(),
             "The map in .lmap bytes (bytes, bytearray or memoryview). Corrupt data raises "
             "ValueError, more than ``max_cells`` cells (or beyond a limit of ``limits``, a "
             "DecodeLimits) MemoryError.");
  module.def("vectors", &Vectors, py::arg("source"), py::arg("max_cells") = py::none(),
             py::arg("window_cells") = py::none(), py::kw_only(), py::arg("limits") = py::none(),
             R"doc(
The vector layers of an .lmap file (a path) or of .lmap bytes (format 1.0
files are read whole: their layers sit between raster chunks). A dict,
geometry in map-frame metres through cell centres:
``walls`` (N, 4) float64 segments x1, y1, x2, y2 (each wall polyline's
consecutive points), ``wall_polylines`` the polylines as (K, 2) arrays, ``wall_ids`` (one per polyline) int64
each polyline's index among the whole file's walls (0, 1, 2, ... without a
window; with one, the ids ``linemap export --window`` writes),
``rooms`` a list of {id, kind, outline: (K, 2) closed chain},
``furniture`` a list of {id, room_id or None, outline: (K, 2) closed chain},
and the file's ``version``, ``width``, ``height``, ``resolution``, ``origin``.
``window_cells=(col0, row0, col1, row1)`` (half-open cell indices, row 0 at
the origin, as for load()) keeps only the items whose bounding box meets
that window, in file order: a version 2.2 file reads only the layer sections
that reach it. A window that is empty or reaches past the map raises
ValueError. ``limits`` and errors as for load().
)doc");
  module.def("room_at", &RoomAt, py::arg("source"), py::arg("x"), py::arg("y"),
             py::arg("max_cells") = py::none(), py::kw_only(), py::arg("limits") = py::none(),
             R"doc(
The room at the map-frame point (``x``, ``y``) metres of an .lmap file (a
path) or .lmap bytes: of the rooms whose border chain encloses the cell
holding the point (the cell of the nearest centre), the one of smallest
area, with the cells of its border's box. Reads the file's header, the
layer sections around the cell and the tiles of the box only (a room of a
282-Mcell map in milliseconds). A dict {``id``, ``kind``, ``outline``:
(K, 2) closed chain in metres as vectors() gives rooms, ``window_cells``:
(col0, row0, col1, row1) the box, ``map``: the Map of its cells, origin at
its lower-left corner as load(window_cells=...) returns it}; None when no
room's border encloses the point (unknown space, a file without rooms). A
point off the map raises ValueError naming it; ``limits`` and other errors
as for load().
)doc");
  module.def("info", &Info, py::arg("source"), py::kw_only(), py::arg("limits") = py::none(),
             R"doc(
What an .lmap file (a path) or .lmap bytes says of itself, read from its
header and metadata without its layers or cells (``linemap info --json``
also counts the layers and cells, calls the tolerance ``tolerance_cells``
and lists every value of a repeated metadata key): a dict {``version`` ("2.3"), ``width``, ``height``
(cells), ``resolution`` (m/cell), ``origin`` (x, y, yaw: metres, radians),
``lossless`` (the file is the map cell for cell), ``tolerance`` (cells: the
T of ``save(..., tolerance=T)`` a file simplified within a tolerance was
saved at, whose guarantees then hold; None for an exact file and for files
that do not name it), ``metadata`` (dict of str: the file's metadata, such
as ``creator``, ``time``, ``frame_id``, ``robot_pose``; a repeated key keeps
its last value)}. Errors as for load().
)doc");
}

}  // namespace linemap::python
