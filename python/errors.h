// linemap::Status codes as Python exceptions. The library reports errors as
// values; the module raises them once it holds the GIL again, with the
// library's message (which names the file and the problem).
//
//   kInvalidArgument, kCorrupt, kUnsupported  -> ValueError
//   kNotFound                                 -> FileNotFoundError (an OSError;
//                                                errno ENOENT)
//   kPermissionDenied                         -> PermissionError (an OSError;
//                                                errno EACCES, or EPERM)
//   kIoError                                  -> OSError (the subclass of its
//                                                errno when it has one)
//   kResourceExhausted                        -> MemoryError (a caller-set limit such
//                                                as max_cells, not the machine's memory;
//                                                .limit its keyword, or None)
//   kInternal                                 -> RuntimeError
//
// The errno is the Status's sys_errno(): the one the failed system call
// gave (kNotFound and kPermissionDenied fall back to ENOENT and EACCES
// where no call is behind them). A save's kIoError with an errno (a
// missing folder, a read-only file or folder, a full disk) is raised as
// open(path, "w") raises it: the OSError subclass of its errno
// (FileNotFoundError ENOENT, PermissionError EACCES, NotADirectoryError
// ENOTDIR) with the output as `filename` (RaiseWriteStatus).
#ifndef LINEMAP_PYTHON_ERRORS_H_
#define LINEMAP_PYTHON_ERRORS_H_

#include <pybind11/pybind11.h>

#include <string>
#include <utility>
#include <vector>

#include "linemap/status.h"

namespace linemap::python {

// The Python exception class for a library error code (see above).
PyObject* ExceptionTypeFor(StatusCode code);

// Raises `status` (not OK) as its Python exception. Needs the GIL.
[[noreturn]] void RaiseStatus(const Status& status);

// Raises `status` (not OK) of a save that writes `outputs` (in the order the
// library opens them): a kIoError with an errno as the OSError subclass of
// that errno (a file of mode 0444 is EACCES even for root, as the library
// refuses it), with the library's message and as `filename` the first
// output CheckSaveTarget refuses, else the only output, else None;
// anything else as RaiseStatus. Needs the GIL.
[[noreturn]] void RaiseWriteStatus(const Status& status, const std::vector<std::string>& outputs);

inline void RaiseIfError(const Status& status) {
  if (!status.ok()) RaiseStatus(status);
}

template <typename T>
T ValueOrRaise(StatusOr<T>&& result) {
  if (!result.ok()) RaiseStatus(result.status());
  return std::move(result).value();
}

}  // namespace linemap::python

#endif  // LINEMAP_PYTHON_ERRORS_H_
