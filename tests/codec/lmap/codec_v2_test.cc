// Version 2.0 files: exact round trips (random grids, bundled and shared
// maps, with and without the vector layers, any tile size and thread
// count), the layers' invariants checked against the input map, and window
// decoding against the crop of the whole decode.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <optional>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "codec/tolerance/simplify.h"
#include "linemap/codec.h"
#include "linemap/lmap_vectors.h"
#include "linemap/map_io.h"
#include "linemap/segmentation.h"
#include "tests/testing/reference_geometry.h"
#include "tests/testing/reference_tolerance.h"
#include "tests/testing/test_support.h"

namespace linemap {
namespace {

Grid RandomGrid(std::mt19937* rng, int w, int h) {
  Grid grid(w, h, Cell::kUnknown);
  // Blocks of one value with sprinkled noise: runs, edges and specks.
  for (int r = 0; r < h; ++r) {
    for (int c = 0; c < w; ++c) {
      const unsigned block = ((c / 7) * 31 + (r / 5) * 17) % 3;
      grid.set(c, r, static_cast<Cell>((*rng)() % 10 == 0 ? (*rng)() % 3 : block));
    }
  }
  grid.meta.resolution = 0.05;
  grid.meta.origin = {1.5, -2.25, 0.3};
  return grid;
}

StatusOr<Grid> RoundTrip(const Grid& grid, const EncodeOptions& options) {
  LINEMAP_ASSIGN_OR_RETURN(std::vector<std::uint8_t> bytes, EncodeLmap(grid, options));
  return DecodeLmap(bytes);
}

std::vector<std::string> SharedMaps() {
  const std::string dir = testing::SharedMapsDir();
  if (dir.empty()) return {};
  std::vector<std::string> maps = testing::FindYamlFiles(dir);
  for (const std::string& image : testing::FindBareImages(dir)) maps.push_back(image);
  return maps;
}

TEST(CodecV2Test, RandomGridsRoundTripExactly) {
  std::mt19937 rng(21);
  for (int trial = 0; trial < 60; ++trial) {
    const int w = static_cast<int>(rng() % 90), h = static_cast<int>(rng() % 90);
    const Grid grid = RandomGrid(&rng, w, h);
    EncodeOptions options;
    options.vector_layers = trial % 2 == 0;
    options.tile_size_cells = trial % 3 == 0 ? 16 : 1024;
    options.max_threads = 1 + trial % 3;
    auto decoded = RoundTrip(grid, options);
    ASSERT_TRUE(decoded.ok()) << decoded.status().ToString();
    EXPECT_EQ(*decoded, grid) << w << " x " << h;
  }
}

TEST(CodecV2Test, FilesAreVersionTwoAndMarkedExact) {
  auto bytes = EncodeLmap(Grid(5, 5, Cell::kFree));
  ASSERT_TRUE(bytes.ok());
  ASSERT_GE(bytes->size(), 10u);
  EXPECT_EQ((*bytes)[8], 2);
  EXPECT_EQ((*bytes)[9], 0);
  auto contents = DecodeLmapContents(*bytes);
  ASSERT_TRUE(contents.ok());
  EXPECT_TRUE(contents->lossless);
}

TEST(CodecV2Test, BundledMapsRoundTripWithAndWithoutLayers) {
  for (const std::string& path : testing::FindYamlFiles(testing::BundledMapsDir())) {
    auto grid = LoadRosMap(path);
    ASSERT_TRUE(grid.ok()) << path;
    for (bool layers : {true, false}) {
      for (bool compact : {false, true}) {
        EncodeOptions options;
        options.vector_layers = layers;
        options.compact = compact;
        auto decoded = RoundTrip(*grid, options);
        ASSERT_TRUE(decoded.ok()) << path << ": " << decoded.status().ToString();
        EXPECT_EQ(*decoded, *grid)
            << path << (layers ? "" : " raster-only") << (compact ? " compact" : "");
      }
    }
  }
}

// The minor version names the newest feature a file may hold (spec 2):
// 3 where tiles may use model 12 (compact cells, BLKS), 2 for LAYR, 0 for
// cells alone; a tolerance file that falls back to the exact cells keeps
// the exact file's minor version. Checked on freshly encoded files of each
// path, by decoding the header.
TEST(CodecV2Test, MinorVersionNamesTheNewestFeature) {
  auto depot = LoadRosMap(testing::BundledMapsDir() + "/nav2/depot.yaml");
  auto arena = LoadRosMap(testing::BundledMapsDir() + "/navtut/lse_arena.yaml");
  ASSERT_TRUE(depot.ok() && arena.ok());
  struct Case {
    const Grid* grid;
    bool layers, compact;
    int tolerance;
    int minor;
    bool blocks;
  };
  const Case cases[] = {
      {&*depot, true, false, 0, 2, false}, {&*depot, false, false, 0, 0, false},
      {&*depot, true, true, 0, 3, false},  {&*depot, false, true, 0, 3, false},
      {&*depot, true, false, 1, 3, true},  {&*arena, true, false, 4, 2, false},
      {&*arena, true, true, 4, 3, false},
  };
  for (const Case& c : cases) {
    EncodeOptions options;
    options.vector_layers = c.layers;
    options.compact = c.compact;
    options.tolerance_cells = c.tolerance;
    auto bytes = EncodeLmap(*c.grid, options);
    ASSERT_TRUE(bytes.ok()) << bytes.status().ToString();
    auto contents = DecodeLmapContents(*bytes);
    ASSERT_TRUE(contents.ok()) << contents.status().ToString();
    const std::string what = std::string(c.grid == &*depot ? "depot" : "lse_arena") +
                             (c.layers ? "" : " raster-only") + (c.compact ? " compact" : "") +
                             " T=" + std::to_string(c.tolerance);
    EXPECT_EQ(contents->major, 2) << what;
    EXPECT_EQ(contents->minor, c.minor) << what;
    EXPECT_EQ(contents->lossless, !c.blocks) << what;
  }
}

TEST(CodecV2Test, SharedMapsRoundTripExactly) {
  const std::vector<std::string> maps = SharedMaps();
  if (maps.empty()) GTEST_SKIP() << "../shared/maps is absent";
  int tested = 0;
  for (const std::string& path : maps) {
    auto grid = LoadRosMap(path);
    if (!grid.ok()) continue;  // e.g. a YAML naming a missing image
    for (bool compact : {false, true}) {
      EncodeOptions options;
      options.compact = compact;
      auto decoded = RoundTrip(*grid, options);
      ASSERT_TRUE(decoded.ok()) << path << ": " << decoded.status().ToString();
      EXPECT_EQ(*decoded, *grid) << path << (compact ? " compact" : "");
    }
    ++tested;
  }
  EXPECT_GT(tested, 10);
}

TEST(CodecV2Test, ThreadsAndTilesDoNotChangeTheCells) {
  auto grid = LoadRosMap(testing::BundledMapsDir() + "/nav2/depot.yaml");
  ASSERT_TRUE(grid.ok());
  // 64-cell tiles: 50 tiles for the threads to share (depot is one tile of
  // the default side).
  EncodeOptions one, many;
  one.max_threads = 1;
  many.max_threads = 4;
  one.tile_size_cells = many.tile_size_cells = 64;
  auto a = EncodeLmap(*grid, one);
  auto b = EncodeLmap(*grid, many);
  ASSERT_TRUE(a.ok() && b.ok());
  EXPECT_EQ(*a, *b);
  auto whole = RoundTrip(*grid, EncodeOptions{});
  ASSERT_TRUE(whole.ok());
  EXPECT_EQ(*whole, *grid);
  for (const int threads : {1, 2, 4}) {
    DecodeLimits limits;
    limits.max_threads = threads;
    auto d = DecodeLmap(*a, limits);
    ASSERT_TRUE(d.ok()) << threads;
    EXPECT_EQ(*d, *grid) << threads;
  }
}

TEST(CodecV2Test, LayerBlocksOnManyThreadsGiveTheBytesOfOne) {
  // Maps over 2048 cells a side have their layers extracted block by block,
  // the blocks on as many threads as allowed: 4100 x 700 cells of depot
  // copies is three blocks (the last 4 cells wide), which threads may
  // finish in any order.
  auto depot = LoadRosMap(testing::BundledMapsDir() + "/nav2/depot.yaml");
  ASSERT_TRUE(depot.ok());
  const Grid grid = testing::TiledMap(*depot, 4100, 700);
  EncodeOptions one, three;
  one.max_threads = 1;
  three.max_threads = 3;
  auto a = EncodeLmap(grid, one);
  auto b = EncodeLmap(grid, three);
  ASSERT_TRUE(a.ok() && b.ok());
  EXPECT_EQ(*a, *b);
  auto decoded = DecodeLmap(*b);
  ASSERT_TRUE(decoded.ok());
  EXPECT_EQ(*decoded, grid);
  auto vectors = DecodeLmapVectors(*b);
  ASSERT_TRUE(vectors.ok());
  // Every block has rooms of its own: depot has 8 rooms a copy.
  EXPECT_GT(vectors->rooms.size(), 24u);
}

// The layers against the map they were made from, checked cell by cell.
void ExpectLayerInvariants(const Grid& grid, const LmapVectors& v, const std::string& path) {
  const auto occupied_near = [&](int c, int r) {
    for (int dr = -1; dr <= 1; ++dr) {
      for (int dc = -1; dc <= 1; ++dc) {
        if (grid.Contains(c + dc, r + dr) && grid.at(c + dc, r + dr) == Cell::kOccupied) {
          return true;
        }
      }
    }
    return false;
  };
  // Walls lie on the walls: every cell of every segment (rasterised by the
  // spec's rule, written out here) within one cell of an occupied cell.
  std::size_t off_wall = 0;
  for (const WallPolyline& wall : v.walls) {
    ASSERT_GE(wall.points.size(), 2u) << path;
    for (std::size_t i = 1; i < wall.points.size(); ++i) {
      const CellIndex a = wall.points[i - 1], b = wall.points[i];
      const long dx = b.col - a.col, dy = b.row - a.row;
      const long n = std::max(std::labs(dx), std::labs(dy));
      const auto floor_div = [](long num, long den) {
        return num >= 0 ? num / den : -((-num + den - 1) / den);
      };
      for (long k = 0; k <= n; ++k) {
        const long c = a.col + floor_div(2 * k * dx + n, 2 * n);
        const long r = a.row + floor_div(2 * k * dy + n, 2 * n);
        off_wall += !occupied_near(static_cast<int>(c), static_cast<int>(r));
      }
    }
  }
  EXPECT_EQ(off_wall, 0u) << path;
  const auto closed_and_8_connected = [&](const std::vector<CellIndex>& chain) {
    for (std::size_t i = 0; i < chain.size(); ++i) {
      const CellIndex p = chain[i], q = chain[(i + 1) % chain.size()];
      if (std::abs(p.col - q.col) > 1 || std::abs(p.row - q.row) > 1) return false;
      if (!grid.Contains(p.col, p.row)) return false;
    }
    return !chain.empty();
  };
  for (const RoomOutline& room : v.rooms) {
    EXPECT_TRUE(closed_and_8_connected(room.chain)) << path << " room " << room.id;
  }
  // Furniture outlines hold occupied cells of the input (an object's
  // cells); the outline may run around them, e.g. around a table's legs.
  for (const FurnitureObject& object : v.furniture) {
    EXPECT_TRUE(closed_and_8_connected(object.outline)) << path << " furniture " << object.id;
    // Enclosed by the plain crossing count of spec 8.2, not the library's
    // fill; every enclosed cell lies in the outline's box.
    std::size_t occupied = 0;
    const testing::ReferenceChainInterior outline(object.outline);
    const BoundingBox box = BoxOfCells(object.outline);
    for (int r = box.min_row; r <= box.max_row; ++r) {
      for (int c = box.min_col; c <= box.max_col; ++c) {
        occupied += outline.Encloses(c, r) && grid.at(c, r) == Cell::kOccupied;
      }
    }
    EXPECT_GT(occupied, 0u) << path << " furniture " << object.id;
  }
}

TEST(CodecV2Test, LayersKeepTheirInvariantsOnEveryMap) {
  const std::vector<std::string> bundled = testing::FindYamlFiles(testing::BundledMapsDir());
  const std::vector<std::string> shared = SharedMaps();
  std::vector<std::string> maps = bundled;
  maps.insert(maps.end(), shared.begin(), shared.end());
  std::size_t checked = 0;
  for (const std::string& path : maps) {
    auto grid = LoadRosMap(path);
    // ../shared/maps holds a YAML naming an image it lacks (nav2's
    // empty_room.yaml; its image is read as a bare image); nothing else
    // may fail to load.
    if (!grid.ok() && grid.status().code() == StatusCode::kNotFound && !shared.empty() &&
        path.rfind(testing::SharedMapsDir(), 0) == 0) {
      continue;
    }
    ASSERT_TRUE(grid.ok()) << path << ": " << grid.status().ToString();
    ++checked;
    auto bytes = EncodeLmap(*grid);
    ASSERT_TRUE(bytes.ok()) << path;
    auto vectors = DecodeLmapVectors(*bytes);
    ASSERT_TRUE(vectors.ok()) << path << ": " << vectors.status().ToString();
    EXPECT_EQ(vectors->major, 2);
    EXPECT_EQ(vectors->width, grid->width());
    EXPECT_FALSE(vectors->walls.empty()) << path;
    ExpectLayerInvariants(*grid, *vectors, path);
    // The full decode reads the same layers.
    auto contents = DecodeLmapContents(*bytes);
    ASSERT_TRUE(contents.ok());
    EXPECT_EQ(contents->walls, vectors->walls);
    EXPECT_EQ(contents->rooms, vectors->rooms);
    EXPECT_EQ(contents->furniture, vectors->furniture);
  }
  // Every bundled map, and the shared ones when present (25 maps).
  EXPECT_GE(checked, bundled.size() + (shared.empty() ? 0 : 25));
}

TEST(CodecV2Test, RasterOnlyFilesHaveNoLayers) {
  auto grid = LoadRosMap(testing::BundledMapsDir() + "/nav2/depot.yaml");
  ASSERT_TRUE(grid.ok());
  EncodeOptions options;
  options.vector_layers = false;
  auto bytes = EncodeLmap(*grid, options);
  ASSERT_TRUE(bytes.ok());
  auto v = DecodeLmapVectors(*bytes);
  ASSERT_TRUE(v.ok());
  EXPECT_TRUE(v->walls.empty() && v->rooms.empty() && v->furniture.empty());
}

Grid Crop(const Grid& grid, const CellWindow& w) {
  Grid out(w.col1 - w.col0, w.row1 - w.row0);
  for (int r = w.row0; r < w.row1; ++r) {
    for (int c = w.col0; c < w.col1; ++c) out.set(c - w.col0, r - w.row0, grid.at(c, r));
  }
  return out;
}

// A window inside a width x height map at a random corner, at most
// `max_rows` rows tall.
CellWindow RandomWindow(std::mt19937& rng, int width, int height, int max_rows) {
  CellWindow w;
  w.col0 = static_cast<int>(rng() % width);
  w.row0 = static_cast<int>(rng() % height);
  w.col1 = w.col0 + 1 + static_cast<int>(rng() % (width - w.col0));
  w.row1 = w.row0 + 1 + static_cast<int>(rng() % std::min(max_rows, height - w.row0));
  return w;
}

TEST(CodecV2Test, WindowsEqualTheCropOfTheWholeDecode) {
  std::mt19937 rng(5);
  for (const std::string& path : testing::FindYamlFiles(testing::BundledMapsDir())) {
    auto grid = LoadRosMap(path);
    ASSERT_TRUE(grid.ok());
    EncodeOptions options;
    options.tile_size_cells = 64;  // several tiles even on small maps
    // Layer sections not aligned with the tiles: a window draws its tiles'
    // hints from the sections whose box reaches them.
    options.layer_section_cells = 48;
    auto bytes = EncodeLmap(*grid, options);
    ASSERT_TRUE(bytes.ok());
    for (int trial = 0; trial < 25; ++trial) {
      CellWindow w = RandomWindow(rng, grid->width(), grid->height(), grid->height());
      if (trial == 0) w = {0, 0, grid->width(), grid->height()};
      if (trial == 1) w = {grid->width() - 1, grid->height() - 1, grid->width(), grid->height()};
      auto region = DecodeLmapRegion(*bytes, w);
      ASSERT_TRUE(region.ok()) << region.status().ToString();
      EXPECT_EQ(region->cells(), Crop(*grid, w).cells()) << path;
      // The window's origin is its lower-left corner in the map frame.
      double x = 0, y = 0;
      grid->CellToWorld(w.col0 - 0.5, w.row0 - 0.5, &x, &y);
      EXPECT_NEAR(region->meta.origin.x, x, 1e-9);
      EXPECT_NEAR(region->meta.origin.y, y, 1e-9);
      EXPECT_EQ(region->meta.origin.yaw, grid->meta.origin.yaw);
      EXPECT_EQ(region->meta.resolution, grid->meta.resolution);
    }
    for (CellWindow bad : {CellWindow{0, 0, 0, 1}, CellWindow{-1, 0, 2, 2},
                           CellWindow{0, 0, grid->width() + 1, 1}}) {
      auto region = DecodeLmapRegion(*bytes, bad);
      ASSERT_FALSE(region.ok());
      EXPECT_EQ(region.status().code(), StatusCode::kInvalidArgument);
    }
  }
}

// A file saved within a tolerance keeps its cells in BLKS tiles, whose
// windows also stop inside a tile after the window's last row.
TEST(CodecV2Test, WindowsOfToleranceFilesEqualTheCropOfTheirWholeDecode) {
  std::mt19937 rng(8);
  auto grid = LoadRosMap(testing::BundledMapsDir() + "/nav2/depot.yaml");
  ASSERT_TRUE(grid.ok());
  EncodeOptions options;
  options.tolerance_cells = 3;  // where blocks beat the exact cells on depot
  options.tile_size_cells = 64;
  auto bytes = EncodeLmap(*grid, options);
  ASSERT_TRUE(bytes.ok());
  auto contents = DecodeLmapContents(*bytes);
  ASSERT_TRUE(contents.ok());
  ASSERT_TRUE(std::any_of(contents->chunks.begin(), contents->chunks.end(),
                          [](const LmapChunkInfo& c) { return c.type == "BLKS"; }));
  auto whole = DecodeLmap(*bytes);
  ASSERT_TRUE(whole.ok());
  for (int trial = 0; trial < 40; ++trial) {
    // Short windows, most of them ending inside a 64-row tile.
    const CellWindow w = RandomWindow(rng, grid->width(), grid->height(), 80);
    auto region = DecodeLmapRegion(*bytes, w);
    ASSERT_TRUE(region.ok()) << region.status().ToString();
    EXPECT_EQ(region->cells(), Crop(*whole, w).cells()) << trial;
  }
}

TEST(CodecV2Test, WindowsOfVersionOneFilesAreCropped) {
  auto grid = LoadRosMap(testing::BundledMapsDir() + "/navtut/lse_arena.yaml");
  ASSERT_TRUE(grid.ok());
  auto full = LoadLmap(testing::SourceDir() + "/tests/data/lmap/lse_arena_lossless.lmap");
  ASSERT_TRUE(full.ok());
  const CellWindow w{10, 5, 50, 40};
  auto region =
      LoadLmapRegion(testing::SourceDir() + "/tests/data/lmap/lse_arena_lossless.lmap", w);
  ASSERT_TRUE(region.ok());
  EXPECT_EQ(region->cells(), Crop(*grid, w).cells());
}

// Within a tolerance the file decodes to the simplified map (whose
// guarantees tests/codec/tolerance/simplify_test.cc checks by brute force) or, where that is no
// smaller, to the map itself; never larger than the exact file.
// (navtut/lse_arena at T = 4 once came out a byte larger than its exact
// file: its walls within the tolerance cost more than the exact ones.)
TEST(CodecV2Test, ToleranceFilesDecodeToTheSimplifiedMapOrTheExactOne) {
  for (const char* map : {"strands/kth/map.yaml", "navtut/lse_arena.yaml", "nav2/depot.yaml"}) {
    auto grid = LoadRosMap(testing::BundledMapsDir() + "/" + map);
    ASSERT_TRUE(grid.ok()) << map;
    auto exact = EncodeLmap(*grid);
    ASSERT_TRUE(exact.ok());
    for (int t = 1; t <= 4; ++t) {
      EncodeOptions options;
      options.tolerance_cells = t;
      auto bytes = EncodeLmap(*grid, options);
      ASSERT_TRUE(bytes.ok()) << bytes.status().ToString();
      EXPECT_LE(bytes->size(), exact->size()) << map << " T = " << t;
      auto decoded = DecodeLmap(*bytes);
      ASSERT_TRUE(decoded.ok());
      auto simplified = SimplifyWithinTolerance(*grid, t);
      ASSERT_TRUE(simplified.ok());
      EXPECT_TRUE(*decoded == *simplified || *decoded == *grid) << map << " T = " << t;
      // What the file decodes to keeps every guarantee, by the brute-force
      // references (not by the encoder's own checks).
      testing::ExpectGuarantees(*grid, *decoded, t, map);
      // The header says whether the file is exact, and a file that is not
      // names its tolerance in its metadata.
      auto contents = DecodeLmapContents(*bytes);
      ASSERT_TRUE(contents.ok());
      EXPECT_EQ(contents->lossless, *decoded == *grid) << map << " T = " << t;
      const std::pair<std::string, std::string> named{"tolerance", std::to_string(t)};
      const auto& metadata = contents->metadata;
      if (contents->lossless) {
        EXPECT_TRUE(metadata.empty()) << map << " T = " << t;
        EXPECT_EQ(ToleranceCellsOf(2, true, metadata), std::nullopt);
      } else {
        EXPECT_EQ(metadata, (std::vector{named})) << map << " T = " << t;
        EXPECT_EQ(ToleranceCellsOf(2, false, metadata), t);
      }
    }
  }
}

// A map of 2 x 2 blocks of one value each is drawn exactly by the blocks of
// T = 1: the file decodes to the map, so it says it is exact and names no T
// (whether its cells are BLKS or CELL).
TEST(CodecV2Test, BlocksThatDrawTheMapExactlyMakeAnExactFile) {
  std::mt19937 rng(7);
  Grid grid(256, 256, Cell::kFree);
  for (int r = 0; r < 256; r += 2) {
    for (int c = 0; c < 256; c += 2) {
      const Cell value = static_cast<Cell>(rng() % 3);
      for (int dr = 0; dr < 2; ++dr) {
        for (int dc = 0; dc < 2; ++dc) grid.set(c + dc, r + dr, value);
      }
    }
  }
  grid.meta.resolution = 0.05;
  EncodeOptions options;
  options.tolerance_cells = 1;
  auto bytes = EncodeLmap(grid, options);
  ASSERT_TRUE(bytes.ok()) << bytes.status().ToString();
  auto contents = DecodeLmapContents(*bytes);
  ASSERT_TRUE(contents.ok());
  EXPECT_EQ(contents->grid.cells(), grid.cells());
  EXPECT_TRUE(contents->lossless);
  EXPECT_TRUE(contents->metadata.empty());
}

// The caller's metadata comes first, then the tolerance; an exact save
// names none, whatever the caller gives.
TEST(CodecV2Test, ToleranceIsNamedBesideTheCallersMetadata) {
  auto grid = LoadRosMap(testing::BundledMapsDir() + "/nav2/depot.yaml");
  ASSERT_TRUE(grid.ok());
  EncodeOptions options;
  options.creator = "robot 7";
  options.frame_id = "map";
  using Entries = std::vector<std::pair<std::string, std::string>>;
  for (int t : {0, 2}) {
    options.tolerance_cells = t;
    auto bytes = EncodeLmap(*grid, options);
    ASSERT_TRUE(bytes.ok()) << bytes.status().ToString();
    auto contents = DecodeLmapContents(*bytes);
    ASSERT_TRUE(contents.ok());
    ASSERT_EQ(contents->lossless, t == 0) << "depot is simplified at T = 2";
    Entries want{{"creator", "robot 7"}, {"frame_id", "map"}};
    if (t > 0) want.emplace_back("tolerance", "2");
    EXPECT_EQ(contents->metadata, want) << "T = " << t;
  }
}

TEST(CodecV2Test, ToleranceOutsideZeroToFourIsRefused) {
  EncodeOptions options;
  options.tolerance_cells = 5;
  auto bytes = EncodeLmap(Grid(4, 4, Cell::kFree), options);
  ASSERT_FALSE(bytes.ok());
  EXPECT_EQ(bytes.status().code(), StatusCode::kInvalidArgument);
  options.tolerance_cells = -1;
  EXPECT_FALSE(EncodeLmap(Grid(4, 4, Cell::kFree), options).ok());
  options.tolerance_cells = 0;
  options.tile_size_cells = 8;
  EXPECT_FALSE(EncodeLmap(Grid(4, 4, Cell::kFree), options).ok());
}

// Saving within a tolerance holds the whole grid and its distance maps, so
// maps over EncodeOptions::max_tolerance_cells (2^26 unless set; 0: no
// limit) are refused before any work, with the map's size and the option
// named; exact saves are not limited by it.
TEST(CodecV2Test, ToleranceRefusesMapsOverItsCellLimit) {
  EXPECT_EQ(EncodeOptions{}.max_tolerance_cells, 67108864u);
  Grid grid(20, 20, Cell::kFree);
  for (int c = 0; c < 20; ++c) grid.set(c, 10, Cell::kOccupied);
  EncodeOptions options;
  options.tolerance_cells = 1;
  options.max_tolerance_cells = 399;
  const auto refused = EncodeLmap(grid, options);
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.status().code(), StatusCode::kResourceExhausted);
  EXPECT_NE(refused.status().message().find("400 cells"), std::string::npos)
      << refused.status().message();
  EXPECT_NE(refused.status().message().find("max_tolerance_cells"), std::string::npos);
  for (const std::uint64_t limit : {std::uint64_t{400}, std::uint64_t{0}}) {
    options.max_tolerance_cells = limit;
    EXPECT_TRUE(EncodeLmap(grid, options).ok()) << limit;
  }
  options.tolerance_cells = 0;
  options.max_tolerance_cells = 1;
  EXPECT_TRUE(EncodeLmap(grid, options).ok());
}

}  // namespace
}  // namespace linemap
