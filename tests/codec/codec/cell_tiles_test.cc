// The CELL chunk's tiles: what model the encoder writes, that threads do
// not change the bytes, and that files whose tiles use the models before
// the layer context still decode.
#include "codec/codec/cell_tiles.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "format/byte_io.h"
#include "linemap/codec.h"
#include "linemap/map_io.h"
#include "linemap/vector_layers.h"
#include "tests/testing/test_support.h"

namespace linemap {
namespace {

Grid Depot() {
  StatusOr<Grid> g = LoadRosMap(testing::BundledMapsDir() + "/nav2/depot.yaml");
  EXPECT_TRUE(g.ok()) << g.status().ToString();
  return g.ok() ? std::move(*g) : Grid();
}

// The first byte of each non-empty tile's data in a CELL body (its model
// id in bits 0-4, spec/tile_coding.md section 2).
std::vector<unsigned> TileModels(const std::vector<std::uint8_t>& body, const TileLayout& layout) {
  ByteCursor cursor(body);
  EXPECT_TRUE(cursor.ReadVarint("tile size").ok());
  std::vector<std::uint64_t> lengths;
  for (std::uint64_t i = 0; i < layout.count(); ++i) {
    StatusOr<std::uint64_t> n = cursor.ReadVarint("length");
    EXPECT_TRUE(n.ok());
    lengths.push_back(n.ok() ? *n : 0);
  }
  std::vector<unsigned> models;
  for (std::uint64_t n : lengths) {
    StatusOr<const std::uint8_t*> data = cursor.ReadBytes(static_cast<std::size_t>(n), "tile");
    EXPECT_TRUE(data.ok());
    if (data.ok() && n > 0) models.push_back((*data)[0] & 31u);
  }
  return models;
}

TEST(CellTilesTest, TilesAreCodedWithTheLayerContextWhateverTheThreads) {
  const Grid g = Depot();
  const std::vector<WallPolyline> walls;
  const std::vector<RoomOutline> rooms;
  const std::vector<FurnitureObject> furniture;
  const LayerIndex layers(walls, rooms, furniture);
  for (int tile_size : {16, 97, 256}) {
    const std::vector<std::uint8_t> one = EncodeCellChunk(g, layers, tile_size, 1);
    EXPECT_EQ(one, EncodeCellChunk(g, layers, tile_size, 3)) << tile_size;
    const TileLayout layout(g.width(), g.height(), tile_size);
    for (unsigned model : TileModels(one, layout)) {
      EXPECT_EQ(model, static_cast<unsigned>(TileModel::kLayerContext));
    }
    std::vector<Cell> out(g.size(), Cell::kFree);
    for (int threads : {1, 2}) {
      const Status s = DecodeCellChunk(one, layers, g.width(), g.height(),
                                       CellRect{0, 0, g.width(), g.height()}, threads, out.data());
      ASSERT_TRUE(s.ok()) << s.ToString();
      EXPECT_EQ(out, g.cells()) << tile_size << " " << threads;
    }
  }
}

// Written by the encoder of 2.0 (tile model 0 in every tile, before the
// layer context): it decodes to its map forever.
TEST(CellTilesTest, TemplateModelFileDecodes) {
  StatusOr<Grid> decoded =
      LoadLmap(testing::SourceDir() + "/tests/data/lmap/depot_v2_0_template_tiles.lmap");
  ASSERT_TRUE(decoded.ok()) << decoded.status().ToString();
  EXPECT_EQ(*decoded, Depot());
}

}  // namespace
}  // namespace linemap
