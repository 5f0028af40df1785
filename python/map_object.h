// linemap.Map: a trinary occupancy grid as a numpy array plus the metadata
// that places it in the map frame (and writes it back as ROS map YAML).
#ifndef LINEMAP_PYTHON_MAP_OBJECT_H_
#define LINEMAP_PYTHON_MAP_OBJECT_H_

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstdint>
#include <optional>

#include "linemap/grid.h"

namespace linemap::python {

namespace py = pybind11;

struct Map {
  // (height, width) uint8 array, row 0 at the origin, values Cell (0 free,
  // 1 occupied, 2 unknown). Python code may write into it, so its values are
  // checked again whenever a grid is made from it (GridFromMap).
  py::array cells;
  // Resolution, origin and the YAML fields (mode, negate, thresholds) the
  // map was loaded with, so that saving it as YAML keeps them.
  MapMetadata meta;
  // The T of the .lmap file the map was loaded from when that file was
  // saved within a tolerance (its cells are the robot's map simplified
  // within T cells); nullopt otherwise. save() and encode() keep it, as
  // `linemap encode` of such a file does.
  std::optional<int> tolerance;
  // Loaded from a file whose cells are not the robot's map but which names
  // no tolerance (a 2.1-2.3 file written before files named their T, a
  // lossy 1.0 file): save() and encode() refuse it, as `linemap encode`
  // does, since a copy could not say which guarantees hold.
  bool simplified_without_tolerance = false;
};

// The grid's cells become the array without a copy.
Map MapFromGrid(Grid grid);

// A grid with copies of the map's cells (so the library can run on it with
// the GIL released while Python changes the array). Raises ValueError when a
// cell holds something other than 0, 1 or 2. Needs the GIL.
Grid GridFromMap(const Map& map);

// Checks that `cells` is a 2-D uint8 numpy array (TypeError, ValueError).
void CheckCellsArray(const py::handle& cells);

void BindMap(py::module_& module);

}  // namespace linemap::python

#endif  // LINEMAP_PYTHON_MAP_OBJECT_H_
