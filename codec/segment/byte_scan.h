// Scanning rows of byte flags for the next set (or clear) one, eight bytes
// at a time: most rows of a map's masks are long runs of zeros (open floor,
// unknown space), and the labelling, the wall-furniture search and the wall
// cover's search for edge cells no wall accounts for
// (codec/layers/wall_cover.cc) walk them.
#ifndef LINEMAP_CODEC_SEGMENT_BYTE_SCAN_H_
#define LINEMAP_CODEC_SEGMENT_BYTE_SCAN_H_

#include <cstdint>
#include <cstring>

namespace linemap {

// The first index >= `col` of `bytes[0, w)` whose byte is non-zero, or `w`.
inline int FirstNonZeroByte(const std::uint8_t* bytes, int col, int w) {
  while (col + 8 <= w) {
    std::uint64_t chunk;
    std::memcpy(&chunk, bytes + col, 8);
    if (chunk) break;
    col += 8;
  }
  while (col < w && !bytes[col]) ++col;
  return col;
}

// The first index >= `col` of `bytes[0, w)` whose byte is zero, or `w`: the
// end of a run of set flags (any non-zero byte is set).
inline int FirstZeroByte(const std::uint8_t* bytes, int col, int w) {
  constexpr std::uint64_t kOnes = 0x0101010101010101ULL;
  constexpr std::uint64_t kHighBits = 0x8080808080808080ULL;
  while (col + 8 <= w) {
    std::uint64_t chunk;
    std::memcpy(&chunk, bytes + col, 8);
    // Non-zero exactly when some byte of the chunk is zero.
    if ((chunk - kOnes) & ~chunk & kHighBits) break;
    col += 8;
  }
  while (col < w && bytes[col]) ++col;
  return col;
}

}  // namespace linemap

#endif  // LINEMAP_CODEC_SEGMENT_BYTE_SCAN_H_
