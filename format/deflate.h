// zlib deflate / inflate of chunk payloads, with a hard cap on the inflated
// size so a small hostile payload cannot expand into a huge allocation.
#ifndef LINEMAP_FORMAT_DEFLATE_H_
#define LINEMAP_FORMAT_DEFLATE_H_

#include <cstddef>
#include <cstdint>
#include <vector>

#include "linemap/status.h"

namespace linemap {

// zlib stream (RFC 1950) at level 9, default window and strategy, so the
// output is the same for the same input and zlib version.
std::vector<std::uint8_t> DeflateBytes(const std::uint8_t* data, std::size_t size);

// Inflates exactly `expected_size` bytes; any other length, trailing data or a
// bad stream is kCorrupt. `expected_size` must already be checked against the
// caller's limit.
StatusOr<std::vector<std::uint8_t>> InflateBytes(const std::uint8_t* data, std::size_t size,
                                                 std::size_t expected_size);

// CRC-32 (ISO-HDLC, as zlib's crc32()) of `size` bytes continuing from `crc`.
std::uint32_t Crc32(std::uint32_t crc, const std::uint8_t* data, std::size_t size);

}  // namespace linemap

#endif  // LINEMAP_FORMAT_DEFLATE_H_
