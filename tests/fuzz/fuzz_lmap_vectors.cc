// Fuzz target: the vector-layer reader and window decoding of 2.0 files.
// Whatever the input, DecodeLmapVectors gives layers inside the map (walls of
// at least two points, closed 8-connected room and furniture chains) or an
// error; a window decode, with the window taken from the input's last bytes,
// gives that window's cells or an error, and when the whole grid decodes it
// gives the same cells as the whole grid there (a window reads only the
// tiles and layer sections that reach it). Anything else aborts.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "linemap/codec.h"
#include "linemap/lmap_vectors.h"

namespace {

[[noreturn]] void Fail(const char* what) {
  std::fprintf(stderr, "lmap_vectors: %s\n", what);
  std::abort();
}

bool Inside(const linemap::CellIndex& p, const linemap::LmapVectors& v) {
  return p.col >= 0 && p.row >= 0 && p.col < v.width && p.row < v.height;
}

void CheckChain(const std::vector<linemap::CellIndex>& chain, const linemap::LmapVectors& v) {
  if (chain.empty()) Fail("empty chain");
  for (std::size_t i = 0; i < chain.size(); ++i) {
    const linemap::CellIndex p = chain[i], q = chain[(i + 1) % chain.size()];
    if (!Inside(p, v)) Fail("chain cell outside the map");
    if (std::abs(p.col - q.col) > 1 || std::abs(p.row - q.row) > 1) Fail("chain not 8-connected");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::vector<std::uint8_t> bytes(data, data + size);
  linemap::DecodeLimits limits;
  limits.max_cells = std::uint64_t{1} << 24;
  limits.max_threads = 1;
  const auto vectors = linemap::DecodeLmapVectors(bytes, limits);
  if (!vectors.ok()) return 0;
  for (const auto& wall : vectors->walls) {
    if (wall.points.size() < 2) Fail("wall of fewer than two points");
    for (const auto& p : wall.points) {
      if (!Inside(p, *vectors)) Fail("wall point outside the map");
    }
  }
  for (const auto& room : vectors->rooms) CheckChain(room.chain, *vectors);
  for (const auto& object : vectors->furniture) CheckChain(object.outline, *vectors);
  if (vectors->width > 0 && vectors->height > 0 && size >= 4) {
    linemap::CellWindow w;
    w.col0 = data[size - 4] % vectors->width;
    w.row0 = data[size - 3] % vectors->height;
    w.col1 = w.col0 + 1 + data[size - 2] % (vectors->width - w.col0);
    w.row1 = w.row0 + 1 + data[size - 1] % (vectors->height - w.row0);
    const auto region = linemap::DecodeLmapRegion(bytes, w, limits);
    if (region.ok() &&
        (region->width() != w.col1 - w.col0 || region->height() != w.row1 - w.row0)) {
      Fail("window of the wrong size");
    }
    const auto whole = linemap::DecodeLmap(bytes, limits);
    if (whole.ok()) {
      if (!region.ok()) Fail("a window of a grid that decodes fails");
      for (int r = w.row0; r < w.row1; ++r) {
        for (int c = w.col0; c < w.col1; ++c) {
          if (region->at(c - w.col0, r - w.row0) != whole->at(c, r)) {
            Fail("a window differs from the whole grid");
          }
        }
      }
    }
  }
  return 0;
}
