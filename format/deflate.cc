#include "format/deflate.h"

#include <zlib.h>

#include <algorithm>
#include <limits>

namespace linemap {

std::vector<std::uint8_t> DeflateBytes(const std::uint8_t* data, std::size_t size) {
  uLongf out_size = compressBound(static_cast<uLong>(size));
  std::vector<std::uint8_t> out(out_size);
  const int rc = compress2(out.data(), &out_size, data, static_cast<uLong>(size), 9);
  if (rc != Z_OK) return {};
  out.resize(out_size);
  return out;
}

StatusOr<std::vector<std::uint8_t>> InflateBytes(const std::uint8_t* data, std::size_t size,
                                                 std::size_t expected_size) {
  std::vector<std::uint8_t> out(expected_size);
  z_stream zs{};
  if (inflateInit(&zs) != Z_OK) return InternalError("inflateInit failed");
  // Feed and drain in pieces that fit zlib's 32-bit counters.
  constexpr std::size_t kStep = std::numeric_limits<uInt>::max() / 2;
  std::size_t in_pos = 0;
  std::size_t out_pos = 0;
  int rc = Z_OK;
  while (rc == Z_OK) {
    const std::size_t in_now = std::min(kStep, size - in_pos);
    const std::size_t out_now = std::min(kStep, expected_size - out_pos);
    zs.next_in = const_cast<Bytef*>(data + in_pos);
    zs.avail_in = static_cast<uInt>(in_now);
    // One spare byte of room detects a stream longer than announced.
    std::uint8_t spare = 0;
    zs.next_out = out_now > 0 ? out.data() + out_pos : &spare;
    zs.avail_out = static_cast<uInt>(out_now > 0 ? out_now : 1);
    rc = inflate(&zs, Z_NO_FLUSH);
    const std::size_t used_in = in_now - zs.avail_in;
    const std::size_t made = (out_now > 0 ? out_now : 1) - zs.avail_out;
    in_pos += used_in;
    if (out_now == 0 && made > 0) rc = Z_DATA_ERROR;
    if (out_now > 0) out_pos += made;
    if (rc == Z_BUF_ERROR || (rc == Z_OK && used_in == 0 && made == 0)) rc = Z_DATA_ERROR;
  }
  inflateEnd(&zs);
  if (rc != Z_STREAM_END || out_pos != expected_size || in_pos != size) {
    return CorruptError("deflate stream is malformed or has the wrong length");
  }
  return out;
}

std::uint32_t Crc32(std::uint32_t crc, const std::uint8_t* data, std::size_t size) {
  uLong c = crc;
  while (size > 0) {
    const uInt n = static_cast<uInt>(std::min<std::size_t>(size, 1u << 30));
    c = crc32(c, data, n);
    data += n;
    size -= n;
  }
  return static_cast<std::uint32_t>(c);
}

}  // namespace linemap
