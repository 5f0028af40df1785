// The decoding fuzz targets' inputs with every chunk's CRC made right
// (spec/format.md section 3), so that a mutation reaches the decoder behind
// the container instead of failing its CRC check: with the CRCs left as
// mutated, 12 minutes of fuzzing the decoder gained 20 coverage edges. The
// harness fixes the CRCs in every build, so a crash found here replays
// from the same input in the tests' replay targets.
#ifndef LINEMAP_TESTS_FUZZ_FIX_CHUNK_CRCS_H_
#define LINEMAP_TESTS_FUZZ_FIX_CHUNK_CRCS_H_

#include <zlib.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace linemap::fuzzing {

// A copy of `data` whose chunks, walked as the container lays them out (a
// 10-byte file header, then type, varint length, payload, CRC-32 of type
// and payload, little-endian), carry the CRC of their type and payload; the
// walk stops where the layout does not hold (a length past the end).
inline std::vector<std::uint8_t> WithChunkCrcsFixed(const std::uint8_t* data, std::size_t size) {
  std::vector<std::uint8_t> out(data, data + size);
  std::size_t pos = 10;
  while (pos + 4 < out.size()) {
    const std::size_t type = pos;
    pos += 4;
    std::uint64_t length = 0;
    int shift = 0;
    while (pos < out.size() && shift < 64) {
      const std::uint8_t b = out[pos++];
      length |= static_cast<std::uint64_t>(b & 0x7F) << shift;
      shift += 7;
      if (!(b & 0x80)) break;
    }
    if (length > out.size() || pos + length + 4 > out.size()) break;
    uLong crc = crc32(0L, out.data() + type, 4);
    crc = crc32(crc, out.data() + pos, static_cast<uInt>(length));
    pos += static_cast<std::size_t>(length);
    for (int k = 0; k < 4; ++k) out[pos + k] = static_cast<std::uint8_t>(crc >> (8 * k));
    pos += 4;
  }
  return out;
}

}  // namespace linemap::fuzzing

#endif  // LINEMAP_TESTS_FUZZ_FIX_CHUNK_CRCS_H_
