// Little-endian byte writing and a bounds-checked read cursor: the only way
// the decoder touches file bytes (spec/format.md section "Conventions").
#ifndef LINEMAP_FORMAT_BYTE_IO_H_
#define LINEMAP_FORMAT_BYTE_IO_H_

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "linemap/status.h"

namespace linemap {

// Appends fixed-width little-endian integers and LEB128 varints to a buffer.
class ByteWriter {
 public:
  void PutU8(std::uint8_t v) { bytes_.push_back(v); }
  void PutU16(std::uint16_t v);
  void PutU32(std::uint32_t v);
  void PutU64(std::uint64_t v);
  // Unsigned LEB128: 7 bits per byte, low group first, high bit = more.
  void PutVarint(std::uint64_t v);
  // Zigzag (0,-1,1,-2,... -> 0,1,2,3,...) then PutVarint.
  void PutSignedVarint(std::int64_t v);
  void PutBytes(std::string_view data);
  void PutBytes(const std::vector<std::uint8_t>& data);

  const std::vector<std::uint8_t>& bytes() const { return bytes_; }
  std::vector<std::uint8_t>& mutable_bytes() { return bytes_; }
  std::size_t size() const { return bytes_.size(); }

 private:
  std::vector<std::uint8_t> bytes_;
};

// Reads from a byte range it does not own. Every read checks the bytes left;
// a failed read returns kCorrupt naming `what`, and the cursor stays put.
class ByteCursor {
 public:
  ByteCursor(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  explicit ByteCursor(const std::vector<std::uint8_t>& data)
      : ByteCursor(data.data(), data.size()) {}

  std::size_t remaining() const { return size_ - pos_; }
  std::size_t position() const { return pos_; }
  bool empty() const { return pos_ == size_; }

  StatusOr<std::uint8_t> ReadU8(const char* what);
  StatusOr<std::uint16_t> ReadU16(const char* what);
  StatusOr<std::uint32_t> ReadU32(const char* what);
  StatusOr<std::uint64_t> ReadU64(const char* what);
  // At most 10 bytes; a value above 2^64-1 or an over-long encoding
  // (a trailing 0x00 group) is kCorrupt, so each value has one encoding.
  StatusOr<std::uint64_t> ReadVarint(const char* what);
  StatusOr<std::int64_t> ReadSignedVarint(const char* what);
  // A varint that must be <= max (a count or a length checked before use).
  StatusOr<std::uint64_t> ReadVarintAtMost(std::uint64_t max, const char* what);
  // `n` bytes as a view into the underlying data.
  StatusOr<const std::uint8_t*> ReadBytes(std::size_t n, const char* what);

 private:
  Status Truncated(const char* what) const;
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
};

// a * b, or false when it overflows 64 bits.
bool CheckedMul(std::uint64_t a, std::uint64_t b, std::uint64_t* out);

}  // namespace linemap

#endif  // LINEMAP_FORMAT_BYTE_IO_H_
