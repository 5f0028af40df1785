// Files of maps coded a row of layer blocks at a time (row_encoder.h):
// SaveRosMapAsLmap, which reads the map's image row by row, writes the bytes
// EncodeLmap writes for the loaded grid, and they decode to the map.
#include "codec/lmap/row_encoder.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "linemap/codec.h"
#include "linemap/lmap_vectors.h"
#include "linemap/map_io.h"
#include "tests/testing/test_support.h"

namespace linemap {
namespace {

// A width x height map of nav2 depot copies (walls, rooms and furniture in
// every layer block).
Grid DepotCopies(int width, int height) {
  const StatusOr<Grid> depot = LoadRosMap(testing::BundledMapsDir() + "/nav2/depot.yaml");
  EXPECT_TRUE(depot.ok());
  return testing::TiledMap(*depot, width, height);
}

std::vector<std::uint8_t> Bytes(const std::string& text) {
  return std::vector<std::uint8_t>(text.begin(), text.end());
}

// Saves `grid` as a map YAML + PGM, saves that as an .lmap with
// SaveRosMapAsLmap, and checks the file against EncodeLmap's of the saved
// map and its decode against `grid`.
void ExpectSavedAsEncoded(const Grid& grid, const EncodeOptions& options, const std::string& tag) {
  const std::string dir = testing::MakeTempDir(tag);
  ASSERT_TRUE(SaveRosMap(dir + "/map.yaml", grid, Durability::kUnsynced).ok());
  StatusOr<LmapSaveSummary> saved =
      SaveRosMapAsLmap(dir + "/map.yaml", dir + "/map.lmap", options, {}, Durability::kUnsynced);
  ASSERT_TRUE(saved.ok()) << saved.status().ToString();
  EXPECT_EQ(saved->width, grid.width());
  EXPECT_EQ(saved->height, grid.height());
  const std::vector<std::uint8_t> file = Bytes(testing::ReadFile(dir + "/map.lmap"));
  EXPECT_EQ(saved->bytes, file.size());
  // The saved YAML may carry other thresholds than `grid` (map_saver's).
  StatusOr<Grid> loaded = LoadRosMap(dir + "/map.yaml");
  ASSERT_TRUE(loaded.ok());
  ASSERT_EQ(loaded->cells(), grid.cells());
  StatusOr<std::vector<std::uint8_t>> encoded = EncodeLmap(*loaded, options);
  ASSERT_TRUE(encoded.ok());
  EXPECT_EQ(file, *encoded) << tag;
  StatusOr<Grid> decoded = DecodeLmap(file);
  ASSERT_TRUE(decoded.ok()) << decoded.status().ToString();
  EXPECT_EQ(decoded->cells(), grid.cells()) << tag;
}

TEST(RowEncoderTest, CodesMapsOfSeveralSectionsExactOnly) {
  EncodeOptions options;
  EXPECT_TRUE(EncodesByRows(4097, 10, options));
  EXPECT_TRUE(EncodesByRows(10, 5000, options));
  EXPECT_FALSE(EncodesByRows(4096, 4096, options));  // one section
  // Sections must be whole blocks (2048 cells), and then the map is larger
  // than a block.
  options.layer_section_cells = 2048;
  EXPECT_TRUE(EncodesByRows(5000, 10, options));
  EXPECT_FALSE(EncodesByRows(2000, 1500, options));
  options.layer_section_cells = 1024;
  EXPECT_FALSE(EncodesByRows(5000, 5000, options));
  options.layer_section_cells = 0;
  options.tolerance_cells = 1;
  EXPECT_FALSE(EncodesByRows(5000, 5000, options));
}

TEST(RowEncoderTest, TallMapSavedAsItsImageIsReadIsTheEncodedFile) {
  // 900 x 4300 cells: three rows of layer blocks (2048, 2048, 204 rows),
  // each a row of sections; the tiles (512 cells: the map is over 4096 a
  // side) nest in the blocks.
  const Grid grid = DepotCopies(900, 4300);
  ExpectSavedAsEncoded(grid, EncodeOptions{}, "row_encoder_tall");
  EncodeOptions raster_only;
  raster_only.vector_layers = false;
  ExpectSavedAsEncoded(grid, raster_only, "row_encoder_tall_cells");
}

TEST(RowEncoderTest, TilesAcrossBlockRowsAndThreadsGiveTheSameFile) {
  // Tiles of 1000 and 3000 cells straddle the block rows (2048 cells): their
  // hints come from the items of two block rows. Sections hold one block
  // each (the default on maps over 4096 cells a side), or four.
  const Grid grid = DepotCopies(700, 4300);
  for (const int tile : {1000, 3000}) {
    EncodeOptions one;
    one.tile_size_cells = tile;
    one.max_threads = 1;
    EncodeOptions three = one;
    three.max_threads = 3;
    ExpectSavedAsEncoded(grid, one, "row_encoder_tile_" + std::to_string(tile));
    StatusOr<std::vector<std::uint8_t>> a = EncodeLmap(grid, one);
    StatusOr<std::vector<std::uint8_t>> b = EncodeLmap(grid, three);
    ASSERT_TRUE(a.ok() && b.ok());
    EXPECT_EQ(*a, *b) << "tile " << tile;
  }
  EncodeOptions four_block_sections;
  four_block_sections.layer_section_cells = 4096;
  ExpectSavedAsEncoded(grid, four_block_sections, "row_encoder_sections_4096");
}

TEST(RowEncoderTest, SectionsSmallerThanABlockDecodeExactly) {
  // Sections that cut a block put its rooms in other orders than their
  // extraction's (a room's chain clears the fill of rooms drawn before it):
  // such files are coded from the whole grid. willow-2010 with sections of
  // 16 or 1000 cells, and tiled past a section, once decoded 3 cells wrong.
  const StatusOr<Grid> willow =
      LoadRosMap(testing::BundledMapsDir() + "/turtlebot_apps/willow-2010-02-18-0.10.yaml");
  ASSERT_TRUE(willow.ok());
  const Grid tiled = testing::TiledMap(*willow, 4300, 1200);
  for (const Grid* grid : std::vector<const Grid*>{&*willow, &tiled}) {
    for (const int side : {16, 700, 1000}) {
      EncodeOptions options;
      options.layer_section_cells = side;
      StatusOr<std::vector<std::uint8_t>> file = EncodeLmap(*grid, options);
      ASSERT_TRUE(file.ok());
      StatusOr<Grid> decoded = DecodeLmap(*file);
      ASSERT_TRUE(decoded.ok()) << "sections of " << side << ": " << decoded.status().ToString();
      EXPECT_EQ(decoded->cells(), grid->cells()) << "sections of " << side;
    }
  }
}

TEST(RowEncoderTest, ProgressRisesToOneAfterEachBlockRow) {
  // 700 x 4300 cells: three block rows, then the file.
  std::vector<double> reports;
  EncodeOptions options;
  options.progress = [&reports](double done) { reports.push_back(done); };
  ASSERT_TRUE(EncodeLmap(DepotCopies(700, 4300), options).ok());
  ASSERT_EQ(reports.size(), 4u);
  for (std::size_t i = 1; i < reports.size(); ++i) EXPECT_GT(reports[i], reports[i - 1]);
  EXPECT_GT(reports.front(), 0.0);
  EXPECT_EQ(reports.back(), 1.0);
  // A map of one section reports once, when its file is complete.
  reports.clear();
  ASSERT_TRUE(EncodeLmap(DepotCopies(300, 200), options).ok());
  EXPECT_EQ(reports, std::vector<double>{1.0});
}

TEST(RowEncoderTest, RoomsAreNumberedInFileOrder) {
  const Grid grid = DepotCopies(4200, 700);
  StatusOr<std::vector<std::uint8_t>> file = EncodeLmap(grid);
  ASSERT_TRUE(file.ok());
  StatusOr<LmapVectors> vectors = DecodeLmapVectors(*file);
  ASSERT_TRUE(vectors.ok());
  ASSERT_GT(vectors->rooms.size(), 8u);
  for (std::size_t i = 0; i < vectors->rooms.size(); ++i) {
    EXPECT_EQ(vectors->rooms[i].id, i + 1);
  }
  for (const FurnitureObject& object : vectors->furniture) {
    EXPECT_LE(object.room_id, static_cast<std::int32_t>(vectors->rooms.size()));
  }
}

TEST(RowEncoderTest, SmallMapSavedFromItsFileIsTheEncodedFile) {
  // One section: the grid is loaded and coded whole.
  const StatusOr<Grid> depot = LoadRosMap(testing::BundledMapsDir() + "/nav2/depot.yaml");
  ASSERT_TRUE(depot.ok());
  ExpectSavedAsEncoded(*depot, EncodeOptions{}, "row_encoder_small");
}

TEST(RowEncoderTest, ImageDefectMetWhileCodingFailsNamingItAndWritesNothing) {
  // A PGM whose last row (the map's lowest, read last) holds a sample above
  // its maxval: the first rows are coded before it is met.
  const std::string dir = testing::MakeTempDir("row_encoder_bad_sample");
  const int w = 4200, h = 300;
  std::string pgm = "P5\n" + std::to_string(w) + " " + std::to_string(h) + "\n254\n";
  pgm += std::string(static_cast<std::size_t>(w) * h, static_cast<char>(254));
  pgm.back() = static_cast<char>(255);
  testing::WriteFile(dir + "/map.pgm", pgm);
  testing::WriteFile(dir + "/map.yaml",
                     "image: map.pgm\nresolution: 0.05\norigin: [0, 0, 0]\nnegate: 0\n"
                     "occupied_thresh: 0.65\nfree_thresh: 0.196\n");
  ASSERT_TRUE(EncodesByRows(w, h, EncodeOptions{}));
  for (const std::string source : {"map.yaml", "map.pgm"}) {
    StatusOr<LmapSaveSummary> saved = SaveRosMapAsLmap(dir + "/" + source, dir + "/map.lmap");
    ASSERT_FALSE(saved.ok());
    const std::string message = saved.status().message();
    EXPECT_NE(message.find("map.pgm"), std::string::npos) << message;
    EXPECT_NE(message.find(source), std::string::npos) << message;
    // Named once: the image's own error names it.
    EXPECT_EQ(message.find("map.pgm"), message.rfind("map.pgm")) << message;
    EXPECT_FALSE(testing::FileExists(dir + "/map.lmap"));
  }
}

TEST(RowEncoderTest, TruncatedImageFailsNamingItAndWritesNothing) {
  const std::string dir = testing::MakeTempDir("row_encoder_truncated");
  ASSERT_TRUE(SaveRosMap(dir + "/map.yaml", DepotCopies(4200, 300), Durability::kUnsynced).ok());
  const std::string pgm = testing::ReadFile(dir + "/map.pgm");
  // The last rows read (the map's lowest) are cut off.
  testing::WriteFile(dir + "/map.pgm", pgm.substr(0, pgm.size() - 3 * 4200));
  StatusOr<LmapSaveSummary> saved = SaveRosMapAsLmap(dir + "/map.yaml", dir + "/map.lmap");
  ASSERT_FALSE(saved.ok());
  EXPECT_NE(saved.status().message().find("map.pgm"), std::string::npos)
      << saved.status().message();
  EXPECT_FALSE(testing::FileExists(dir + "/map.lmap"));
  StatusOr<LmapSaveSummary> missing = SaveRosMapAsLmap(dir + "/none.yaml", dir + "/map.lmap");
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.status().message().find("none.yaml"), std::string::npos);
}

}  // namespace
}  // namespace linemap
