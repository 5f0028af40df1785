// numpy arrays out of library results, and checked Python arguments in.
// Geometry handed to Python is in map-frame metres (Grid::CellToWorld):
// lattice point (col, row) is the centre of that cell.
#ifndef LINEMAP_PYTHON_ARRAYS_H_
#define LINEMAP_PYTHON_ARRAYS_H_

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "linemap/cells.h"
#include "linemap/grid.h"

namespace linemap::python {

namespace py = pybind11;

// A numpy array viewing `values`, which it takes over (no copy): the vector
// lives as long as the array. `shape` must hold values.size() elements.
template <typename T>
py::array_t<T> ArrayOwning(std::vector<T> values, std::vector<py::ssize_t> shape) {
  auto* owned = new std::vector<T>(std::move(values));
  py::capsule owner(owned, [](void* p) { delete static_cast<std::vector<T>*>(p); });
  return py::array_t<T>(std::move(shape), owned->data(), owner);
}

// (K, 2) float64 array of the map-frame metres of lattice points, by the
// frame's resolution and origin.
py::array_t<double> WorldPoints(const Grid& frame, const std::vector<CellIndex>& points);

// (x, y) in map-frame metres of one lattice point.
py::tuple WorldPoint(const Grid& frame, const CellIndex& point);

// A file name from str, bytes or os.PathLike, as the file system's bytes
// (os.fsencode); ValueError for one holding a NUL byte.
std::string PathArgument(const py::handle& path);

// A tolerance in whole cells, 0..kMaxToleranceCells (linemap/tolerance.h):
// TypeError for anything but an int (a bool included), ValueError outside
// the range, both quoting the value given.
int ToleranceCellsArgument(const py::handle& tolerance);

// Between min_size and max_size finite floats from a Python sequence, e.g.
// an origin (x, y[, yaw]); raises ValueError naming `what` otherwise.
std::vector<double> FiniteFloats(const py::handle& sequence, const char* what, std::size_t min_size,
                                 std::size_t max_size);

// A whole number from Python named `name`: an int (bools, which are ints to
// Python, and floats raise TypeError saying it must be `kind`) from `min` to
// `max` (else ValueError naming the range).
std::uint64_t WholeNumberArgument(const py::handle& value, const char* name, std::uint64_t min,
                                  std::uint64_t max, const char* kind = "an int");

// A max_cells argument: None gives `fallback`; else a whole number from 1
// to 2^64 - 1.
std::uint64_t MaxCellsArgument(const py::object& max_cells, std::uint64_t fallback);

}  // namespace linemap::python

#endif  // LINEMAP_PYTHON_ARRAYS_H_
