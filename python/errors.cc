#include "python/errors.h"

#include <cerrno>

namespace linemap::python {

PyObject* ExceptionTypeFor(StatusCode code) {
  switch (code) {
    case StatusCode::kInvalidArgument:
    case StatusCode::kCorrupt:
    case StatusCode::kUnsupported:
      return PyExc_ValueError;
    case StatusCode::kNotFound:
      return PyExc_FileNotFoundError;
    case StatusCode::kPermissionDenied:
      return PyExc_PermissionError;
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
  // The OSErrors that say why a file could not be opened carry their errno,
  // as Python's own open() gives them (the message stays the library's).
  const int error_number = status.code() == StatusCode::kNotFound           ? ENOENT
                           : status.code() == StatusCode::kPermissionDenied ? EACCES
                                                                            : 0;
  if (error_number != 0) {
    PyObject* args = Py_BuildValue("(is)", error_number, status.message().c_str());
    PyErr_SetObject(ExceptionTypeFor(status.code()), args);
    Py_XDECREF(args);
  } else if (status.code() == StatusCode::kResourceExhausted) {
    // A refusal over a limit names it as `limit`, the keyword that lifts it
    // (DecodeLimits(max_segments=...), save(max_tolerance_cells=...)); None
    // when no keyword does (a save whose layers decoders would refuse).
    pybind11::object error = pybind11::reinterpret_borrow<pybind11::object>(
        ExceptionTypeFor(status.code()))(status.message());
    error.attr("limit") = status.limit() == Limit::kNone
                              ? pybind11::none()
                              : pybind11::object(pybind11::str(LimitFieldName(status.limit())));
    PyErr_SetObject(ExceptionTypeFor(status.code()), error.ptr());
  } else {
    PyErr_SetString(ExceptionTypeFor(status.code()), status.message().c_str());
  }
  throw pybind11::error_already_set();
}

}  // namespace linemap::python
