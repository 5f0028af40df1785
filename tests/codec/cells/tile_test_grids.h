// Grids for the tile coder's tests (tile_coder_test.cc and
// tile_coding_spec_test.cc): random grids and tiles, which exercise every
// path of the scan, and the bundled maps, whose walls and rooms the layer
// contexts are made for.
#ifndef LINEMAP_TESTS_CODEC_CELLS_TILE_TEST_GRIDS_H_
#define LINEMAP_TESTS_CODEC_CELLS_TILE_TEST_GRIDS_H_

#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "codec/cells/tile_coder.h"
#include "linemap/grid.h"
#include "linemap/map_io.h"
#include "linemap/status.h"
#include "tests/testing/test_support.h"

namespace linemap::tile_test {

using Bytes = std::vector<std::uint8_t>;

inline Cell RandomCell(std::mt19937& rng) { return static_cast<Cell>(rng() % 3); }

// A width x height grid of one of three kinds: independent random cells
// (nothing to predict), rectangles of one value over a background (rows and
// blocks equal to the row below, the copy paths), or rectangles with a
// sprinkle of noise.
inline std::vector<Cell> RandomGrid(std::mt19937& rng, int width, int height) {
  const std::size_t n = static_cast<std::size_t>(width) * height;
  std::vector<Cell> cells(n, RandomCell(rng));
  const int kind = static_cast<int>(rng() % 3);
  if (kind == 0) {
    for (Cell& c : cells) c = RandomCell(rng);
    return cells;
  }
  const int rects = static_cast<int>(rng() % 6);
  for (int k = 0; k < rects && width > 0 && height > 0; ++k) {
    const int x0 = static_cast<int>(rng() % width);
    const int y0 = static_cast<int>(rng() % height);
    const int x1 = x0 + 1 + static_cast<int>(rng() % (width - x0));
    const int y1 = y0 + 1 + static_cast<int>(rng() % (height - y0));
    const Cell v = RandomCell(rng);
    for (int y = y0; y < y1; ++y) {
      for (int x = x0; x < x1; ++x) cells[static_cast<std::size_t>(y) * width + x] = v;
    }
  }
  if (kind == 2) {
    for (Cell& c : cells) {
      if (rng() % 20 == 0) c = RandomCell(rng);
    }
  }
  return cells;
}

inline CellRect RandomTile(std::mt19937& rng, int width, int height) {
  CellRect t;
  t.x0 = static_cast<int>(rng() % (width + 1));
  t.x1 = t.x0 + static_cast<int>(rng() % (width - t.x0 + 1));
  t.y0 = static_cast<int>(rng() % (height + 1));
  t.y1 = t.y0 + static_cast<int>(rng() % (height - t.y0 + 1));
  return t;
}

inline std::vector<Grid> BundledMaps() {
  std::vector<Grid> maps;
  for (const std::string& yaml : testing::FindYamlFiles(testing::BundledMapsDir())) {
    StatusOr<Grid> g = LoadRosMap(yaml);
    EXPECT_TRUE(g.ok()) << yaml << ": " << g.status().ToString();
    if (g.ok()) maps.push_back(std::move(*g));
  }
  EXPECT_GE(maps.size(), 4u);
  return maps;
}

}  // namespace linemap::tile_test

#endif  // LINEMAP_TESTS_CODEC_CELLS_TILE_TEST_GRIDS_H_
