#include "python/errors.h"

namespace linemap::python {

PyObject* ExceptionTypeFor(StatusCode code) {
  switch (code) {
    case StatusCode::kInvalidArgument:
    case StatusCode::kCorrupt:
    case StatusCode::kUnsupported:
      return PyExc_ValueError;
    case StatusCode::kNotFound:
      return PyExc_FileNotFoundError;
    case StatusCode::kIoError:
      return PyExc_OSError;
    case StatusCode::kResourceExhausted:
      return PyExc_MemoryError;
    case StatusCode::kOk:  // never raised; a bug if it were
    case StatusCode::kInternal:
      break;
  }
  return PyExc_RuntimeError;
}

void RaiseStatus(const Status& status) {
  PyErr_SetString(ExceptionTypeFor(status.code()), status.message().c_str());
  throw pybind11::error_already_set();
}

}  // namespace linemap::python
