// Fuzz target: the .lmap decoder (versions 1.0 and 2.0). Any input must give
// a grid or an error, never a crash, a hang or a huge allocation. The cell
// limit is lowered from the default 2^30 so that a header claiming a huge
// map is refused instead of allocating a gigabyte per execution.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "linemap/codec.h"
#include "tests/fuzz/fix_chunk_crcs.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::vector<std::uint8_t> bytes = linemap::fuzzing::WithChunkCrcsFixed(data, size);
  linemap::DecodeLimits limits;
  limits.max_cells = std::uint64_t{1} << 24;
  // The layers' item limits too: an empty range-coded stream decodes as
  // any number of the smallest items (57 bytes can ask for 2^24 walls, some
  // 1.5 GB and 25 s under the sanitizers; 54 bytes for 2^20 rooms), which
  // the default limits allow.
  limits.max_segments = std::uint64_t{1} << 16;
  limits.max_chain_length = std::uint64_t{1} << 18;
  limits.max_objects = std::uint64_t{1} << 14;
  limits.max_threads = 1;  // one execution, one core
  (void)linemap::DecodeLmapContents(bytes, limits);
  return 0;
}
