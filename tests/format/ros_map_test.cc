// Map YAML parsing, writing maps as map_saver does, and the round trip over
// the bundled maps and every map in ../shared/maps.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <filesystem>
#include <random>

#include "format/pixel_classifier.h"
#include "linemap/map_io.h"
#include "tests/testing/test_support.h"

namespace linemap {
namespace {

using testing::FileExists;
using testing::ListDir;
using testing::MakeTempDir;
using testing::ReadFile;
using testing::WriteFile;

Grid RandomGrid(int width, int height, unsigned seed) {
  Grid grid(width, height);
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> state(0, 2);
  for (Cell& c : grid.mutable_cells()) c = static_cast<Cell>(state(rng));
  return grid;
}

TEST(RosMapTest, SaveWritesMapSaverTrinaryPgm) {
  const std::string dir = MakeTempDir("ros");
  Grid grid(3, 1, Cell::kUnknown);
  grid.set(0, 0, Cell::kOccupied);
  grid.set(1, 0, Cell::kFree);
  ASSERT_TRUE(SaveRosMap(dir + "/out.yaml", grid).ok());
  const std::string pgm = ReadFile(dir + "/out.pgm");
  ASSERT_GE(pgm.size(), 3u);
  EXPECT_EQ(pgm.substr(0, 2), "P5");
  EXPECT_EQ(pgm.substr(pgm.size() - 3), std::string("\x00\xfe\xcd", 3));
  const std::string yaml = ReadFile(dir + "/out.yaml");
  EXPECT_NE(yaml.find("image: out.pgm"), std::string::npos);
  EXPECT_NE(yaml.find("mode: trinary"), std::string::npos);
  EXPECT_NE(yaml.find("negate: 0"), std::string::npos);
  // Only the two files: no temporary left behind.
  EXPECT_EQ(ListDir(dir), (std::vector<std::string>{"out.pgm", "out.yaml"}));
}

TEST(RosMapTest, RandomGridsRoundTripWithMetadata) {
  const std::string dir = MakeTempDir("ros");
  for (unsigned seed = 1; seed <= 5; ++seed) {
    Grid grid = RandomGrid(17 + seed, 9 + 2 * seed, seed);
    grid.meta.resolution = 0.037 * seed;
    grid.meta.origin = {-54.949999999999996, 1.0 / 3.0, 0.1 * seed};
    grid.meta.free_thresh = 0.1 + 0.015 * seed;  // 0.115 .. 0.175: 205 stays unknown
    grid.meta.occupied_thresh = 0.7;
    const std::string path = dir + "/m" + std::to_string(seed) + ".yaml";
    ASSERT_TRUE(SaveRosMap(path, grid).ok());
    StatusOr<Grid> back = LoadRosMap(path);
    ASSERT_TRUE(back.ok()) << back.status().message();
    EXPECT_EQ(back->cells(), grid.cells()) << "seed " << seed;
    EXPECT_EQ(back->meta, grid.meta) << "seed " << seed;
  }
}

// Every legal file name survives the YAML: the image the saved YAML names
// is read back, by LoadRosMap and by yaml-cpp (as nav2's map_server reads
// it), byte for byte. Plain names stay unquoted, as map_saver writes them.
TEST(RosMapTest, AnyFileNameRoundTripsThroughTheYaml) {
  const std::string dir = MakeTempDir("ros_names");
  const Grid grid = RandomGrid(5, 4, 9);
  const std::vector<std::string> stems = {"plain_map-2.v1",
                                          "my map #2",
                                          "map: v2",
                                          "[x]",
                                          "{x}",
                                          "&a",
                                          "*a",
                                          "!tag",
                                          "%x",
                                          "@x",
                                          "`x",
                                          "|x",
                                          ">x",
                                          "?x",
                                          ",x",
                                          "-x",
                                          "- x",
                                          "#",
                                          "a'b",
                                          "''",
                                          "a\"b",
                                          "a\\b",
                                          " lead",
                                          "trail ",
                                          "two  spaces",
                                          "tab\there",
                                          "new\nline",
                                          "cr\rx",
                                          "\x01\x1f\x7f",
                                          "caf\xc3\xa9",
                                          "\xe2\x80\xa8sep",
                                          "\xc2\x85nel",
                                          "\xff\xfe raw bytes",
                                          "\xef\xbb\xbf"
                                          "bom",
                                          "'quoted'",
                                          "\"dq\"",
                                          "a: b # c",
                                          "..."};
  for (const std::string& stem : stems) {
    SCOPED_TRACE(stem);
    const std::string yaml_path = dir + "/" + stem + ".yaml";
    ASSERT_TRUE(SaveRosMap(yaml_path, grid).ok());
    ASSERT_TRUE(FileExists(dir + "/" + stem + ".pgm"));
    StatusOr<Grid> back = LoadRosMap(yaml_path);
    ASSERT_TRUE(back.ok()) << back.status().message();
    EXPECT_EQ(back->cells(), grid.cells());
    const YAML::Node doc = YAML::Load(ReadFile(yaml_path));
    EXPECT_EQ(doc["image"].as<std::string>(), stem + ".pgm");
    EXPECT_DOUBLE_EQ(doc["resolution"].as<double>(), grid.meta.resolution);
    StatusOr<std::string> image = RosMapImagePath(yaml_path);
    ASSERT_TRUE(image.ok()) << image.status().message();
    EXPECT_EQ(*image, dir + "/" + stem + ".pgm");
    std::filesystem::remove(yaml_path);
    std::filesystem::remove(dir + "/" + stem + ".pgm");
  }
  ASSERT_TRUE(SaveRosMap(dir + "/plain_map-2.v1.yaml", grid).ok());
  EXPECT_EQ(ReadFile(dir + "/plain_map-2.v1.yaml").rfind("image: plain_map-2.v1.pgm\n", 0), 0u);
  ASSERT_TRUE(SaveRosMap(dir + "/it's.yaml", grid).ok());
  EXPECT_EQ(ReadFile(dir + "/it's.yaml").rfind("image: 'it''s.pgm'\n", 0), 0u);
  ASSERT_TRUE(SaveRosMap(dir + "/a\tb.yaml", grid).ok());
  EXPECT_EQ(ReadFile(dir + "/a\tb.yaml").rfind("image: \"a\\x09b.pgm\"\n", 0), 0u);
}

TEST(RosMapTest, ImagePathOfAMap) {
  const std::string dir = MakeTempDir("ros_image_path");
  WriteFile(dir + "/rel.yaml", "image: sub/m.pgm\nresolution: 0.05\norigin: [0, 0, 0]\n");
  WriteFile(dir + "/abs.yaml", "image: /maps/m.pgm\nresolution: 0.05\norigin: [0, 0, 0]\n");
  EXPECT_EQ(RosMapImagePath(dir + "/rel.yaml").value(), dir + "/sub/m.pgm");
  EXPECT_EQ(RosMapImagePath(dir + "/abs.yaml").value(), "/maps/m.pgm");
  EXPECT_EQ(RosMapImagePath(dir + "/bare.pgm").value(), dir + "/bare.pgm");
  EXPECT_EQ(RosMapImagePath(dir + "/missing.yaml").status().code(), StatusCode::kNotFound);
}

TEST(RosMapTest, ThresholdsThatCannotHoldMapSaverValuesFallBackToDefaults) {
  const std::string dir = MakeTempDir("ros");
  // nav2's depot.yaml: free_thresh 0.25 reads grey 205 as free.
  Grid depot_like = RandomGrid(8, 8, 42);
  depot_like.meta.free_thresh = 0.25;
  // negate 1 swaps dark and light; map_saver's PGM is never negated.
  Grid negated = RandomGrid(8, 8, 43);
  negated.meta.negate = true;
  for (const Grid& grid : {depot_like, negated}) {
    ASSERT_TRUE(SaveRosMap(dir + "/m.yaml", grid).ok());
    const std::string pgm = ReadFile(dir + "/m.pgm");
    const std::string raster = pgm.substr(pgm.size() - 64);
    EXPECT_EQ(raster.find_first_not_of(std::string("\x00\xfe\xcd", 3)), std::string::npos)
        << "only map_saver's grey values";
    StatusOr<Grid> back = LoadRosMap(dir + "/m.yaml");
    ASSERT_TRUE(back.ok());
    EXPECT_EQ(back->cells(), grid.cells());
    EXPECT_FALSE(back->meta.negate);
    EXPECT_DOUBLE_EQ(back->meta.free_thresh, kDefaultFreeThresh);
    EXPECT_DOUBLE_EQ(back->meta.occupied_thresh, kDefaultOccupiedThresh);
  }
}

TEST(RosMapTest, YamlErrorsNameTheFile) {
  const std::string dir = MakeTempDir("ros");
  WriteFile(dir + "/img.pgm", std::string("P5 1 1 255\n") + std::string("\x00", 1));
  struct Case {
    const char* name;
    const char* text;
    StatusCode code;
  };
  const Case cases[] = {
      {"no_image.yaml", "resolution: 0.05\norigin: [0, 0, 0]\n", StatusCode::kInvalidArgument},
      {"negative_resolution.yaml", "image: img.pgm\nresolution: -0.05\norigin: [0, 0, 0]\n",
       StatusCode::kInvalidArgument},
      {"zero_resolution.yaml", "image: img.pgm\nresolution: 0\norigin: [0, 0, 0]\n",
       StatusCode::kInvalidArgument},
      {"text_resolution.yaml", "image: img.pgm\nresolution: fine\norigin: [0, 0, 0]\n",
       StatusCode::kInvalidArgument},
      {"short_origin.yaml", "image: img.pgm\nresolution: 0.05\norigin: [1, 2]\n",
       StatusCode::kInvalidArgument},
      {"no_origin.yaml", "image: img.pgm\nresolution: 0.05\n", StatusCode::kInvalidArgument},
      {"bad_mode.yaml", "image: img.pgm\nresolution: 0.05\norigin: [0, 0, 0]\nmode: fancy\n",
       StatusCode::kInvalidArgument},
      {"bad_thresh.yaml", "image: img.pgm\nresolution: 0.05\norigin: [0, 0, 0]\nfree_thresh: 1.5\n",
       StatusCode::kInvalidArgument},
      {"not_a_map.yaml", "- just\n- a list\n", StatusCode::kInvalidArgument},
      {"broken.yaml", "image: [unclosed\n", StatusCode::kInvalidArgument},
      {"missing_image.yaml", "image: nothere.pgm\nresolution: 0.05\norigin: [0, 0, 0]\n",
       StatusCode::kNotFound},
  };
  for (const Case& c : cases) {
    WriteFile(dir + "/" + c.name, c.text);
    StatusOr<Grid> grid = LoadRosMap(dir + "/" + c.name);
    ASSERT_FALSE(grid.ok()) << c.name;
    EXPECT_EQ(grid.status().code(), c.code) << c.name << ": " << grid.status().message();
    EXPECT_NE(grid.status().message().find(c.name), std::string::npos) << grid.status().message();
  }
  EXPECT_EQ(LoadRosMap(dir + "/absent.yaml").status().code(), StatusCode::kNotFound);
  EXPECT_EQ(LoadRosMap(dir).status().code(), StatusCode::kInvalidArgument);
}

// nav2's map_server (and ROS 1's) refuses a YAML without origin, as one
// without image or resolution: a map read at 0,0,0 instead would put every
// cell in the wrong place without a word.
TEST(RosMapTest, YamlWithoutOriginIsRefusedAsMapServerRefusesIt) {
  const std::string dir = MakeTempDir("ros");
  WriteFile(dir + "/img.pgm", std::string("P5 1 1 255\n") + std::string("\x00", 1));
  WriteFile(dir + "/no_origin.yaml", "image: img.pgm\nresolution: 0.05\n");
  // Not even when the caller overrides it: a missing resolution is refused
  // with an override too.
  MapLoadOptions overridden;
  overridden.origin = Pose2D{};
  for (const MapLoadOptions& options : {MapLoadOptions{}, overridden}) {
    StatusOr<Grid> grid = LoadRosMap(dir + "/no_origin.yaml", options);
    ASSERT_FALSE(grid.ok());
    EXPECT_EQ(grid.status().code(), StatusCode::kInvalidArgument);
    EXPECT_NE(grid.status().message().find("no_origin.yaml"), std::string::npos)
        << grid.status().message();
    EXPECT_NE(grid.status().message().find("'origin'"), std::string::npos)
        << grid.status().message();
  }
  EXPECT_FALSE(RosMapImagePath(dir + "/no_origin.yaml").ok());
}

TEST(RosMapTest, FailedSaveLeavesExistingFilesIntact) {
  const std::string dir = MakeTempDir("ros");
  WriteFile(dir + "/keep.yaml", "old yaml");
  EXPECT_FALSE(SaveRosMap(dir + "/keep.yaml", Grid()).ok());  // empty grid
  EXPECT_EQ(ReadFile(dir + "/keep.yaml"), "old yaml");
  EXPECT_FALSE(SaveRosMap(dir + "/missing_dir/x.yaml", RandomGrid(2, 2, 1)).ok());
  EXPECT_FALSE(FileExists(dir + "/missing_dir"));
}

void ExpectRoundTrip(const std::string& yaml) {
  SCOPED_TRACE(yaml);
  StatusOr<Grid> grid = LoadRosMap(yaml);
  ASSERT_TRUE(grid.ok()) << grid.status().message();
  const std::string dir = MakeTempDir("rt");
  ASSERT_TRUE(SaveRosMap(dir + "/copy.yaml", *grid).ok());
  StatusOr<Grid> back = LoadRosMap(dir + "/copy.yaml");
  ASSERT_TRUE(back.ok()) << back.status().message();
  EXPECT_EQ(back->width(), grid->width());
  EXPECT_EQ(back->height(), grid->height());
  EXPECT_TRUE(back->cells() == grid->cells());
  EXPECT_DOUBLE_EQ(back->meta.resolution, grid->meta.resolution);
  EXPECT_EQ(back->meta.origin, grid->meta.origin);
  // The thresholds survive unless they read map_saver's 205 as free (then
  // the documented fallback 0.65 / 0.196 is written).
  const bool holds_205 = ClassifyGrey8(kPgmUnknown, grid->meta) == Cell::kUnknown;
  EXPECT_DOUBLE_EQ(back->meta.free_thresh, holds_205 ? grid->meta.free_thresh : kDefaultFreeThresh);
  std::filesystem::remove_all(dir);
}

TEST(RosMapTest, BundledMapsRoundTrip) {
  const auto yamls = testing::FindYamlFiles(testing::BundledMapsDir());
  ASSERT_GE(yamls.size(), 3u);
  for (const std::string& yaml : yamls) ExpectRoundTrip(yaml);
}

TEST(RosMapTest, SharedMapsLoadAndRoundTrip) {
  const std::string shared = testing::SharedMapsDir();
  if (shared.empty()) GTEST_SKIP() << "../shared/maps is absent";
  int loaded = 0;
  for (const std::string& yaml : testing::FindYamlFiles(shared)) {
    if (yaml.find("empty_room.yaml") != std::string::npos) {
      // Names empty.pgm, which is not there (as in its source repository).
      EXPECT_EQ(LoadRosMap(yaml).status().code(), StatusCode::kNotFound);
      continue;
    }
    ExpectRoundTrip(yaml);
    ++loaded;
  }
  for (const std::string& image : testing::FindBareImages(shared)) {
    StatusOr<Grid> grid = LoadRosMap(image);
    ASSERT_TRUE(grid.ok()) << grid.status().message();
    ++loaded;
  }
  EXPECT_GE(loaded, 24);
}

// The PGM SaveRosMap writes, byte for byte, from a reference written out
// here: map_saver's header, then the rows top first. The grid is wider and
// taller than the save's 1 MiB bands, so bands join in the file.
std::string ReferencePgm(const Grid& grid) {
  std::string pgm = "P5\n# CREATOR: linemap\n" + std::to_string(grid.width()) + " " +
                    std::to_string(grid.height()) + "\n255\n";
  for (int row = grid.height() - 1; row >= 0; --row) {
    for (int col = 0; col < grid.width(); ++col) {
      const Cell c = grid.at(col, row);
      pgm += static_cast<char>(c == Cell::kFree ? 254 : c == Cell::kOccupied ? 0 : 205);
    }
  }
  return pgm;
}

TEST(RosMapTest, SaveWritesEveryBandInPlace) {
  const std::string dir = MakeTempDir("ros_bands");
  const Grid grid = RandomGrid(1500, 1901, 3);  // 2.85 Mcells: three bands
  ASSERT_TRUE(SaveRosMap(dir + "/big.yaml", grid, Durability::kUnsynced).ok());
  EXPECT_TRUE(ReadFile(dir + "/big.pgm") == ReferencePgm(grid));
  EXPECT_EQ(ListDir(dir), (std::vector<std::string>{"big.pgm", "big.yaml"}));
}

// RosMapWriter takes rectangles in any order and gives SaveRosMap's files.
TEST(RosMapWriterTest, RectanglesInAnyOrderGiveTheSavedFiles) {
  const std::string dir = MakeTempDir("ros_writer");
  Grid grid = RandomGrid(301, 207, 9);
  grid.meta.origin = {2.5, -1.25, 0.5};
  ASSERT_TRUE(SaveRosMap(dir + "/whole.yaml", grid).ok());
  StatusOr<RosMapWriter> writer =
      RosMapWriter::Open(dir + "/pieces.yaml", grid.width(), grid.height(), grid.meta);
  ASSERT_TRUE(writer.ok()) << writer.status().message();
  // A 4 x 3 cut of the map, shuffled.
  struct Piece {
    int col0, row0, cols, rows;
  };
  std::vector<Piece> pieces;
  const int col_cuts[] = {0, 1, 150, 300, 301};
  const int row_cuts[] = {0, 100, 206, 207};
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 3; ++j) {
      pieces.push_back(
          {col_cuts[i], row_cuts[j], col_cuts[i + 1] - col_cuts[i], row_cuts[j + 1] - row_cuts[j]});
    }
  }
  std::shuffle(pieces.begin(), pieces.end(), std::mt19937(4));
  for (const Piece& p : pieces) {
    std::vector<Cell> cells;
    for (int r = p.row0; r < p.row0 + p.rows; ++r) {
      for (int c = p.col0; c < p.col0 + p.cols; ++c) cells.push_back(grid.at(c, r));
    }
    ASSERT_TRUE(writer->WriteCells(p.col0, p.row0, p.cols, p.rows, cells.data()).ok());
  }
  EXPECT_FALSE(FileExists(dir + "/pieces.pgm")) << "visible before Commit()";
  ASSERT_TRUE(writer->Commit().ok());
  EXPECT_TRUE(ReadFile(dir + "/pieces.pgm") == ReadFile(dir + "/whole.pgm"));
  std::string yaml = ReadFile(dir + "/pieces.yaml");
  const std::string whole_yaml = ReadFile(dir + "/whole.yaml");
  EXPECT_EQ(yaml.replace(yaml.find("pieces.pgm"), 10, "whole.pgm"), whole_yaml);
}

TEST(RosMapWriterTest, RefusesCellsOutsideTheMapAndAnIncompleteMap) {
  const std::string dir = MakeTempDir("ros_writer");
  WriteFile(dir + "/old.yaml", "old yaml");
  WriteFile(dir + "/old.pgm", "old pgm");
  {
    StatusOr<RosMapWriter> writer = RosMapWriter::Open(dir + "/old.yaml", 10, 5, MapMetadata());
    ASSERT_TRUE(writer.ok());
    const std::vector<Cell> cells(50, Cell::kFree);
    EXPECT_EQ(writer->WriteCells(5, 0, 6, 1, cells.data()).code(), StatusCode::kInvalidArgument);
    EXPECT_EQ(writer->WriteCells(0, -1, 1, 1, cells.data()).code(), StatusCode::kInvalidArgument);
    EXPECT_EQ(writer->WriteCells(0, 0, 0, 1, cells.data()).code(), StatusCode::kInvalidArgument);
    ASSERT_TRUE(writer->WriteCells(0, 0, 10, 4, cells.data()).ok());
    const Status committed = writer->Commit();  // the top row is missing
    EXPECT_FALSE(committed.ok());
    EXPECT_NE(committed.message().find("40 of 50"), std::string::npos) << committed.message();
  }
  EXPECT_EQ(ReadFile(dir + "/old.yaml"), "old yaml");
  EXPECT_EQ(ReadFile(dir + "/old.pgm"), "old pgm");
  EXPECT_EQ(ListDir(dir), (std::vector<std::string>{"old.pgm", "old.yaml"}));
  EXPECT_EQ(RosMapWriter::Open(dir + "/x.pgm", 1, 1, MapMetadata()).status().code(),
            StatusCode::kInvalidArgument);
  EXPECT_EQ(RosMapWriter::Open(dir + "/x.yaml", 0, 1, MapMetadata()).status().code(),
            StatusCode::kInvalidArgument);
}

}  // namespace
}  // namespace linemap
