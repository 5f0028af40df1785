// Shared by the round-trip fuzz targets: a small grid and encoder options
// derived from the fuzzer's bytes.
//
// Input layout: byte 0 -> width (1..64), byte 1 -> height (1..64), byte 2 ->
// encoder options (see OptionsFromByte: bit 2 compact cells (tile models 12
// and 3), bit 3 two threads, bit 5 no vector layers, bit 6 16-cell tiles,
// bits 6-7 the tolerance; bits 0, 1 and 4 chose 1.0 encoder options and
// are unused now), then one byte per cell (value % 3 is the Cell,
// row 0 first); cells past the end of the input are unknown. The height is
// cut so that the grid holds at most 4 cells per input cell byte plus 64:
// short inputs (which libFuzzer prefers) stay small grids, so executions
// stay cheap, and long unknown tails add nothing a shorter input lacks.
#ifndef LINEMAP_TESTS_FUZZ_FUZZ_GRID_H_
#define LINEMAP_TESTS_FUZZ_FUZZ_GRID_H_

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <utility>

#include "linemap/codec.h"
#include "linemap/grid.h"

namespace linemap::fuzz {

constexpr int kMaxSide = 64;
constexpr std::size_t kHeaderBytes = 3;

inline Grid GridFromBytes(const std::uint8_t* data, std::size_t size) {
  const int width = 1 + data[0] % kMaxSide;
  const std::size_t max_cells = 4 * (size - kHeaderBytes) + 64;
  const int max_height = static_cast<int>(std::max<std::size_t>(1, max_cells / width));
  const int height = std::min(1 + data[1] % kMaxSide, max_height);
  Grid grid(width, height, Cell::kUnknown);
  std::size_t next = kHeaderBytes;
  for (auto& cell : grid.mutable_cells()) {
    if (next >= size) break;
    cell = static_cast<Cell>(data[next++] % 3);
  }
  return grid;
}

inline EncodeOptions OptionsFromByte(std::uint8_t flags, bool exact) {
  EncodeOptions options;
  // Exact: a 2.x file (with or without its layers, in 16-cell or 1024-cell
  // tiles). Else within a tolerance of 1..4 cells (bits 6-7; BLKS where
  // blocks pay).
  options.tolerance_cells = exact ? 0 : 1 + ((flags >> 6) & 3);
  options.vector_layers = (flags & 32) == 0;
  options.tile_size_cells = (flags & 64) ? 16 : 1024;
  options.max_threads = (flags & 8) ? 2 : 1;
  options.compact = (flags & 4) != 0;
  return options;
}

[[noreturn]] inline void Fail(const char* target, const char* what, const Status& status = {}) {
  std::fprintf(stderr, "%s: %s%s%s\n", target, what, status.ok() ? "" : ": ",
               status.ok() ? "" : status.ToString().c_str());
  std::abort();
}

// Encodes `grid` (exact or within a tolerance, options from `flags`) and
// decodes the bytes; any error, or a decode of other dimensions or
// metadata (which no tolerance allows), aborts, naming `target`. Returns
// the decoded grid.
inline Grid EncodeDecodeOrFail(const char* target, const Grid& grid, std::uint8_t flags,
                               bool exact) {
  auto encoded = EncodeLmap(grid, OptionsFromByte(flags, exact));
  if (!encoded.ok()) Fail(target, "encode failed", encoded.status());
  auto decoded = DecodeLmap(*encoded);
  if (!decoded.ok()) Fail(target, "decode failed", decoded.status());
  if (decoded->width() != grid.width() || decoded->height() != grid.height() ||
      !(decoded->meta == grid.meta)) {
    Fail(target, "the decode changed the dimensions or metadata");
  }
  return *std::move(decoded);
}

}  // namespace linemap::fuzz

#endif  // LINEMAP_TESTS_FUZZ_FUZZ_GRID_H_
