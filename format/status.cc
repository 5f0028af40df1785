#include "linemap/status.h"

namespace linemap {

const char* StatusCodeName(StatusCode code) {
  switch (code) {
    case StatusCode::kOk:
      return "OK";
    case StatusCode::kInvalidArgument:
      return "invalid argument";
    case StatusCode::kNotFound:
      return "not found";
    case StatusCode::kIoError:
      return "I/O error";
    case StatusCode::kCorrupt:
      return "corrupt data";
    case StatusCode::kUnsupported:
      return "unsupported";
    case StatusCode::kResourceExhausted:
      return "limit exceeded";
    case StatusCode::kInternal:
      return "internal error";
    case StatusCode::kPermissionDenied:
      return "permission denied";
  }
  return "unknown status";
}

const char* LimitFieldName(Limit limit) {
  switch (limit) {
    case Limit::kNone:
      return "";
    case Limit::kFileBytes:
      return "max_file_bytes";
    case Limit::kCells:
      return "max_cells";
    case Limit::kChunkBytes:
      return "max_chunk_bytes";
    case Limit::kInflatedBytes:
      return "max_inflated_bytes";
    case Limit::kSegments:
      return "max_segments";
    case Limit::kChainLength:
      return "max_chain_length";
    case Limit::kObjects:
      return "max_objects";
    case Limit::kToleranceCells:
      return "max_tolerance_cells";
  }
  return "";
}

std::string Status::ToString() const { return ok() ? std::string("OK") : message_; }

Status Status::WithContext(const std::string& prefix) const {
  if (ok()) return *this;
  Status status = *this;
  status.message_ = prefix + ": " + message_;
  return status;
}

Status Status::WithErrno(int err) const {
  if (ok()) return *this;
  Status status = *this;
  status.sys_errno_ = err;
  return status;
}

}  // namespace linemap
