// Round trips, edge cases, determinism, limits and corruption handling of
// the .lmap encoder and decoder.
#include "linemap/codec.h"

#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "codec/codec/chunk_coding.h"
#include "codec/codec/draco_segments.h"
#include "format/byte_io.h"
#include "format/container.h"
#include "format/deflate.h"
#include "linemap/labeling.h"
#include "linemap/map_io.h"
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

// The 1.0 encoder, lossy (EncodeOptions::format_v1): what most tests here
// check. Version 2.0 files are tested in codec_v2_test.cc.
EncodeOptions LossyV1() {
  EncodeOptions options;
  options.format_v1 = true;
  return options;
}

EncodeOptions Lossless(LosslessMethod method) {
  EncodeOptions options = LossyV1();
  options.lossless = true;
  options.lossless_method = method;
  return options;
}

TEST(CodecTest, LosslessRoundTripOnRandomGrids) {
  std::mt19937 rng(1);
  for (int trial = 0; trial < 60; ++trial) {
    const int w = 1 + static_cast<int>(rng() % 70);
    const int h = 1 + static_cast<int>(rng() % 50);
    const Grid grid = RandomGrid(rng, w, h, static_cast<int>(trial % 10));
    for (LosslessMethod method : {LosslessMethod::kExactLayers, LosslessMethod::kResidual}) {
      const Grid decoded = RoundTrip(grid, Lossless(method));
      ASSERT_EQ(decoded, grid) << "trial " << trial << " " << w << "x" << h;
    }
  }
}

TEST(CodecTest, ResidualAloneRebuildsAnyGrid) {
  // Lossy layers off: RESD codes the whole grid against an all-unknown base.
  std::mt19937 rng(2);
  EncodeOptions options = Lossless(LosslessMethod::kResidual);
  options.store_segments = false;
  for (int trial = 0; trial < 20; ++trial) {
    const Grid grid =
        RandomGrid(rng, 1 + static_cast<int>(rng() % 40), 1 + static_cast<int>(rng() % 40), 5);
    ASSERT_EQ(RoundTrip(grid, options), grid) << "trial " << trial;
  }
}

TEST(CodecTest, EdgeCases) {
  std::vector<Grid> grids;
  for (Cell c : {Cell::kFree, Cell::kOccupied, Cell::kUnknown}) {
    grids.emplace_back(1, 1, c);    // a 1x1 map of each kind
    grids.emplace_back(37, 23, c);  // all free (no obstacles), all occupied, all unknown
  }
  grids.emplace_back(0, 0);
  grids.emplace_back(5, 0);
  Grid no_free(20, 20, Cell::kUnknown);
  for (int i = 0; i < 20; ++i) no_free.set(i, i, Cell::kOccupied);
  grids.push_back(no_free);
  for (const Grid& grid : grids) {
    EXPECT_EQ(RoundTrip(grid, Lossless(LosslessMethod::kExactLayers)), grid)
        << grid.width() << "x" << grid.height();
    const Grid lossy = RoundTrip(grid, LossyV1());
    EXPECT_EQ(lossy.width(), grid.width());
    EXPECT_EQ(lossy.height(), grid.height());
    EXPECT_EQ(lossy.meta, grid.meta);
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
  const Grid decoded = RoundTrip(grid, LossyV1());
  EXPECT_EQ(decoded.meta, grid.meta);
}

TEST(CodecTest, MetadataChunkIsReadBack) {
  EncodeOptions options = LossyV1();
  options.creator = "unit test";
  options.time = "2026-11-22T04:00:00Z";
  options.frame_id = "map";
  options.robot_pose = Pose2D{1.5, -2.0, 0.25};
  auto bytes = EncodeLmap(Grid(4, 4, Cell::kFree), options);
  ASSERT_TRUE(bytes.ok());
  auto contents = DecodeLmapContents(*bytes);
  ASSERT_TRUE(contents.ok());
  ASSERT_EQ(contents->metadata.size(), 4u);
  EXPECT_EQ(contents->metadata[0], (std::pair<std::string, std::string>{"creator", "unit test"}));
  EXPECT_EQ(contents->metadata[1].second, "2026-11-22T04:00:00Z");
  EXPECT_EQ(contents->metadata[3].first, "robot_pose");
}

TEST(CodecTest, EncodingIsDeterministic) {
  const std::string map = testing::BundledMapsDir() + "/nav2/depot.yaml";
  auto grid = LoadRosMap(map);
  ASSERT_TRUE(grid.ok());
  for (bool lossless : {false, true}) {
    EncodeOptions options = LossyV1();
    options.lossless = lossless;
    auto a = EncodeLmap(*grid, options);
    auto b = EncodeLmap(*grid, options);
    ASSERT_TRUE(a.ok() && b.ok());
    EXPECT_EQ(*a, *b);
  }
}

// The candidates coded on a second thread give the same bytes as coding all
// on the calling thread.
TEST(CodecTest, ThreadsDoNotChangeTheBytes) {
  for (const std::string& path : testing::FindYamlFiles(testing::BundledMapsDir())) {
    auto grid = LoadRosMap(path);
    ASSERT_TRUE(grid.ok()) << path;
    for (bool v1 : {false, true}) {
      EncodeOptions one, two;
      one.format_v1 = two.format_v1 = v1;
      one.max_threads = 1;
      two.max_threads = 2;
      auto a = EncodeLmap(*grid, one);
      auto b = EncodeLmap(*grid, two);
      ASSERT_TRUE(a.ok() && b.ok()) << path;
      EXPECT_EQ(*a, *b) << path;
    }
  }
  EncodeOptions none;
  none.max_threads = -1;
  auto bad = EncodeLmap(Grid(4, 4, Cell::kFree), none);
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.status().code(), StatusCode::kInvalidArgument);
  EXPECT_NE(bad.status().message().find("max_threads"), std::string::npos);
}

// The lossy goals, on the bundled maps.
TEST(CodecTest, LossyGoalsOnBundledMaps) {
  const std::vector<std::string> maps = testing::FindYamlFiles(testing::BundledMapsDir());
  ASSERT_FALSE(maps.empty());
  for (const std::string& path : maps) {
    auto grid = LoadRosMap(path);
    ASSERT_TRUE(grid.ok()) << path;
    const Grid decoded = RoundTrip(*grid, LossyV1());
    const GridComparison m = CompareGrids(*grid, decoded);
    EXPECT_TRUE(m.same_geometry) << path;
    EXPECT_EQ(m.leaks, 0u) << path;
    EXPECT_GE(m.obstacle_recall_1, 0.98) << path;
    EXPECT_GE(m.obstacle_precision_1, 0.98) << path;
    EXPECT_GE(m.free_iou, 0.95) << path;
    EXPECT_LE(m.unknown_turned_free_share, 0.02) << path;
  }
}

// Without segments the exact layers compete with the lossy candidates, so a
// lossy file is never larger than the lossless one; with segments it may be
// up to 10 % larger than without (the walls as lines are worth that much).
TEST(CodecTest, LossyIsNoLargerThanLosslessBeyondTheSegmentAllowanceOnBundledMaps) {
  const std::vector<std::string> maps = testing::FindYamlFiles(testing::BundledMapsDir());
  ASSERT_FALSE(maps.empty());
  EncodeOptions plain_lossy = LossyV1();
  plain_lossy.store_segments = false;
  EncodeOptions plain_lossless = plain_lossy;
  plain_lossless.lossless = true;
  for (const std::string& path : maps) {
    auto grid = LoadRosMap(path);
    ASSERT_TRUE(grid.ok()) << path;
    auto lossy_bytes = EncodeLmap(*grid, plain_lossy);
    auto lossless_bytes = EncodeLmap(*grid, plain_lossless);
    auto default_bytes = EncodeLmap(*grid, LossyV1());
    ASSERT_TRUE(lossy_bytes.ok() && lossless_bytes.ok() && default_bytes.ok()) << path;
    EXPECT_LE(lossy_bytes->size(), lossless_bytes->size()) << path;
    EXPECT_LE(static_cast<double>(default_bytes->size()),
              1.10 * static_cast<double>(lossy_bytes->size()))
        << path;
  }
}

// By default the lossy decode keeps the free space a planner sees: no cell
// turns free, and every free cell of a free region of 24+ cells (the largest
// speck the boldest tuning drops) stays free. Checked independently of the
// encoder, with the paper's labelling.
void ExpectFreeSpaceKept(const std::string& path) {
  auto grid = LoadRosMap(path);
  ASSERT_TRUE(grid.ok()) << path;
  auto bytes = EncodeLmap(*grid, LossyV1());
  ASSERT_TRUE(bytes.ok()) << path;
  auto decoded = DecodeLmap(*bytes);
  ASSERT_TRUE(decoded.ok()) << path;
  BinaryMask free(grid->width(), grid->height());
  for (std::size_t i = 0; i < free.bits.size(); ++i) {
    free.bits[i] = grid->cells()[i] == Cell::kFree;
  }
  const Labeling regions = LabelComponents(free, Connectivity::kFour);
  std::size_t turned_free = 0, lost = 0;
  for (std::size_t i = 0; i < free.bits.size(); ++i) {
    const bool was_free = free.bits[i] != 0;
    const bool is_free = decoded->cells()[i] == Cell::kFree;
    turned_free += is_free && !was_free;
    lost += was_free && !is_free && regions.components[regions.labels[i] - 1].cell_count >= 24;
  }
  EXPECT_EQ(turned_free, 0u) << path;
  EXPECT_EQ(lost, 0u) << path;
}

TEST(CodecTest, LossyKeepsFreeSpaceOnBundledMaps) {
  const std::vector<std::string> maps = testing::FindYamlFiles(testing::BundledMapsDir());
  ASSERT_FALSE(maps.empty());
  for (const std::string& path : maps) ExpectFreeSpaceKept(path);
}

TEST(CodecTest, SimplifyFreeSpaceChangesFreeCellsOnARaggedMap) {
  // The option is what trades the free space for size: on a scanned map it
  // must actually move the free boundary.
  auto grid = LoadRosMap(testing::BundledMapsDir() + "/strands/kth/map.yaml");
  ASSERT_TRUE(grid.ok());
  EncodeOptions simplify = LossyV1();
  simplify.simplify_free_space = true;
  auto plain = EncodeLmap(*grid, LossyV1());
  auto simplified = EncodeLmap(*grid, simplify);
  ASSERT_TRUE(plain.ok() && simplified.ok());
  EXPECT_LT(simplified->size(), plain->size());
  auto decoded = DecodeLmap(*simplified);
  ASSERT_TRUE(decoded.ok());
  std::size_t turned_free = 0;
  for (std::size_t i = 0; i < grid->size(); ++i) {
    turned_free += decoded->cells()[i] == Cell::kFree && grid->cells()[i] != Cell::kFree;
  }
  EXPECT_GT(turned_free, 0u);
}

TEST(CodecTest, LosslessRoundTripOnSharedMaps) {
  const std::string dir = testing::SharedMapsDir();
  if (dir.empty()) GTEST_SKIP() << "../shared/maps is absent";
  std::vector<std::string> maps = testing::FindYamlFiles(dir);
  for (const std::string& image : testing::FindBareImages(dir)) maps.push_back(image);
  int tested = 0;
  for (const std::string& path : maps) {
    auto grid = LoadRosMap(path);
    if (!grid.ok()) continue;  // e.g. a YAML naming a missing image
    EncodeOptions options = LossyV1();
    options.lossless = true;
    options.store_segments = false;  // the segments do not change exactness; keep the test fast
    EXPECT_EQ(RoundTrip(*grid, options), *grid) << path;
    ++tested;
  }
  EXPECT_GT(tested, 10);
}

TEST(CodecTest, DecoderRefusesHugeDimensionsBeforeAllocating) {
  ContainerWriter writer(1, 0);
  HeaderFields header;
  header.width = 100000;
  header.height = 100000;
  writer.AddChunk("LMHD", WriteHeader(header));
  auto grid = DecodeLmap(writer.Finish());
  ASSERT_FALSE(grid.ok());
  EXPECT_EQ(grid.status().code(), StatusCode::kResourceExhausted);
  EXPECT_NE(grid.status().message().find("LMHD"), std::string::npos);
}

std::vector<std::uint8_t> WithExtraChunk(const std::string& type) {
  ContainerWriter writer(1, 0);
  HeaderFields header;
  header.width = 4;
  header.height = 3;
  writer.AddChunk("LMHD", WriteHeader(header));
  writer.AddChunk(type, {0, 1, 2});
  return writer.Finish();
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

TEST(CodecTest, EveryBitFlipOfASmallFileIsDetectedOrHarmless) {
  std::mt19937 rng(9);
  Grid grid = RandomGrid(rng, 24, 16, 8);
  EncodeOptions options = LossyV1();
  options.lossless = true;
  options.creator = "x";
  auto bytes = EncodeLmap(grid, options);
  ASSERT_TRUE(bytes.ok());
  for (std::size_t i = 0; i < bytes->size(); ++i) {
    for (int bit = 0; bit < 8; ++bit) {
      std::vector<std::uint8_t> bad = *bytes;
      bad[i] ^= static_cast<std::uint8_t>(1 << bit);
      auto decoded = DecodeLmap(bad);
      if (decoded.ok()) {
        EXPECT_EQ(*decoded, grid) << "byte " << i << " bit " << bit;
      }
    }
  }
  for (std::size_t n = 0; n < bytes->size(); ++n) {
    EXPECT_FALSE(DecodeLmap(std::vector<std::uint8_t>(bytes->begin(), bytes->begin() + n)).ok());
  }
}

TEST(CodecTest, SaveAndLoad) {
  const std::string dir = testing::MakeTempDir("codec_save");
  const std::string path = dir + "/map.lmap";
  std::mt19937 rng(4);
  const Grid grid = RandomGrid(rng, 30, 20, 7);
  EncodeOptions options = LossyV1();
  options.lossless = true;
  ASSERT_TRUE(SaveLmap(path, grid, options).ok());
  auto loaded = LoadLmap(path);
  ASSERT_TRUE(loaded.ok()) << loaded.status().ToString();
  EXPECT_EQ(*loaded, grid);
  // Saving into a missing folder fails and writes nothing.
  EXPECT_FALSE(SaveLmap(dir + "/missing/map.lmap", grid, options).ok());
  auto missing = LoadLmap(dir + "/nothing.lmap");
  ASSERT_FALSE(missing.ok());
  EXPECT_EQ(missing.status().code(), StatusCode::kNotFound);
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
  const std::vector<LatticeSegment> segments = {
      {{0, 0}, {9, 0}}, {{2, 1}, {2, 7}}, {{8, 3}, {1, 6}}, {{5, 5}, {9, 9}}};
  HeaderFields header;
  header.width = 10;
  header.height = 10;
  auto file = [&](const std::vector<std::uint8_t>& segs_payload) {
    ContainerWriter writer(1, 0);
    writer.AddChunk("LMHD", WriteHeader(header));
    writer.AddChunk("SEGS", segs_payload);
    return writer.Finish();
  };
  std::vector<LatticeSegment> canonical = segments;
  CanonicalizeSegments(&canonical);
  std::vector<std::uint8_t> draco = {static_cast<std::uint8_t>(PayloadCoder::kDraco)};
  const std::vector<std::uint8_t> body = EncodeSegmentsDraco(canonical);
  ASSERT_FALSE(body.empty());
  draco.insert(draco.end(), body.begin(), body.end());
  auto from_draco = DecodeLmapContents(file(draco));
  ASSERT_TRUE(from_draco.ok()) << from_draco.status().ToString();
  auto from_varint = DecodeLmapContents(file(WrapPayload(WriteSegments(canonical), false)));
  ASSERT_TRUE(from_varint.ok());
  EXPECT_EQ(from_draco->segments, canonical);
  EXPECT_EQ(from_draco->grid, from_varint->grid);
  EXPECT_EQ(from_draco->chunks[1].coder, "draco");
  // Draco is accepted for SEGS only.
  ContainerWriter writer(1, 0);
  writer.AddChunk("LMHD", WriteHeader(header));
  writer.AddChunk("OCCP", draco);
  EXPECT_FALSE(DecodeLmap(writer.Finish()).ok());
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
  HeaderFields header;
  header.width = 8;
  header.height = 7;
  ContainerWriter writer(1, 0);
  writer.AddChunk("LMHD", WriteHeader(header));
  // The border of columns 1..5 x rows 1..5: 4 steps east, north, west, and
  // 3 south back next to the start.
  writer.AddChunk("ROOM", OneChainPayload({1, 1}, {0, 0, 0, 0, 2, 0, 0, 0, 2, 0, 0, 0, 2, 0, 0}));
  // The 2 x 2 cells from (2, 2): east, north, west.
  writer.AddChunk("BLOB", OneChainPayload({2, 2}, {0, 2, 2}));
  auto contents = DecodeLmapContents(writer.Finish());
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
  const std::vector<CellIndex> blob = {{2, 2}, {3, 2}, {3, 3}, {2, 3}};
  EXPECT_EQ(contents->blob_outlines[0], blob);
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
  std::vector<std::vector<std::uint8_t>> files;
  for (int k = 0; k < 3; ++k) {
    const Grid grid = RandomGrid(rng, 12 + k * 9, 10 + k * 5, 8);
    EncodeOptions options = LossyV1();
    options.lossless = k != 1;
    options.lossless_method = k == 2 ? LosslessMethod::kResidual : LosslessMethod::kExactLayers;
    options.creator = "t";
    auto bytes = EncodeLmap(grid, options);
    ASSERT_TRUE(bytes.ok());
    files.push_back(*bytes);
  }
  const std::string depot = testing::SourceDir() + "/tests/data/lmap/depot_lossy.lmap";
  files.push_back([&] {
    const std::string text = testing::ReadFile(depot);
    return std::vector<std::uint8_t>(text.begin(), text.end());
  }());
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
