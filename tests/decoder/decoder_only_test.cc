// The decoder's objects alone (CMake target linemap_decoder: format/ and the
// decoders under codec/, no encoder source, no line extractor, no
// segmentation): this program links nothing else, so a decoder that comes to
// need an encoder source fails to build here. The fixtures, written by
// earlier encoders, decode to their maps.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "format/deflate.h"
#include "linemap/codec.h"
#include "linemap/lmap_vectors.h"
#include "linemap/map_io.h"

namespace linemap {
namespace {

std::string Source(const std::string& path) { return std::string(LINEMAP_SOURCE_DIR) + path; }

Grid Map(const std::string& yaml) {
  StatusOr<Grid> map = LoadRosMap(Source("/tests/data/maps/" + yaml));
  EXPECT_TRUE(map.ok()) << map.status().ToString();
  return map.ok() ? std::move(*map) : Grid();
}

TEST(DecoderOnlyTest, FixturesOfEveryVersionDecodeToTheirMaps) {
  const std::pair<const char*, const char*> cases[] = {
      {"depot_v2.lmap", "nav2/depot.yaml"},
      {"depot_v2_tiles_64.lmap", "nav2/depot.yaml"},
      {"depot_v2_2_sections_64.lmap", "nav2/depot.yaml"},
      {"depot_v2_3_compact_tiles_64.lmap", "nav2/depot.yaml"},
      {"lse_arena_v2_0.lmap", "navtut/lse_arena.yaml"},
      {"depot_lossless.lmap", "nav2/depot.yaml"},     // version 1.0
      {"depot_v1_residual.lmap", "nav2/depot.yaml"},  // version 1.0, RESD
  };
  for (const auto& [file, map] : cases) {
    StatusOr<Grid> decoded = LoadLmap(Source("/tests/data/lmap/") + file);
    ASSERT_TRUE(decoded.ok()) << file << ": " << decoded.status().ToString();
    EXPECT_EQ(*decoded, Map(map)) << file;
  }
}

TEST(DecoderOnlyTest, LayersReadWithoutTheCells) {
  StatusOr<LmapVectors> layers = LoadLmapVectors(Source("/tests/data/lmap/depot_v2.lmap"));
  ASSERT_TRUE(layers.ok()) << layers.status().ToString();
  EXPECT_EQ(layers->width, 604);
  EXPECT_EQ(layers->height, 307);
  EXPECT_FALSE(layers->walls.empty());
  EXPECT_FALSE(layers->rooms.empty());
  EXPECT_FALSE(layers->furniture.empty());
}

TEST(DecoderOnlyTest, WindowIsTheCropOfTheMap) {
  const Grid map = Map("nav2/depot.yaml");
  const CellWindow window{70, 33, 301, 150};  // across tiles of 64 cells
  StatusOr<Grid> part = LoadLmapRegion(Source("/tests/data/lmap/depot_v2_tiles_64.lmap"), window);
  ASSERT_TRUE(part.ok()) << part.status().ToString();
  ASSERT_EQ(part->width(), window.col1 - window.col0);
  ASSERT_EQ(part->height(), window.row1 - window.row0);
  for (int r = window.row0; r < window.row1; ++r) {
    for (int c = window.col0; c < window.col1; ++c) {
      ASSERT_EQ(part->at(c - window.col0, r - window.row0), map.at(c, r)) << c << "," << r;
    }
  }
}

// CRC-32 of the cell values 0/1/2 in grid-row order.
std::uint32_t CellsCrc(const Grid& grid) {
  std::vector<std::uint8_t> values(grid.size());
  for (std::size_t i = 0; i < grid.size(); ++i) {
    values[i] = static_cast<std::uint8_t>(grid.cells()[i]);
  }
  return Crc32(0, values.data(), values.size());
}

// Files that are not exact decode to the grids recorded when they were
// written (the CRCs computed from `linemap decode`'s PGM by a separate
// script, as tests/codec/lmap/fixtures_test.cc does for its lossy files).
TEST(DecoderOnlyTest, FilesThatAreNotExactDecodeToTheirRecordedGrids) {
  const struct {
    const char* file;
    int width, height;
    std::uint32_t crc;
  } cases[] = {
      {"willow_v2_3_tolerance_1.lmap", 566, 608, 0xb02e60d6u},  // 2.3, BLKS
      {"depot_lossy.lmap", 604, 307, 0x6afc8617u},              // 1.0 lossy
  };
  for (const auto& c : cases) {
    StatusOr<Grid> decoded = LoadLmap(Source("/tests/data/lmap/") + c.file);
    ASSERT_TRUE(decoded.ok()) << c.file << ": " << decoded.status().ToString();
    EXPECT_EQ(decoded->width(), c.width) << c.file;
    EXPECT_EQ(decoded->height(), c.height) << c.file;
    EXPECT_EQ(CellsCrc(*decoded), c.crc) << c.file;
  }
}

}  // namespace
}  // namespace linemap
