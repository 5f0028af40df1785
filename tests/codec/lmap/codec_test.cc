// Edge cases, metadata, determinism and saving of the .lmap encoder and
// decoder, and the 1.0 decoder on files built here and on the 1.0 fixtures
// (1.0 files are no longer written): limits, corruption handling, chains
// and Draco-coded segments. Version 2.x files are tested in
// codec_v2_test.cc.
#include "linemap/codec.h"

#include <gtest/gtest.h>

#include <optional>
#include <random>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "codec/lmap/chunk_coding.h"
#include "codec/lmap/draco_segments.h"
#include "format/byte_io.h"
#include "format/container.h"
#include "format/deflate.h"
#include "linemap/lmap_vectors.h"
#include "linemap/map_io.h"
#include "tests/testing/reference_tolerance.h"
#include "tests/testing/test_support.h"

namespace linemap {
namespace {

Grid RandomGrid(std::mt19937& rng, int width, int height, int blockiness) {
  Grid grid(width, height, Cell::kUnknown);
  grid.meta.resolution = 0.05;
  grid.meta.origin = Pose2D{-1.5, 2.25, 0.0};
  for (int r = 0; r < height; ++r) {
    for (int c = 0; c < width; ++c) {
      // Copy a neighbour most of the time so regions form, as in real maps.
      if (blockiness > 0 && c > 0 && static_cast<int>(rng() % 10) < blockiness) {
        grid.set(c, r, grid.at(c - 1, r));
      } else if (blockiness > 0 && r > 0 && static_cast<int>(rng() % 10) < blockiness) {
        grid.set(c, r, grid.at(c, r - 1));
      } else {
        grid.set(c, r, static_cast<Cell>(rng() % 3));
      }
    }
  }
  return grid;
}

Grid RoundTrip(const Grid& grid, const EncodeOptions& options) {
  auto bytes = EncodeLmap(grid, options);
  EXPECT_TRUE(bytes.ok()) << bytes.status().ToString();
  if (!bytes.ok()) return Grid();
  auto decoded = DecodeLmap(*bytes);
  EXPECT_TRUE(decoded.ok()) << decoded.status().ToString();
  return decoded.ok() ? *decoded : Grid();
}

EncodeOptions WithinOneCell() {
  EncodeOptions options;
  options.tolerance_cells = 1;
  return options;
}

// A 1.0 fixture's bytes (tests/data/lmap; fixtures_test.cc says how they
// were made).
std::vector<std::uint8_t> VersionOneFixture(const std::string& name) {
  const std::string text = testing::ReadFile(testing::SourceDir() + "/tests/data/lmap/" + name);
  return std::vector<std::uint8_t>(text.begin(), text.end());
}

TEST(CodecTest, EdgeCases) {
  std::vector<Grid> grids;
  for (Cell c : {Cell::kFree, Cell::kOccupied, Cell::kUnknown}) {
    grids.emplace_back(1, 1, c);    // a 1x1 map of each kind
    grids.emplace_back(37, 23, c);  // all free (no obstacles), all occupied, all unknown
  }
  grids.emplace_back(0, 0);
  grids.emplace_back(5, 0);
  grids.emplace_back(0, 5);
  Grid no_free(20, 20, Cell::kUnknown);
  for (int i = 0; i < 20; ++i) no_free.set(i, i, Cell::kOccupied);
  grids.push_back(no_free);
  for (const Grid& grid : grids) {
    EXPECT_EQ(RoundTrip(grid, EncodeOptions{}), grid) << grid.width() << "x" << grid.height();
    const Grid within = RoundTrip(grid, WithinOneCell());
    EXPECT_EQ(within.width(), grid.width());
    EXPECT_EQ(within.height(), grid.height());
    EXPECT_EQ(within.meta, grid.meta);
    // Every guarantee of T = 1, by the brute-force references.
    testing::ExpectGuarantees(grid, within, 1,
                              std::to_string(grid.width()) + "x" + std::to_string(grid.height()));
  }
}

TEST(CodecTest, HeaderKeepsMetadataBitForBit) {
  Grid grid(3, 2, Cell::kFree);
  grid.meta.resolution = 0.1 + 1e-17;
  grid.meta.origin = Pose2D{-12.345678901234567, 0.1, 0.7853981633974483};
  grid.meta.occupied_thresh = 0.7;
  grid.meta.free_thresh = 0.25;
  grid.meta.negate = true;
  grid.meta.mode = MapMode::kScale;
  for (const EncodeOptions& options : {EncodeOptions{}, WithinOneCell()}) {
    EXPECT_EQ(RoundTrip(grid, options).meta, grid.meta);
  }
}

// A 4 x 4 map at 0.05 m/cell whose cells hold (x, y) metres.
Grid SmallMapAround(double x, double y) {
  Grid grid(4, 4, Cell::kFree);
  grid.meta.origin = {x - 0.1, y - 0.1, 0.0};
  return grid;
}

TEST(CodecTest, MetadataChunkIsReadBack) {
  EncodeOptions options;
  options.creator = "unit test";
  options.time = "2026-11-22T04:00:00Z";
  options.frame_id = "map";
  options.robot_pose = Pose2D{1.5, -2.0, 0.25};
  auto bytes = EncodeLmap(SmallMapAround(1.5, -2.0), options);
  ASSERT_TRUE(bytes.ok()) << bytes.status().ToString();
  auto contents = DecodeLmapContents(*bytes);
  ASSERT_TRUE(contents.ok());
  ASSERT_EQ(contents->metadata.size(), 4u);
  EXPECT_EQ(contents->metadata[0], (std::pair<std::string, std::string>{"creator", "unit test"}));
  EXPECT_EQ(contents->metadata[1].second, "2026-11-22T04:00:00Z");
  // The shortest decimals that read back as the pose's doubles.
  EXPECT_EQ(contents->metadata[3],
            (std::pair<std::string, std::string>{"robot_pose", "1.5 -2 0.25"}));
  options.robot_pose = Pose2D{30.19, 15.34, 0.1};
  auto posed = DecodeLmapContents(*EncodeLmap(SmallMapAround(30.19, 15.34), options));
  ASSERT_TRUE(posed.ok());
  EXPECT_EQ(posed->metadata[3].second, "30.19 15.34 0.1");
}

// The robot's pose is metadata: the layers are the whole map's wherever the
// robot stands (seeded from a pose in a small free space, the walls were
// that space's plus covering pieces elsewhere, 889 against 320 on depot).
TEST(CodecTest, RobotPoseChangesOnlyTheMetadata) {
  auto grid = LoadRosMap(testing::BundledMapsDir() + "/nav2/depot.yaml");
  ASSERT_TRUE(grid.ok());
  // The file of depot saved with a pose (none for nullopt), whole.
  const auto saved = [&grid](std::optional<Pose2D> pose) {
    EncodeOptions options;
    options.robot_pose = pose;
    const StatusOr<std::vector<std::uint8_t>> bytes = EncodeLmap(*grid, options);
    return bytes.ok() ? DecodeLmapContents(*bytes) : StatusOr<LmapContents>(bytes.status());
  };
  const StatusOr<LmapContents> plain = saved(std::nullopt);
  ASSERT_TRUE(plain.ok());
  for (const Pose2D& pose : {Pose2D{30.19, 15.34, 0}, Pose2D{10, 5, 0.5}}) {
    const StatusOr<LmapContents> contents = saved(pose);
    ASSERT_TRUE(contents.ok());
    EXPECT_EQ(contents->walls, plain->walls) << pose.x;
    EXPECT_EQ(contents->rooms, plain->rooms) << pose.x;
    EXPECT_EQ(contents->furniture, plain->furniture) << pose.x;
    ASSERT_EQ(contents->metadata.size(), 1u);
    EXPECT_EQ(contents->metadata[0].first, "robot_pose");
  }
}

// The pose stored is a point of the map, as --pose is: off the map or not
// finite it is refused, by the grid encoder and by the map-file one.
TEST(CodecTest, RobotPoseOffTheMapIsRefused) {
  Grid grid(20, 10, Cell::kFree);
  grid.meta.resolution = 0.1;
  grid.meta.origin = {1.0, 2.0, 0.0};  // the map spans x 1..3 m, y 2..3 m
  const std::string dir = testing::MakeTempDir("codec_pose_off");
  ASSERT_TRUE(SaveRosMap(dir + "/m.yaml", grid).ok());
  for (const Pose2D& pose : {Pose2D{0.99, 2.5, 0}, Pose2D{2.0, 3.0, 0}, Pose2D{NAN, 2.5, 0},
                             Pose2D{2.0, 2.5, INFINITY}}) {
    EncodeOptions options;
    options.robot_pose = pose;
    const auto bytes = EncodeLmap(grid, options);
    ASSERT_FALSE(bytes.ok()) << pose.x << "," << pose.y;
    EXPECT_EQ(bytes.status().code(), StatusCode::kInvalidArgument);
    EXPECT_NE(bytes.status().message().find("robot pose"), std::string::npos);
    const auto saved = SaveRosMapAsLmap(dir + "/m.yaml", dir + "/m.lmap", options);
    ASSERT_FALSE(saved.ok());
    EXPECT_NE(saved.status().message().find("robot pose"), std::string::npos);
    EXPECT_FALSE(testing::FileExists(dir + "/m.lmap"));
  }
  // On the map's lower-left edge it is in cell (0, 0).
  EncodeOptions options;
  options.robot_pose = Pose2D{1.0, 2.0, 0.0};
  EXPECT_TRUE(EncodeLmap(grid, options).ok());
}

// A grid that is itself a map simplified within T cells is saved exact but
// marked as not the robot's map: lossless flag clear, T named; it cannot be
// simplified again.
TEST(CodecTest, SimplifiedGridSavedExactlyNamesItsTolerance) {
  const Grid grid(16, 8, Cell::kFree);
  EncodeOptions options;
  options.simplified_within_cells = 3;
  auto bytes = EncodeLmap(grid, options);
  ASSERT_TRUE(bytes.ok());
  auto contents = DecodeLmapContents(*bytes);
  ASSERT_TRUE(contents.ok());
  EXPECT_EQ(contents->grid.cells(), grid.cells());
  EXPECT_FALSE(contents->lossless);
  EXPECT_EQ(contents->metadata,
            (std::vector<std::pair<std::string, std::string>>{{"tolerance", "3"}}));
  options.tolerance_cells = 1;
  EXPECT_EQ(EncodeLmap(grid, options).status().code(), StatusCode::kInvalidArgument);
  options.tolerance_cells = 0;
  options.simplified_within_cells = -1;
  EXPECT_EQ(EncodeLmap(grid, options).status().code(), StatusCode::kInvalidArgument);
}

TEST(CodecTest, EncodingIsDeterministic) {
  const std::string map = testing::BundledMapsDir() + "/nav2/depot.yaml";
  auto grid = LoadRosMap(map);
  ASSERT_TRUE(grid.ok());
  for (const EncodeOptions& options : {EncodeOptions{}, WithinOneCell()}) {
    auto a = EncodeLmap(*grid, options);
    auto b = EncodeLmap(*grid, options);
    ASSERT_TRUE(a.ok() && b.ok());
    EXPECT_EQ(*a, *b);
  }
}

// The work done on a second thread gives the same bytes as doing all on
// the calling thread. The bundled maps are under 1024 cells a side, one
// tile each by default: 64-cell tiles give the threads tiles to share.
TEST(CodecTest, ThreadsDoNotChangeTheBytes) {
  int maps = 0;
  for (const std::string& path : testing::FindYamlFiles(testing::BundledMapsDir())) {
    auto grid = LoadRosMap(path);
    ASSERT_TRUE(grid.ok()) << path;
    EncodeOptions one, two;
    one.max_threads = 1;
    two.max_threads = 2;
    one.tile_size_cells = two.tile_size_cells = 64;
    auto a = EncodeLmap(*grid, one);
    auto b = EncodeLmap(*grid, two);
    ASSERT_TRUE(a.ok() && b.ok()) << path;
    EXPECT_EQ(*a, *b) << path;
    ++maps;
  }
  EXPECT_GE(maps, 4);
  EncodeOptions none;
  none.max_threads = -1;
  auto bad = EncodeLmap(Grid(4, 4, Cell::kFree), none);
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.status().code(), StatusCode::kInvalidArgument);
  EXPECT_NE(bad.status().message().find("max_threads"), std::string::npos);
}

// The walls' epsilon obeys ExtractLines' own bound (0.5 cells): under it no
// lattice line holds a wall's cells, and `linemap lines` refuses it too.
TEST(CodecTest, EpsilonUnderHalfACellIsRefused) {
  for (const double epsilon : {0.3, 0.0, -1.0}) {
    EncodeOptions options;
    options.epsilon_cells = epsilon;
    const auto bad = EncodeLmap(Grid(4, 4, Cell::kFree), options);
    ASSERT_FALSE(bad.ok()) << epsilon;
    EXPECT_EQ(bad.status().code(), StatusCode::kInvalidArgument);
    EXPECT_NE(bad.status().message().find("at least 0.5 cells"), std::string::npos);
  }
  EncodeOptions half;
  half.epsilon_cells = 0.5;
  EXPECT_TRUE(EncodeLmap(Grid(4, 4, Cell::kFree), half).ok());
}

// A map argument is an .lmap file by its name or by its first bytes: a
// renamed .lmap is still one, an image named .lmap is one too (and then
// refused as a bad file), a PGM is not.
TEST(CodecTest, IsLmapPathByNameOrSignature) {
  const std::string dir = testing::MakeTempDir("is_lmap_path");
  const std::string depot = testing::SourceDir() + "/tests/data/lmap/depot_v2.lmap";
  testing::WriteFile(dir + "/renamed.map", testing::ReadFile(depot));
  testing::WriteFile(dir + "/image.pgm", "P5 2 1 255\n\x00\xfe");
  testing::WriteFile(dir + "/image.lmap", "P5 2 1 255\n\x00\xfe");
  testing::WriteFile(dir + "/short", "LM");
  EXPECT_TRUE(IsLmapPath(depot));
  EXPECT_TRUE(IsLmapPath(dir + "/renamed.map"));
  EXPECT_TRUE(IsLmapPath(dir + "/image.lmap"));
  EXPECT_TRUE(IsLmapPath(dir + "/missing.lmap"));
  EXPECT_FALSE(IsLmapPath(dir + "/image.pgm"));
  EXPECT_FALSE(IsLmapPath(dir + "/short"));
  EXPECT_FALSE(IsLmapPath(dir + "/missing.pgm"));
}

// A 1.0 file of a width x height map holding `chunks` (type, payload)
// after its header.
using ChunkList = std::vector<std::pair<std::string, std::vector<std::uint8_t>>>;
std::vector<std::uint8_t> VersionOneFile(int width, int height, const ChunkList& chunks) {
  HeaderFields header;
  header.width = width;
  header.height = height;
  ContainerWriter writer(1, 0);
  writer.AddChunk("LMHD", WriteHeader(header));
  for (const auto& [type, payload] : chunks) writer.AddChunk(type, payload);
  return writer.Finish();
}

TEST(CodecTest, DecoderRefusesHugeDimensionsBeforeAllocating) {
  auto grid = DecodeLmap(VersionOneFile(100000, 100000, {}));
  ASSERT_FALSE(grid.ok());
  EXPECT_EQ(grid.status().code(), StatusCode::kResourceExhausted);
  EXPECT_NE(grid.status().message().find("LMHD"), std::string::npos);
}

std::vector<std::uint8_t> WithExtraChunk(const std::string& type) {
  return VersionOneFile(4, 3, {{type, {0, 1, 2}}});
}

TEST(CodecTest, UnknownAncillaryChunkIsSkippedUnknownCriticalRefused) {
  auto skipped = DecodeLmap(WithExtraChunk("zzzz"));
  ASSERT_TRUE(skipped.ok()) << skipped.status().ToString();
  EXPECT_EQ(*skipped, Grid(4, 3, Cell::kUnknown));
  auto refused = DecodeLmap(WithExtraChunk("ZZZZ"));
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.status().code(), StatusCode::kUnsupported);
  EXPECT_NE(refused.status().message().find("ZZZZ"), std::string::npos);
}

TEST(CodecTest, EveryBitFlipOfASmallVersionOneFileIsDetectedOrHarmless) {
  auto grid = LoadRosMap(testing::BundledMapsDir() + "/navtut/lse_arena.yaml");
  ASSERT_TRUE(grid.ok());
  const std::vector<std::uint8_t> bytes = VersionOneFixture("lse_arena_lossless.lmap");
  auto whole = DecodeLmap(bytes);
  ASSERT_TRUE(whole.ok()) << whole.status().ToString();
  ASSERT_EQ(*whole, *grid);
  for (std::size_t i = 0; i < bytes.size(); ++i) {
    for (int bit = 0; bit < 8; ++bit) {
      std::vector<std::uint8_t> bad = bytes;
      bad[i] ^= static_cast<std::uint8_t>(1 << bit);
      auto decoded = DecodeLmap(bad);
      if (decoded.ok()) {
        EXPECT_EQ(*decoded, *grid) << "byte " << i << " bit " << bit;
      }
    }
  }
  for (std::size_t n = 0; n < bytes.size(); ++n) {
    EXPECT_FALSE(DecodeLmap(std::vector<std::uint8_t>(bytes.begin(), bytes.begin() + n)).ok());
  }
}

TEST(CodecTest, SaveAndLoad) {
  const std::string dir = testing::MakeTempDir("codec_save");
  const std::string path = dir + "/map.lmap";
  std::mt19937 rng(4);
  const Grid grid = RandomGrid(rng, 30, 20, 7);
  const EncodeOptions options;
  ASSERT_TRUE(SaveLmap(path, grid, options).ok());
  auto loaded = LoadLmap(path);
  ASSERT_TRUE(loaded.ok()) << loaded.status().ToString();
  EXPECT_EQ(*loaded, grid);
  // Saving into a missing folder fails and writes nothing.
  EXPECT_FALSE(SaveLmap(dir + "/missing/map.lmap", grid, options).ok());
  EXPECT_EQ(testing::ListDir(dir), std::vector<std::string>{"map.lmap"});
  auto missing = LoadLmap(dir + "/nothing.lmap");
  ASSERT_FALSE(missing.ok());
  EXPECT_EQ(missing.status().code(), StatusCode::kNotFound);
}

// An output that cannot be written is reported before any work: the
// encoder's progress callback is never called, and nothing is left behind.
TEST(CodecTest, SavesRefuseAnUnwritableOutputBeforeEncoding) {
  const std::string dir = testing::MakeTempDir("codec_save_early");
  std::mt19937 rng(5);
  const Grid grid = RandomGrid(rng, 40, 30, 7);
  const std::string map_path = dir + "/map.yaml";
  ASSERT_TRUE(SaveRosMap(map_path, grid).ok());
  int progress_calls = 0;
  EncodeOptions options;
  options.progress = [&progress_calls](double) { ++progress_calls; };
  const std::string missing = dir + "/missing/map.lmap";
  const Status saved = SaveLmap(missing, grid, options);
  EXPECT_FALSE(saved.ok());
  EXPECT_NE(saved.ToString().find("No such file"), std::string::npos) << saved.ToString();
  const StatusOr<LmapSaveSummary> converted = SaveRosMapAsLmap(map_path, missing, options);
  EXPECT_FALSE(converted.ok());
  // A directory where the file should go.
  EXPECT_FALSE(SaveLmap(dir, grid, options).ok());
  EXPECT_FALSE(SaveRosMapAsLmap(map_path, dir, options).ok());
  EXPECT_EQ(progress_calls, 0);
  // The same options save once the output can be written.
  ASSERT_TRUE(SaveLmap(dir + "/map.lmap", grid, options).ok());
  EXPECT_GT(progress_calls, 0);
  EXPECT_EQ(testing::ListDir(dir).size(), 3u);  // map.yaml, map.pgm, map.lmap
}

TEST(CompareGridsTest, CountsLeaksBetweenLargeRegions) {
  // Two 10x10 free rooms split by an occupied column; the decode opens it.
  Grid original(21, 10, Cell::kFree);
  for (int r = 0; r < 10; ++r) original.set(10, r, Cell::kOccupied);
  Grid decoded = original;
  decoded.set(10, 5, Cell::kFree);
  const GridComparison m = CompareGrids(original, decoded);
  EXPECT_EQ(m.leaks, 1u);
  EXPECT_EQ(m.cells_equal, original.size() - 1);
  EXPECT_DOUBLE_EQ(m.obstacle_recall_1, 1.0);  // (10,5) has occupied neighbours
  EXPECT_DOUBLE_EQ(m.obstacle_precision_1, 1.0);
  EXPECT_DOUBLE_EQ(m.free_iou, 200.0 / 201.0);
  EXPECT_EQ(CompareGrids(original, original).leaks, 0u);
}

TEST(CompareGridsTest, RecallPrecisionAndUnknownTurnedFree) {
  Grid original(10, 1, Cell::kUnknown);
  original.set(0, 0, Cell::kOccupied);
  original.set(5, 0, Cell::kOccupied);
  original.set(9, 0, Cell::kFree);
  Grid decoded(10, 1, Cell::kUnknown);
  decoded.set(1, 0, Cell::kOccupied);  // within one cell of (0,0)
  decoded.set(8, 0, Cell::kOccupied);  // far from any original obstacle
  decoded.set(9, 0, Cell::kFree);
  decoded.set(3, 0, Cell::kFree);  // was unknown
  const GridComparison m = CompareGrids(original, decoded);
  EXPECT_DOUBLE_EQ(m.obstacle_recall_1, 0.5);
  EXPECT_DOUBLE_EQ(m.obstacle_precision_1, 0.5);
  EXPECT_EQ(m.unknown_turned_free, 1u);
  EXPECT_DOUBLE_EQ(m.unknown_turned_free_share, 1.0);
  EXPECT_DOUBLE_EQ(m.free_iou, 0.5);
}

}  // namespace
}  // namespace linemap

namespace linemap {
namespace {

// A SEGS chunk may be Draco-coded (payload coder 2); it must decode to the
// same grid as the varint form.
TEST(CodecTest, DracoCodedSegmentsDecodeLikeVarints) {
  // Canonical (a <= b by row, then column) and in the order of their a.
  const std::vector<LatticeSegment> segments = {
      {{0, 0}, {9, 0}}, {{2, 1}, {2, 7}}, {{8, 3}, {1, 6}}, {{5, 5}, {9, 9}}};
  auto file = [](const std::vector<std::uint8_t>& segs_payload) {
    return VersionOneFile(10, 10, {{"SEGS", segs_payload}});
  };
  std::vector<std::uint8_t> draco = {static_cast<std::uint8_t>(PayloadCoder::kDraco)};
  const std::vector<std::uint8_t> body = EncodeSegmentsDraco(segments);
  ASSERT_FALSE(body.empty());
  draco.insert(draco.end(), body.begin(), body.end());
  auto from_draco = DecodeLmapContents(file(draco));
  ASSERT_TRUE(from_draco.ok()) << from_draco.status().ToString();
  // The varint form (spec/format.md 11.3): row step, column (relative on
  // the same row), rows and signed columns to b.
  ByteWriter varints;
  varints.PutU8(0);  // payload coder: raw
  varints.PutVarint(segments.size());
  for (const auto& [dr, c, h, w] : {std::tuple{0, 0, 0, 9}, std::tuple{1, 2, 6, 0},
                                    std::tuple{2, 8, 3, -7}, std::tuple{2, 5, 4, 4}}) {
    varints.PutVarint(static_cast<std::uint64_t>(dr));
    varints.PutVarint(static_cast<std::uint64_t>(c));
    varints.PutVarint(static_cast<std::uint64_t>(h));
    varints.PutSignedVarint(w);
  }
  auto from_varint = DecodeLmapContents(file(varints.bytes()));
  ASSERT_TRUE(from_varint.ok()) << from_varint.status().ToString();
  EXPECT_EQ(from_varint->segments, segments);
  EXPECT_EQ(from_draco->segments, segments);
  EXPECT_EQ(from_draco->grid, from_varint->grid);
  EXPECT_EQ(from_draco->chunks[1].coder, "draco");
  // Draco is accepted for SEGS only.
  EXPECT_FALSE(DecodeLmap(VersionOneFile(10, 10, {{"OCCP", draco}})).ok());
}

// A chain body of 1.0 ROOM / BLOB (spec/format.md 11.2), written here from
// the spec: one chain from `start`, each step a turn of the direction.
std::vector<std::uint8_t> OneChainPayload(CellIndex start, const std::vector<std::uint8_t>& turns) {
  ByteWriter body;
  body.PutU8(0);  // payload coder: raw
  body.PutVarint(1);
  body.PutVarint(turns.size() + 1);
  body.PutVarint(static_cast<std::uint64_t>(start.col));
  body.PutVarint(static_cast<std::uint64_t>(start.row));
  for (std::uint8_t turn : turns) body.PutU8(turn);
  return body.bytes();
}

// No encoder wrote BLOB: a room filled as free, then a blob in it filled as
// occupied, in the order of the file.
TEST(CodecTest, VersionOneRoomAndBlobChainsAreFilled) {
  // The border of columns 1..5 x rows 1..5: 4 steps east, north, west, and
  // 3 south back next to the start.
  const auto room = OneChainPayload({1, 1}, {0, 0, 0, 0, 2, 0, 0, 0, 2, 0, 0, 0, 2, 0, 0});
  // The 2 x 2 cells from (2, 2): east, north, west.
  const auto blob = OneChainPayload({2, 2}, {0, 2, 2});
  auto contents = DecodeLmapContents(VersionOneFile(8, 7, {{"ROOM", room}, {"BLOB", blob}}));
  ASSERT_TRUE(contents.ok()) << contents.status().ToString();
  Grid expected(8, 7, Cell::kUnknown);
  for (int r = 1; r <= 5; ++r) {
    for (int c = 1; c <= 5; ++c) expected.set(c, r, Cell::kFree);
  }
  for (int r = 2; r <= 3; ++r) {
    for (int c = 2; c <= 3; ++c) expected.set(c, r, Cell::kOccupied);
  }
  EXPECT_EQ(contents->grid, expected);
  ASSERT_EQ(contents->room_chains.size(), 1u);
  EXPECT_EQ(contents->room_chains[0].size(), 16u);
  ASSERT_EQ(contents->blob_outlines.size(), 1u);
  const std::vector<CellIndex> outline = {{2, 2}, {3, 2}, {3, 3}, {2, 3}};
  EXPECT_EQ(contents->blob_outlines[0], outline);
}

}  // namespace
}  // namespace linemap

namespace linemap {
namespace {

// Random damage (bytes overwritten, inserted, removed) to valid files, the
// CRCs then recomputed so the damage reaches the chunk decoders: every case
// must give an error or a grid, never a crash (run under the sanitizers).
TEST(CodecTest, RandomlyDamagedChunksNeverCrash) {
  std::mt19937 rng(21);
  // Between them every chunk type a 1.0 encoder wrote: meta, ROOM, SEGS,
  // OCCP, FREE, RESD.
  std::vector<std::vector<std::uint8_t>> files;
  for (const char* name :
       {"lse_arena_lossless.lmap", "lse_arena_lossy.lmap", "depot_lossy.lmap",
        "depot_v1_residual.lmap", "depot_v1_room_chains.lmap", "depot_lossy_rooms.lmap"}) {
    files.push_back(VersionOneFixture(name));
  }
  int decoded_ok = 0;
  for (int trial = 0; trial < 1200; ++trial) {
    const std::vector<std::uint8_t>& file = files[trial % files.size()];
    auto view = ParseContainer(file, std::uint64_t{1} << 30);
    ASSERT_TRUE(view.ok());
    // Rebuild the file with one chunk's payload damaged and a valid CRC.
    const std::size_t target = rng() % view->chunks.size();
    ContainerWriter writer(1, 0);
    for (std::size_t i = 0; i < view->chunks.size(); ++i) {
      const Chunk& c = view->chunks[i];
      std::vector<std::uint8_t> payload(c.payload, c.payload + c.size);
      if (i == target) {
        const int edits = 1 + static_cast<int>(rng() % 4);
        for (int e = 0; e < edits; ++e) {
          const int kind = static_cast<int>(rng() % 3);
          const std::size_t at = payload.empty() ? 0 : rng() % payload.size();
          if (kind == 0 && !payload.empty()) {
            payload[at] = static_cast<std::uint8_t>(rng());
          } else if (kind == 1) {
            payload.insert(payload.begin() + static_cast<std::ptrdiff_t>(at),
                           static_cast<std::uint8_t>(rng()));
          } else if (!payload.empty()) {
            payload.erase(payload.begin() + static_cast<std::ptrdiff_t>(at));
          }
        }
      }
      writer.AddChunk(c.type, payload);
    }
    auto grid = DecodeLmap(writer.Finish());
    decoded_ok += grid.ok();
  }
  // Most damage is caught; some (e.g. in a model's don't-care bits) decodes.
  EXPECT_LT(decoded_ok, 1200);
}

}  // namespace
}  // namespace linemap
