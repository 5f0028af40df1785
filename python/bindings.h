// The parts of the `linemap` Python module, each adding its functions.
#ifndef LINEMAP_PYTHON_BINDINGS_H_
#define LINEMAP_PYTHON_BINDINGS_H_

#include <pybind11/pybind11.h>

namespace linemap::python {

// load, save, encode, decode, vectors (io_functions.cc).
void BindIo(pybind11::module_& module);
// lines, segment, plan, eval (analysis_functions.cc).
void BindAnalysis(pybind11::module_& module);

}  // namespace linemap::python

#endif  // LINEMAP_PYTHON_BINDINGS_H_
