#include "python/errors.h"

#include <cerrno>

#include "format/file_io.h"

namespace linemap::python {

namespace {

// Text of the library's (a message or a file name) as a Python str: file
// names are the file system's bytes, which need not be UTF-8, so bytes that
// are not come back as surrogate escapes, as os.fsdecode gives them.
pybind11::str Text(const std::string& bytes) {
  PyObject* text =
      PyUnicode_DecodeUTF8(bytes.data(), static_cast<Py_ssize_t>(bytes.size()), "surrogateescape");
  if (text == nullptr) throw pybind11::error_already_set();
  return pybind11::reinterpret_steal<pybind11::str>(text);
}

// Raises OSError(errno, message, filename), which Python makes the subclass
// of errno's kind (FileNotFoundError for ENOENT, NotADirectoryError for
// ENOTDIR, ...) as its own open() does. `filename` None for none.
[[noreturn]] void RaiseOsError(int error_number, const std::string& message,
                               const pybind11::object& filename) {
  const pybind11::object error = pybind11::reinterpret_borrow<pybind11::object>(PyExc_OSError)(
      error_number, Text(message), filename);
  PyErr_SetObject(reinterpret_cast<PyObject*>(Py_TYPE(error.ptr())), error.ptr());
  throw pybind11::error_already_set();
}

// Which of a save's `outputs` a kIoError is about. The Status names no file
// (only its message does), so: the first output the library's own
// CheckSaveTarget refuses (the files are opened in that order); else the
// only output; else None (a failure the check does not see, such as a full
// disk, in a save of two files). Only the file is looked for here: the
// errno is the status's own.
pybind11::object FailedOutput(const std::vector<std::string>& outputs) {
  for (const std::string& output : outputs) {
    if (!CheckSaveTarget(output).ok()) return Text(output);
  }
  if (outputs.size() == 1) return Text(outputs[0]);
  return pybind11::none();
}

}  // namespace

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

namespace {

// Whether `status` is a system call's failure (or a refusal standing in for
// one), which Python reports as the OSError subclass of its errno.
bool IsOsError(const Status& status) {
  return status.sys_errno() != 0 && status.code() != StatusCode::kResourceExhausted &&
         status.code() != StatusCode::kInternal;
}

}  // namespace

void RaiseStatus(const Status& status) {
  // A failed system call raises what Python's own open() would for its
  // errno (FileNotFoundError, NotADirectoryError, IsADirectoryError, ...),
  // with that errno; the message stays the library's. A missing or
  // unreadable file without one gets the errno its kind stands for.
  if (IsOsError(status)) {
    RaiseOsError(status.sys_errno(), status.message(), pybind11::none());
  } else if (status.code() == StatusCode::kNotFound ||
             status.code() == StatusCode::kPermissionDenied) {
    const int error_number = status.code() == StatusCode::kNotFound ? ENOENT : EACCES;
    const pybind11::tuple args = pybind11::make_tuple(error_number, Text(status.message()));
    PyErr_SetObject(ExceptionTypeFor(status.code()), args.ptr());
  } else if (status.code() == StatusCode::kResourceExhausted) {
    // A refusal over a limit names it as `limit`, the keyword that lifts it
    // (DecodeLimits(max_segments=...), save(max_tolerance_cells=...)); None
    // when no keyword does (a save whose layers decoders would refuse).
    pybind11::object error = pybind11::reinterpret_borrow<pybind11::object>(
        ExceptionTypeFor(status.code()))(Text(status.message()));
    error.attr("limit") = status.limit() == Limit::kNone
                              ? pybind11::none()
                              : pybind11::object(pybind11::str(LimitFieldName(status.limit())));
    PyErr_SetObject(ExceptionTypeFor(status.code()), error.ptr());
  } else {
    PyErr_SetObject(ExceptionTypeFor(status.code()), Text(status.message()).ptr());
  }
  throw pybind11::error_already_set();
}

void RaiseWriteStatus(const Status& status, const std::vector<std::string>& outputs) {
  if (IsOsError(status)) {
    RaiseOsError(status.sys_errno(), status.message(), FailedOutput(outputs));
  }
  RaiseStatus(status);
}

}  // namespace linemap::python
