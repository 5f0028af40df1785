#include "format/byte_io.h"

namespace linemap {

void ByteWriter::PutU16(std::uint16_t v) {
  PutU8(static_cast<std::uint8_t>(v));
  PutU8(static_cast<std::uint8_t>(v >> 8));
}

void ByteWriter::PutU32(std::uint32_t v) {
  for (int i = 0; i < 4; ++i) PutU8(static_cast<std::uint8_t>(v >> (8 * i)));
}

void ByteWriter::PutU64(std::uint64_t v) {
  for (int i = 0; i < 8; ++i) PutU8(static_cast<std::uint8_t>(v >> (8 * i)));
}

void ByteWriter::PutVarint(std::uint64_t v) {
  while (v >= 0x80) {
    PutU8(static_cast<std::uint8_t>(v | 0x80));
    v >>= 7;
  }
  PutU8(static_cast<std::uint8_t>(v));
}

void ByteWriter::PutSignedVarint(std::int64_t v) {
  const std::uint64_t u = static_cast<std::uint64_t>(v);
  PutVarint((u << 1) ^ (v < 0 ? ~std::uint64_t{0} : 0));
}

void ByteWriter::PutBytes(std::string_view data) {
  bytes_.insert(bytes_.end(), data.begin(), data.end());
}

void ByteWriter::PutBytes(const std::vector<std::uint8_t>& data) {
  bytes_.insert(bytes_.end(), data.begin(), data.end());
}

Status ByteCursor::Truncated(const char* what) const {
  return CorruptError(std::string("truncated ") + what + " at byte " + std::to_string(pos_));
}

StatusOr<std::uint8_t> ByteCursor::ReadU8(const char* what) {
  if (remaining() < 1) return Truncated(what);
  return data_[pos_++];
}

StatusOr<std::uint16_t> ByteCursor::ReadU16(const char* what) {
  if (remaining() < 2) return Truncated(what);
  const std::uint16_t v = static_cast<std::uint16_t>(data_[pos_] | (data_[pos_ + 1] << 8));
  pos_ += 2;
  return v;
}

StatusOr<std::uint32_t> ByteCursor::ReadU32(const char* what) {
  if (remaining() < 4) return Truncated(what);
  std::uint32_t v = 0;
  for (int i = 3; i >= 0; --i) v = (v << 8) | data_[pos_ + static_cast<std::size_t>(i)];
  pos_ += 4;
  return v;
}

StatusOr<std::uint64_t> ByteCursor::ReadU64(const char* what) {
  if (remaining() < 8) return Truncated(what);
  std::uint64_t v = 0;
  for (int i = 7; i >= 0; --i) v = (v << 8) | data_[pos_ + static_cast<std::size_t>(i)];
  pos_ += 8;
  return v;
}

StatusOr<std::uint64_t> ByteCursor::ReadVarint(const char* what) {
  std::uint64_t v = 0;
  std::size_t p = pos_;
  for (int shift = 0; shift < 64; shift += 7) {
    if (p >= size_) return Truncated(what);
    const std::uint8_t byte = data_[p++];
    const std::uint64_t group = byte & 0x7F;
    if (shift == 63 && group > 1) break;  // above 2^64-1
    v |= group << shift;
    if ((byte & 0x80) == 0) {
      if (byte == 0 && shift > 0) break;  // over-long encoding
      pos_ = p;
      return v;
    }
  }
  return CorruptError(std::string("malformed varint in ") + what + " at byte " +
                      std::to_string(pos_));
}

StatusOr<std::int64_t> ByteCursor::ReadSignedVarint(const char* what) {
  LINEMAP_ASSIGN_OR_RETURN(std::uint64_t u, ReadVarint(what));
  return static_cast<std::int64_t>((u >> 1) ^ (~(u & 1) + 1));
}

StatusOr<std::uint64_t> ByteCursor::ReadVarintAtMost(std::uint64_t max, const char* what) {
  const std::size_t start = pos_;
  LINEMAP_ASSIGN_OR_RETURN(std::uint64_t v, ReadVarint(what));
  if (v > max) {
    pos_ = start;
    return CorruptError(std::string(what) + " " + std::to_string(v) + " exceeds " +
                        std::to_string(max));
  }
  return v;
}

StatusOr<const std::uint8_t*> ByteCursor::ReadBytes(std::size_t n, const char* what) {
  if (remaining() < n) return Truncated(what);
  const std::uint8_t* p = data_ + pos_;
  pos_ += n;
  return p;
}

bool CheckedMul(std::uint64_t a, std::uint64_t b, std::uint64_t* out) {
  return !__builtin_mul_overflow(a, b, out);
}

}  // namespace linemap
