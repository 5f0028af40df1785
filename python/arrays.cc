#include "python/arrays.h"

#include <cmath>

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
  return py::module_::import("os").attr("fsdecode")(path).cast<std::string>();
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
  for (const py::handle item : items) {
    // Numbers only: float() would also parse strings.
    if (!PyNumber_Check(item.ptr()) || py::isinstance<py::str>(item)) {
      throw py::value_error(std::string(what) + " must hold numbers");
    }
    const double v = py::float_(py::reinterpret_borrow<py::object>(item));
    if (!std::isfinite(v)) throw py::value_error(std::string(what) + " must be finite");
    values.push_back(v);
  }
  return values;
}

std::uint64_t MaxCellsArgument(const py::object& max_cells, std::uint64_t fallback) {
  if (max_cells.is_none()) return fallback;
  if (!py::isinstance<py::int_>(max_cells) || py::isinstance<py::bool_>(max_cells)) {
    throw py::type_error("max_cells must be an int or None");
  }
  if (max_cells < py::int_(1)) throw py::value_error("max_cells must be at least 1");
  if (max_cells > py::int_(UINT64_MAX)) throw py::value_error("max_cells must be below 2^64");
  return max_cells.cast<std::uint64_t>();
}

}  // namespace linemap::python
