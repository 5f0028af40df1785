// DecodeLmapToRosMap: the files it writes band by band equal those of the
// whole decode saved by SaveRosMap (on the bundled maps with large and small
// tiles, on 1.0 files, and on a map wide enough to be cut into column
// groups), and bad inputs fail naming the file, writing nothing.
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "linemap/codec.h"
#include "linemap/map_io.h"
#include "tests/testing/test_support.h"

namespace linemap {
namespace {

using testing::ListDir;
using testing::MakeTempDir;
using testing::ReadFile;

// Decodes `lmap` both ways into `dir` and compares the files.
void ExpectSameFilesAsWholeDecode(const std::string& dir, const std::string& lmap,
                                  const Grid& input) {
  StatusOr<Grid> whole = LoadLmap(lmap);
  ASSERT_TRUE(whole.ok()) << whole.status().message();
  ASSERT_TRUE(SaveRosMap(dir + "/whole.yaml", *whole, Durability::kUnsynced).ok());
  StatusOr<MapFileSummary> summary =
      DecodeLmapToRosMap(lmap, dir + "/banded.yaml", {}, Durability::kUnsynced);
  ASSERT_TRUE(summary.ok()) << summary.status().message();
  EXPECT_TRUE(ReadFile(dir + "/banded.pgm") == ReadFile(dir + "/whole.pgm"));
  std::string yaml = ReadFile(dir + "/banded.yaml");
  EXPECT_EQ(yaml.replace(yaml.find("banded.pgm"), 10, "whole.pgm"), ReadFile(dir + "/whole.yaml"));
  EXPECT_EQ(summary->width, input.width());
  EXPECT_EQ(summary->height, input.height());
  EXPECT_EQ(summary->meta, whole->meta);
  const CellCounts counts = input.Count();
  EXPECT_EQ(summary->counts.free, counts.free);
  EXPECT_EQ(summary->counts.occupied, counts.occupied);
  EXPECT_EQ(summary->counts.unknown, counts.unknown);
}

TEST(DecodeToMapFilesTest, BundledMapsGiveTheWholeDecodesFiles) {
  const std::vector<std::string> yamls = testing::FindYamlFiles(testing::BundledMapsDir());
  ASSERT_GE(yamls.size(), 3u);
  const std::string dir = MakeTempDir("decode_files");
  for (const std::string& yaml : yamls) {
    StatusOr<Grid> grid = LoadRosMap(yaml);
    ASSERT_TRUE(grid.ok()) << grid.status().message();
    // Default tiles; 16-cell tiles (many tile rows per band).
    EncodeOptions small_tiles;
    small_tiles.tile_size_cells = 16;
    small_tiles.vector_layers = false;
    for (const EncodeOptions& options : {EncodeOptions(), small_tiles}) {
      SCOPED_TRACE(yaml + " tile " + std::to_string(options.tile_size_cells));
      ASSERT_TRUE(SaveLmap(dir + "/map.lmap", *grid, options).ok());
      ExpectSameFilesAsWholeDecode(dir, dir + "/map.lmap", *grid);
    }
  }
}

// 1.0 files, which are no longer written: the fixtures, lossless and lossy
// (the counts are then the whole decode's).
TEST(DecodeToMapFilesTest, VersionOneFixturesGiveTheWholeDecodesFiles) {
  const std::string dir = MakeTempDir("decode_files_v1");
  for (const char* name : {"lse_arena_lossless.lmap", "depot_v1_residual.lmap",
                           "depot_v1_room_chains.lmap", "depot_lossy_rooms.lmap"}) {
    SCOPED_TRACE(name);
    const std::string lmap = testing::SourceDir() + "/tests/data/lmap/" + name;
    StatusOr<Grid> grid = LoadLmap(lmap);
    ASSERT_TRUE(grid.ok()) << grid.status().message();
    ExpectSameFilesAsWholeDecode(dir, lmap, *grid);
  }
}

// 25,000 x 1,030 cells: wider than a band holds with 1024-row tile rows
// (24 Mi cells), so each band is cut into two column groups, and the top
// band is a partial tile row of 6 rows.
TEST(DecodeToMapFilesTest, WideMapCutIntoColumnGroups) {
  constexpr int kWidth = 25000, kHeight = 1030;
  Grid grid(kWidth, kHeight, Cell::kFree);
  for (int r = 0; r < kHeight; ++r) {
    for (int c = 0; c < kWidth; ++c) {
      if (c % 97 == 0 || r % 89 == 0) grid.set(c, r, Cell::kOccupied);
      if ((c / 500 + r / 300) % 5 == 0) grid.set(c, r, Cell::kUnknown);
    }
  }
  const std::string dir = MakeTempDir("decode_files_wide");
  EncodeOptions options;
  options.vector_layers = false;
  options.tile_size_cells = 1024;  // the encoder would pick 512 here, whose rows fit a band
  ASSERT_TRUE(SaveLmap(dir + "/wide.lmap", grid, options).ok());
  ExpectSameFilesAsWholeDecode(dir, dir + "/wide.lmap", grid);
}

TEST(DecodeToMapFilesTest, BadInputsFailNamingTheFileAndWriteNothing) {
  const std::string dir = MakeTempDir("decode_files_bad");
  StatusOr<MapFileSummary> missing = DecodeLmapToRosMap(dir + "/none.lmap", dir + "/out.yaml");
  EXPECT_EQ(missing.status().code(), StatusCode::kNotFound);
  EXPECT_NE(missing.status().message().find("none.lmap"), std::string::npos);
  // A good file cut short in its CELL chunk.
  Grid grid(300, 200, Cell::kFree);
  for (int c = 0; c < 300; ++c) grid.set(c, 100, Cell::kOccupied);
  ASSERT_TRUE(SaveLmap(dir + "/good.lmap", grid).ok());
  const std::string good = ReadFile(dir + "/good.lmap");
  testing::WriteFile(dir + "/cut.lmap", good.substr(0, good.size() - 20));
  StatusOr<MapFileSummary> cut = DecodeLmapToRosMap(dir + "/cut.lmap", dir + "/out.yaml");
  EXPECT_FALSE(cut.ok());
  EXPECT_NE(cut.status().message().find("cut.lmap"), std::string::npos);
  EXPECT_EQ(DecodeLmapToRosMap(dir + "/good.lmap", dir + "/out.pgm").status().code(),
            StatusCode::kInvalidArgument);
  EXPECT_EQ(ListDir(dir), (std::vector<std::string>{"cut.lmap", "good.lmap"}));
}

}  // namespace
}  // namespace linemap
