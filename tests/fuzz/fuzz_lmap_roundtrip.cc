// Fuzz target: exact encode -> decode round trip on small grids derived
// from the input (layout in fuzz_grid.h). The decoded grid must equal the
// input cell for cell, with the same metadata; anything else aborts (a
// finding). Files within a tolerance have their own target,
// fuzz_lmap_tolerance.cc, because checking their guarantees costs ten times
// as much per execution.
#include <cstddef>
#include <cstdint>

#include "linemap/codec.h"
#include "linemap/grid.h"
#include "tests/fuzz/fuzz_grid.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace linemap;
  if (size < fuzz::kHeaderBytes) return 0;
  const Grid grid = fuzz::GridFromBytes(data, size);
  const Grid decoded = fuzz::EncodeDecodeOrFail("lmap_roundtrip", grid, data[2], /*exact=*/true);
  if (decoded.cells() != grid.cells()) {
    fuzz::Fail("lmap_roundtrip", "the exact round trip changed the cells");
  }
  return 0;
}
