// What makes the module's classes pickle with every protocol.
#ifndef LINEMAP_PYTHON_PICKLING_H_
#define LINEMAP_PYTHON_PICKLING_H_

#include <pybind11/pybind11.h>

#include <algorithm>

namespace linemap::python {

namespace py = pybind11;

// pybind11 pickles with protocol 2 and later: protocols 0 and 1 reduce
// through copyreg._reduce_ex, which aborts the interpreter on a pybind11
// instance. Every protocol reduces as protocol 2 does (copyreg.__newobj__
// and the state of the class's py::pickle), which protocols 0 and 1 store
// too.
template <typename T>
void ReduceAsProtocolTwoAtLeast(py::class_<T>& cls) {
  cls.def(
      "__reduce_ex__",
      [](const py::object& self, int protocol) {
        return py::module_::import("builtins")
            .attr("object")
            .attr("__reduce_ex__")(self, std::max(protocol, 2));
      },
      py::arg("protocol"));
}

}  // namespace linemap::python

#endif  // LINEMAP_PYTHON_PICKLING_H_
