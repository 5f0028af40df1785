// Fuzz target: the .lmap decoder with its default limits. Any input must give
// a grid or an error, never a crash, a hang or a huge allocation.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "linemap/codec.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::vector<std::uint8_t> bytes(data, data + size);
  (void)linemap::DecodeLmapContents(bytes);
  return 0;
}
