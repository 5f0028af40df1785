// The `linemap` Python module: maps as numpy arrays, .lmap files and their
// vector layers, and the library's analyses, for Debian's python3.
#include <pybind11/pybind11.h>

#include "linemap/grid.h"
#include "python/bindings.h"
#include "python/decode_limits.h"
#include "python/map_object.h"

PYBIND11_MODULE(linemap, module) {
  namespace py = pybind11;
  using linemap::Cell;
  module.doc() = R"doc(
linemap: robot occupancy-grid maps as numpy arrays, saved as small .lmap files.

  m = linemap.load("map.yaml")          # .lmap, map YAML or bare PGM / PNG
  m.cells                                # uint8 (height, width), row 0 at the origin
  linemap.save("map.lmap", m)            # exact by default; .yaml writes YAML + PGM

Errors raise Python exceptions carrying the library's message (which names
the file): ValueError for bad input (a corrupt file, a malformed map, an
option out of range), FileNotFoundError for a missing file, OSError for
other I/O failures, MemoryError when a caller-set limit (max_cells, the
file-size limit, a DecodeLimits) would be exceeded, RuntimeError for a bug in linemap. A
numpy array of the wrong dtype raises TypeError, of the wrong shape or with
values other than FREE / OCCUPIED / UNKNOWN ValueError; arrays are never
converted silently. Encoding, decoding, loading, saving, extraction,
segmentation and planning release the GIL.
)doc";
  module.attr("FREE") = static_cast<int>(Cell::kFree);
  module.attr("OCCUPIED") = static_cast<int>(Cell::kOccupied);
  module.attr("UNKNOWN") = static_cast<int>(Cell::kUnknown);
  module.attr("__version__") = LINEMAP_VERSION_STRING;
  linemap::python::BindDecodeLimits(module);
  linemap::python::BindMap(module);
  linemap::python::BindIo(module);
  linemap::python::BindAnalysis(module);
}
