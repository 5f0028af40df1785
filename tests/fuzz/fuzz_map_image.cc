// Fuzz target: the PGM and PNG map-image decoders. Any input must give an
// image or an error, never a crash, a hang or a huge allocation.
#include <cstddef>
#include <cstdint>
#include <span>

#include "format/image.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::span<const std::uint8_t> bytes(data, size);
  constexpr std::uint64_t kMaxCells = std::uint64_t{1} << 22;
  (void)linemap::DecodePgm(bytes, "fuzz.pgm", kMaxCells);
  (void)linemap::DecodePng(bytes, "fuzz.png", kMaxCells);
  return 0;
}
