// Fuzz target: encode -> decode round trip on small grids derived from the
// input. Lossless must give back the identical grid; lossy must decode to a
// grid of the same dimensions. Any other outcome aborts (a finding).
//
// Input layout: byte 0 -> width (1..64), byte 1 -> height (1..64), byte 2 ->
// encoder options (bit 0: residual lossless method, bit 1: store segments,
// bit 2: store room chains), then one byte per cell (value % 3 is the Cell,
// row 0 first); cells past the end of the input are unknown.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "linemap/codec.h"
#include "linemap/grid.h"

namespace {

constexpr int kMaxSide = 64;
constexpr std::size_t kHeaderBytes = 3;

linemap::Grid GridFromBytes(const std::uint8_t* data, std::size_t size) {
  const int width = 1 + data[0] % kMaxSide;
  const int height = 1 + data[1] % kMaxSide;
  linemap::Grid grid(width, height, linemap::Cell::kUnknown);
  std::size_t next = kHeaderBytes;
  for (auto& cell : grid.mutable_cells()) {
    if (next >= size) break;
    cell = static_cast<linemap::Cell>(data[next++] % 3);
  }
  return grid;
}

linemap::EncodeOptions OptionsFromByte(std::uint8_t flags, bool lossless) {
  linemap::EncodeOptions options;
  options.lossless = lossless;
  options.lossless_method =
      (flags & 1) ? linemap::LosslessMethod::kResidual : linemap::LosslessMethod::kExactLayers;
  options.store_segments = (flags & 2) != 0;
  options.store_room_chains = (flags & 4) != 0;
  return options;
}

[[noreturn]] void Fail(const char* what, const linemap::Status& status) {
  std::fprintf(stderr, "lmap_roundtrip: %s: %s\n", what, status.ToString().c_str());
  std::abort();
}

void CheckLossless(const linemap::Grid& grid, std::uint8_t flags) {
  auto encoded = linemap::EncodeLmap(grid, OptionsFromByte(flags, /*lossless=*/true));
  if (!encoded.ok()) Fail("lossless encode failed", encoded.status());
  auto decoded = linemap::DecodeLmap(*encoded);
  if (!decoded.ok()) Fail("lossless decode failed", decoded.status());
  if (decoded->width() != grid.width() || decoded->height() != grid.height() ||
      decoded->cells() != grid.cells() || !(decoded->meta == grid.meta)) {
    std::fprintf(stderr, "lmap_roundtrip: lossless round trip changed the grid\n");
    std::abort();
  }
}

void CheckLossy(const linemap::Grid& grid, std::uint8_t flags) {
  auto encoded = linemap::EncodeLmap(grid, OptionsFromByte(flags, /*lossless=*/false));
  if (!encoded.ok()) Fail("lossy encode failed", encoded.status());
  auto decoded = linemap::DecodeLmap(*encoded);
  if (!decoded.ok()) Fail("lossy decode failed", decoded.status());
  if (decoded->width() != grid.width() || decoded->height() != grid.height()) {
    std::fprintf(stderr, "lmap_roundtrip: lossy round trip changed the dimensions\n");
    std::abort();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < kHeaderBytes) return 0;
  const linemap::Grid grid = GridFromBytes(data, size);
  CheckLossless(grid, data[2]);
  CheckLossy(grid, data[2]);
  return 0;
}
