// Errors as values, in the style of Draco's Status / StatusOr: no exception
// crosses the public API and the library never calls exit().
#ifndef LINEMAP_STATUS_H_
#define LINEMAP_STATUS_H_

#include <cassert>
#include <optional>
#include <string>
#include <utility>

namespace linemap {

enum class StatusCode {
  kOk = 0,
  kInvalidArgument,    // A parameter or an option is out of its range.
  kNotFound,           // A file does not exist.
  kIoError,            // Reading or writing failed for a reason outside the data.
  kCorrupt,            // The data is malformed (bad CRC, truncated, wrong magic).
  kUnsupported,        // Well-formed, but uses a feature this version lacks.
  kResourceExhausted,  // A caller-set limit (cells, bytes) would be exceeded.
  kInternal,           // A bug in linemap.
  kPermissionDenied,   // An input file the caller may not read.
};

const char* StatusCodeName(StatusCode code);

// Which caller-set limit a kResourceExhausted error is over: the fields of
// DecodeLimits (linemap/codec.h) and the image loaders' `max_cells`, and
// EncodeOptions::max_tolerance_cells. kNone for every other error. A front
// end names the option that lifts a refusal from this, not from the words
// of the message.
enum class Limit {
  kNone = 0,
  kFileBytes,       // DecodeLimits::max_file_bytes
  kCells,           // max_cells: width * height of a file, image or message
  kChunkBytes,      // DecodeLimits::max_chunk_bytes
  kInflatedBytes,   // DecodeLimits::max_inflated_bytes
  kSegments,        // DecodeLimits::max_segments
  kChainLength,     // DecodeLimits::max_chain_length
  kObjects,         // DecodeLimits::max_objects
  kToleranceCells,  // EncodeOptions::max_tolerance_cells
};

// The name of the field that sets `limit` ("max_segments"; "" for kNone),
// which the Python module and the ROS nodes use for their options too.
const char* LimitFieldName(Limit limit);

class [[nodiscard]] Status {
 public:
  Status() = default;
  Status(StatusCode code, std::string message) : code_(code), message_(std::move(message)) {}
  Status(StatusCode code, std::string message, Limit limit)
      : code_(code), message_(std::move(message)), limit_(limit) {}

  static Status Ok() { return Status(); }

  bool ok() const { return code_ == StatusCode::kOk; }
  StatusCode code() const { return code_; }
  const std::string& message() const { return message_; }
  // The limit a kResourceExhausted error is over; kNone otherwise.
  Limit limit() const { return limit_; }
  // The errno of the system call that failed (ENOENT, EACCES, ENOSPC, ...),
  // or of the call the library's own refusal stands in for (EISDIR for a
  // directory given as the file to write); 0 when no system call is behind
  // the error. A front end maps it to its own error types (Python's OSError
  // subclasses and their `errno`) rather than probing the file again, which
  // may find another cause or none, or reading it from the message.
  int sys_errno() const { return sys_errno_; }

  // "message" for errors, "OK" for success.
  std::string ToString() const;

  // Returns a copy whose message is "prefix: message" (the code, the limit
  // and the errno kept); used to add the file name or the chunk that failed
  // as the error travels up.
  Status WithContext(const std::string& prefix) const;

  // Returns a copy carrying `err` as its sys_errno(), as in
  // `IoError("cannot write ...").WithErrno(err)`. An OK status stays OK
  // with no errno.
  Status WithErrno(int err) const;

 private:
  StatusCode code_ = StatusCode::kOk;
  std::string message_;
  Limit limit_ = Limit::kNone;
  int sys_errno_ = 0;
};

inline Status InvalidArgumentError(std::string m) {
  return Status(StatusCode::kInvalidArgument, std::move(m));
}
inline Status NotFoundError(std::string m) { return Status(StatusCode::kNotFound, std::move(m)); }
inline Status IoError(std::string m) { return Status(StatusCode::kIoError, std::move(m)); }
inline Status CorruptError(std::string m) { return Status(StatusCode::kCorrupt, std::move(m)); }
inline Status UnsupportedError(std::string m) {
  return Status(StatusCode::kUnsupported, std::move(m));
}
// A caller-set limit exceeded: kResourceExhausted, tagged with which.
inline Status OverLimitError(Limit limit, std::string m) {
  return Status(StatusCode::kResourceExhausted, std::move(m), limit);
}
// The name of OverLimitError before refusals said which limit they are
// over; kept so that callers written against it still build.
[[deprecated("use OverLimitError(Limit, message)")]] inline Status ResourceExhaustedError(
    std::string m) {
  return OverLimitError(Limit::kNone, std::move(m));
}
inline Status InternalError(std::string m) { return Status(StatusCode::kInternal, std::move(m)); }
inline Status PermissionDeniedError(std::string m) {
  return Status(StatusCode::kPermissionDenied, std::move(m));
}

// Either a value or a non-OK Status.
template <typename T>
class [[nodiscard]] StatusOr {
 public:
  StatusOr(const Status& status) : status_(status) {  // NOLINT(runtime/explicit)
    assert(!status_.ok() && "StatusOr built from an OK status without a value");
    if (status_.ok()) status_ = InternalError("StatusOr built from an OK status without a value");
  }
  StatusOr(T value) : value_(std::move(value)) {}  // NOLINT(runtime/explicit)

  bool ok() const { return status_.ok(); }
  const Status& status() const { return status_; }

  const T& value() const& { return *value_; }
  T& value() & { return *value_; }
  T&& value() && { return std::move(*value_); }
  const T& operator*() const& { return *value_; }
  T& operator*() & { return *value_; }
  T&& operator*() && { return std::move(*value_); }
  const T* operator->() const { return &*value_; }
  T* operator->() { return &*value_; }

 private:
  Status status_;
  std::optional<T> value_;
};

}  // namespace linemap

#define LINEMAP_STATUS_CONCAT_INNER_(a, b) a##b
#define LINEMAP_STATUS_CONCAT_(a, b) LINEMAP_STATUS_CONCAT_INNER_(a, b)

// Returns from the current function if `expr` (a Status) is not OK.
#define LINEMAP_RETURN_IF_ERROR(expr)                          \
  do {                                                         \
    ::linemap::Status linemap_status_tmp_ = (expr);            \
    if (!linemap_status_tmp_.ok()) return linemap_status_tmp_; \
  } while (false)

// `lhs = value of expr` (a StatusOr), or returns its error.
#define LINEMAP_ASSIGN_OR_RETURN(lhs, expr) \
  LINEMAP_ASSIGN_OR_RETURN_IMPL_(LINEMAP_STATUS_CONCAT_(linemap_statusor_, __LINE__), lhs, expr)
#define LINEMAP_ASSIGN_OR_RETURN_IMPL_(tmp, lhs, expr) \
  auto tmp = (expr);                                   \
  if (!tmp.ok()) return tmp.status();                  \
  lhs = std::move(tmp).value()

#endif  // LINEMAP_STATUS_H_
