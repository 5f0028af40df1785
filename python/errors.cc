#include "python/errors.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>

namespace linemap::python {

namespace {

// The folder a new file for `path` is made in (format/file_io.cc's rule).
std::string DirectoryOf(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  if (slash == std::string::npos) return ".";
  if (slash == 0) return "/";
  return path.substr(0, slash);
}

// Why writing `path` fails, as an errno, following the library's
// AtomicFileWriter: an existing file (symlinks followed) is replaced only
// when writable, by us and by someone (mode 0444 is refused even for root);
// the new file is made in the target's folder. 0 when nothing here refuses.
int WriteErrno(const std::string& path) {
  std::string target = path;
  struct stat st;
  if (::stat(path.c_str(), &st) == 0) {
    if (S_ISREG(st.st_mode)) {
      if (::access(path.c_str(), W_OK) != 0) return errno;
      if ((st.st_mode & 0222) == 0) return EACCES;
    }
    if (char* resolved = ::realpath(path.c_str(), nullptr)) {
      target = resolved;
      std::free(resolved);
    }
  } else if (errno != ENOENT) {
    return errno;  // ENOTDIR, EACCES, ELOOP, ...: as open() fails
  }
  const std::string dir = DirectoryOf(target);
  if (::stat(dir.c_str(), &st) != 0) return errno;
  if (!S_ISDIR(st.st_mode)) return ENOTDIR;
  if (::access(dir.c_str(), W_OK | X_OK) != 0) return errno;
  return 0;
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

void RaiseWriteStatus(const Status& status, const std::vector<std::string>& outputs) {
  if (status.code() == StatusCode::kIoError) {
    for (const std::string& output : outputs) {
      const int error_number = WriteErrno(output);
      if (error_number == 0) continue;
      // OSError(errno, message, filename) makes the subclass of errno's kind.
      const pybind11::object error = pybind11::reinterpret_borrow<pybind11::object>(PyExc_OSError)(
          error_number, status.message(), output);
      PyErr_SetObject(reinterpret_cast<PyObject*>(Py_TYPE(error.ptr())), error.ptr());
      throw pybind11::error_already_set();
    }
  }
  RaiseStatus(status);
}

}  // namespace linemap::python
