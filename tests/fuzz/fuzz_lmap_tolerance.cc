// Fuzz target: encode within a tolerance of 1..4 cells -> decode on small
// grids derived from the input (layout in fuzz_grid.h). Encoding must
// succeed, the decoded grid must have the input's dimensions and metadata
// and keep every guarantee of the tolerance (CheckTolerance); anything else
// aborts.
#include <cstddef>
#include <cstdint>

#include "codec/tolerance/simplify.h"
#include "linemap/codec.h"
#include "linemap/grid.h"
#include "tests/fuzz/fuzz_grid.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace linemap;
  if (size < fuzz::kHeaderBytes) return 0;
  const Grid grid = fuzz::GridFromBytes(data, size);
  const Grid decoded = fuzz::EncodeDecodeOrFail("lmap_tolerance", grid, data[2], /*exact=*/false);
  const EncodeOptions options = fuzz::OptionsFromByte(data[2], /*exact=*/false);
  if (!CheckTolerance(grid, decoded, options.tolerance_cells).Holds()) {
    fuzz::Fail("lmap_tolerance", "a guarantee of the tolerance fails on the decode");
  }
  return 0;
}
