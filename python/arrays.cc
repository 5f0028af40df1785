#include "python/arrays.h"

#include <cmath>
#include <cstdint>
#include <string>

#include "linemap/tolerance.h"

namespace linemap::python {

py::array_t<double> WorldPoints(const Grid& frame, const std::vector<CellIndex>& points) {
  std::vector<double> xy(points.size() * 2);
  for (std::size_t i = 0; i < points.size(); ++i) {
    frame.CellToWorld(points[i].col, points[i].row, &xy[2 * i], &xy[2 * i + 1]);
  }
  return ArrayOwning(std::move(xy), {static_cast<py::ssize_t>(points.size()), 2});
}

py::tuple WorldPoint(const Grid& frame, const CellIndex& point) {
  double x = 0, y = 0;
  frame.CellToWorld(point.col, point.row, &x, &y);
  return py::make_tuple(x, y);
}

std::string PathArgument(const py::handle& path) {
  // The file system's bytes (os.fsencode), as open() takes a path: a name
  // that is not UTF-8 arrives as a str with surrogate escapes, which a
  // UTF-8 cast refuses.
  const py::bytes encoded = py::module_::import("os").attr("fsencode")(path);
  std::string bytes = encoded;
  // The C library would end the name at a NUL and open another file.
  if (bytes.find('\0') != std::string::npos) throw py::value_error("embedded null byte");
  return bytes;
}

int ToleranceCellsArgument(const py::handle& tolerance) {
  const std::string range = "0.." + std::to_string(kMaxToleranceCells);
  const std::string given = py::repr(tolerance).cast<std::string>();
  if (!py::isinstance<py::int_>(tolerance) || py::isinstance<py::bool_>(tolerance)) {
    throw py::type_error("tolerance must be a whole number of cells, " + range + ", not " + given);
  }
  const auto value = py::reinterpret_borrow<py::int_>(tolerance);
  if (value < py::int_(0) || value > py::int_(kMaxToleranceCells)) {
    throw py::value_error("tolerance must be " + range + " cells, not " + given);
  }
  return value.cast<int>();
}

std::vector<double> FiniteFloats(const py::handle& sequence, const char* what, std::size_t min_size,
                                 std::size_t max_size) {
  const std::string range = min_size == max_size
                                ? std::to_string(min_size)
                                : std::to_string(min_size) + " to " + std::to_string(max_size);
  if (!py::isinstance<py::sequence>(sequence) || py::isinstance<py::str>(sequence)) {
    throw py::value_error(std::string(what) + " must be a sequence of " + range + " numbers");
  }
  const auto items = py::reinterpret_borrow<py::sequence>(sequence);
  if (items.size() < min_size || items.size() > max_size) {
    throw py::value_error(std::string(what) + " must have " + range + " numbers, not " +
                          std::to_string(items.size()));
  }
  std::vector<double> values;
  for (std::size_t i = 0; i < items.size(); ++i) {
    // Owned, not a handle: a sequence may make each item as it is asked for
    // (a numpy array makes a new scalar), and only this reference keeps it.
    const py::object item = items[i];
    // Numbers only: float() would also parse strings.
    if (!PyNumber_Check(item.ptr()) || py::isinstance<py::str>(item)) {
      throw py::value_error(std::string(what) + " must hold numbers");
    }
    const double v = py::float_(item);
    if (!std::isfinite(v)) throw py::value_error(std::string(what) + " must be finite");
    values.push_back(v);
  }
  return values;
}

std::uint64_t WholeNumberArgument(const py::handle& value, const char* name, std::uint64_t min,
                                  std::uint64_t max, const char* kind) {
  if (!py::isinstance<py::int_>(value) || py::isinstance<py::bool_>(value)) {
    throw py::type_error(std::string(name) + " must be " + kind);
  }
  const py::int_ v = py::reinterpret_borrow<py::int_>(value);
  if (v < py::int_(min) || v > py::int_(max)) {
    throw py::value_error(std::string(name) + " must be from " + std::to_string(min) + " to " +
                          std::to_string(max));
  }
  return v.cast<std::uint64_t>();
}

std::uint64_t MaxCellsArgument(const py::object& max_cells, std::uint64_t fallback) {
  if (max_cells.is_none()) return fallback;
  return WholeNumberArgument(max_cells, "max_cells", 1, UINT64_MAX, "an int or None");
}

}  // namespace linemap::python
