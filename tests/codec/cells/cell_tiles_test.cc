// The CELL chunk's tiles: which model the encoder writes in each, that
// threads do not change the bytes, and that files whose tiles use the
// models before the layer context still decode.
#include "codec/cells/cell_tiles.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "codec/layers/layer_extraction.h"
#include "codec/lmap/chunk_coding.h"
#include "format/byte_io.h"
#include "format/container.h"
#include "linemap/codec.h"
#include "linemap/lmap_vectors.h"
#include "linemap/map_io.h"
#include "linemap/tolerance.h"
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

// The model of each tile by the encoder's rule, from the tile coder alone:
// model 0 for a tile without any hint; else the smallest whole coding of
// models 4, 7 and 0 (4, then 7, then 0 on a tie), and in a tile of more than
// 256 rows only among those whose coding of the first 128 rows is within
// 2 % or 8 bytes (whichever is more) of the smallest there. Counts in
// *unlike_whole the tiles whose model differs from the smallest whole coding
// of the three.
std::vector<unsigned> ModelsByFirstRows(const Grid& g, const LayerIndex& index,
                                        const TileLayout& layout, int* unlike_whole) {
  std::vector<unsigned> models;
  for (std::uint64_t i = 0; i < layout.count(); ++i) {
    const CellRect t = layout.Tile(i);
    const int tw = t.x1 - t.x0, th = t.y1 - t.y0;
    const std::vector<Cell> cells = TileCells(g, t);
    const std::vector<std::uint8_t> hints = index.TileHints(t);
    if (std::all_of(hints.begin(), hints.end(), [](std::uint8_t h) { return h == 0; })) {
      models.push_back(0);  // a tile without any hint: model 0 alone
      continue;
    }
    const auto size = [&](unsigned model, int rows) {
      return EncodeTileCells(cells.data(), hints.data(), tw, th, CellRect{0, 0, tw, rows},
                             static_cast<TileModel>(model))
          .size();
    };
    const std::vector<unsigned> all = {4, 7, 0};
    std::vector<unsigned> tried = all;
    if (th > 256) {
      std::size_t least = size(4, 128);
      for (unsigned m : all) least = std::min(least, size(m, 128));
      std::erase_if(tried, [&](unsigned m) {
        return static_cast<double>(size(m, 128)) >
               std::max(1.02 * static_cast<double>(least), static_cast<double>(least) + 8);
      });
    }
    const auto smallest_whole = [&](const std::vector<unsigned>& candidates) {
      unsigned best = candidates[0];
      for (unsigned m : candidates) {
        if (size(m, th) < size(best, th)) best = m;
      }
      return best;
    };
    models.push_back(smallest_whole(tried));
    *unlike_whole += models.back() != smallest_whole(all) ? 1 : 0;
  }
  return models;
}

// Each tile holds the smallest of the layer context, the layer context
// with the wall term alone and the template (the template alone without
// hints); threads change no byte; the chunk
// decodes to the map on any number of threads.
TEST(CellTilesTest, EachTileTakesTheSmallerModelWhateverTheThreads) {
  const Grid g = Depot();
  StatusOr<VectorLayers> extracted = ExtractVectorLayers(g, EncodeOptions{});
  ASSERT_TRUE(extracted.ok()) << extracted.status().ToString();
  const VectorLayers none;
  const VectorLayers& with_layers = *extracted;
  for (const VectorLayers* layers : {&none, &with_layers}) {
    const LayerIndex index(layers->walls, layers->rooms, layers->furniture);
    for (int tile_size : {16, 97, 256}) {
      SCOPED_TRACE("tile size " + std::to_string(tile_size) +
                   (layers == &none ? " without layers" : " with layers"));
      const std::vector<std::uint8_t> one = EncodeCellChunk(g, index, tile_size, 1);
      EXPECT_EQ(one, EncodeCellChunk(g, index, tile_size, 3));
      const TileLayout layout(g.width(), g.height(), tile_size);
      int unlike_whole = 0;
      const std::vector<unsigned> expected = ModelsByFirstRows(g, index, layout, &unlike_whole);
      EXPECT_EQ(TileModels(one, layout), expected);
      if (layers == &none) {
        EXPECT_EQ(static_cast<std::size_t>(std::count(expected.begin(), expected.end(), 0u)),
                  expected.size());
      } else {
        EXPECT_LT(static_cast<std::size_t>(std::count(expected.begin(), expected.end(), 0u)),
                  expected.size());
      }
      std::vector<Cell> out(g.size(), Cell::kFree);
      for (int threads : {1, 2}) {
        const Status s =
            DecodeCellChunk(one, index, g.width(), g.height(),
                            CellRect{0, 0, g.width(), g.height()}, threads, out.data());
        ASSERT_TRUE(s.ok()) << s.ToString();
        EXPECT_EQ(out, g.cells()) << threads << " threads";
      }
    }
  }
}

// A tile of more than 256 rows picks its model on its first 128 rows:
// every model whose coding of them is within 2 % or 8 bytes (whichever is
// more) of the smallest there is coded whole, and the smallest of those is
// kept (4, then 7, then 0 on a tie), so a model that only wins further down
// is never tried. The reference (ModelsByFirstRows) follows that rule with
// the tile coder alone, on depot's tall tiles (one 604 x 307 tile; tiles of
// 300 rows and one of 7) and on depot transposed (604 rows), where it picks
// what coding every model whole would; and on a tile made for the rule to
// bite: 128 rows of noise, which the four-cell contexts of models 4 and 7
// code smaller than model 0's 8-cell template, then 472 rows that repeat
// every other row, which only model 0 sees (its template holds the cell two
// rows below), so that coding every model whole would have taken model 0.
TEST(CellTilesTest, TallTilesPickTheirModelOnTheirFirstRows) {
  const Grid depot = Depot();
  Grid transposed(depot.height(), depot.width());
  transposed.meta = depot.meta;
  for (int r = 0; r < depot.height(); ++r) {
    for (int c = 0; c < depot.width(); ++c) transposed.set(r, c, depot.at(c, r));
  }
  for (const Grid* g : {static_cast<const Grid*>(&depot), static_cast<const Grid*>(&transposed)}) {
    StatusOr<VectorLayers> layers = ExtractVectorLayers(*g, EncodeOptions{});
    ASSERT_TRUE(layers.ok()) << layers.status().ToString();
    const LayerIndex index(layers->walls, layers->rooms, layers->furniture);
    for (int tile_size : {300, 1024}) {
      SCOPED_TRACE((g == &depot ? "depot, tile size " : "depot transposed, tile size ") +
                   std::to_string(tile_size));
      const TileLayout layout(g->width(), g->height(), tile_size);
      int unlike_whole = 0;
      const std::vector<std::uint8_t> one = EncodeCellChunk(*g, index, tile_size, 1);
      EXPECT_EQ(one, EncodeCellChunk(*g, index, tile_size, 3));
      EXPECT_EQ(TileModels(one, layout), ModelsByFirstRows(*g, index, layout, &unlike_whole));
      EXPECT_EQ(unlike_whole, 0);
    }
  }

  Grid made(64, 600);
  std::uint32_t state = 12345;
  const auto noise = [&state] {
    state = state * 1664525u + 1013904223u;
    return static_cast<Cell>((state >> 24) % 3);
  };
  std::vector<Cell> pair(2 * 64);
  for (Cell& c : pair) c = noise();
  for (int r = 0; r < 600; ++r) {
    for (int c = 0; c < 64; ++c) made.set(c, r, r < 128 ? noise() : pair[(r % 2) * 64 + c]);
  }
  // One wall along the last row: a tile without any hint takes model 0 alone.
  const std::vector<WallPolyline> walls = {{{{0, 599}, {63, 599}}}};
  const LayerIndex index(walls, {}, {});
  const TileLayout layout(64, 600, 1024);
  int unlike_whole = 0;
  const std::vector<unsigned> expected = ModelsByFirstRows(made, index, layout, &unlike_whole);
  const std::vector<std::uint8_t> one = EncodeCellChunk(made, index, 1024, 1);
  EXPECT_EQ(one, EncodeCellChunk(made, index, 1024, 2));
  EXPECT_EQ(TileModels(one, layout), expected);
  EXPECT_EQ(unlike_whole, 1) << "the made tile does not tell the rule from coding every model";
  EXPECT_NE(expected[0], 0u);
}

// A file's cells chunk: its type (CELL or BLKS), its block side (BLKS) and
// the tile side it declares; empty and 0 when it has neither.
struct CellsChunk {
  std::string type;
  int tile_side = 0;
  int block_side = 0;
  std::vector<std::uint8_t> body;  // the chunk's payload, unwrapped
};

CellsChunk CellsChunkOf(const std::vector<std::uint8_t>& file) {
  StatusOr<ContainerView> view = ParseContainer(file, std::uint64_t{1} << 30);
  EXPECT_TRUE(view.ok()) << view.status().ToString();
  if (!view.ok()) return {};
  for (const Chunk& chunk : view->chunks) {
    const bool blocks = chunk.type == kBlockChunk;
    if (chunk.type != kCellChunk && !blocks) continue;
    PayloadCoder coder;
    StatusOr<std::vector<std::uint8_t>> body =
        UnwrapPayload(chunk.payload, chunk.size, DecodeLimits{}, &coder);
    EXPECT_TRUE(body.ok()) << body.status().ToString();
    if (!body.ok()) return {chunk.type, 0, 0, {}};
    ByteCursor cursor(*body);
    int block_side = 0;
    if (blocks) {
      StatusOr<std::uint8_t> f = cursor.ReadU8("block side");
      EXPECT_TRUE(f.ok());
      block_side = f.ok() ? *f : 0;
    }
    StatusOr<std::uint64_t> side = cursor.ReadVarint("tile side");
    EXPECT_TRUE(side.ok());
    return {chunk.type, side.ok() ? static_cast<int>(*side) : 0, block_side, *body};
  }
  return {};
}

// A corridor `width` cells long between two straight walls, cheap to code
// however wide, with unknown specks along its walls as a laser scan leaves
// them: blocks of T + 1 cells code it smaller than its exact cells, so a
// file saved within a tolerance holds BLKS.
Grid ScannedCorridor(int width) {
  Grid g(width, 40, Cell::kUnknown);
  std::uint32_t state = 12345;
  for (int c = 0; c < width; ++c) {
    g.set(c, 10, Cell::kOccupied);
    for (int r = 11; r < 30; ++r) g.set(c, r, Cell::kFree);
    g.set(c, 30, Cell::kOccupied);
    for (const int r : {11, 29}) {
      state = state * 1664525u + 1013904223u;
      if ((state >> 28) < 5) g.set(c, r, Cell::kUnknown);
    }
  }
  return g;
}

// Tiles of 1024 cells up to 4096 a side and of 512 beyond (windows of huge
// maps read less), exact or within a tolerance; a side the caller asks for
// is kept. Within a tolerance of T the blocks are T + 1 cells a side (spec
// 9), and the tile side the largest multiple of it that does not exceed.
TEST(CellTilesTest, EncoderPicksTheTileSideByTheMapsSide) {
  const struct {
    int width;
    int tolerance;
    int requested;
    int expected;
  } cases[] = {
      {4096, 0, 0, 1024},  {4097, 0, 0, 512},  {4097, 1, 0, 512},   {4096, 1, 0, 1024},
      {4097, 0, 300, 300}, {100, 0, 64, 64},   {4097, 1, 301, 300}, {4096, 2, 0, 1023},
      {4097, 3, 0, 512},   {4096, 4, 0, 1020}, {4097, 4, 0, 510},   {4097, 2, 301, 300},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE("width " + std::to_string(c.width) + " tolerance " + std::to_string(c.tolerance) +
                 " requested " + std::to_string(c.requested));
    const Grid grid = ScannedCorridor(c.width);
    EncodeOptions options;
    options.tolerance_cells = c.tolerance;
    options.tile_size_cells = c.requested;
    options.vector_layers = false;
    StatusOr<std::vector<std::uint8_t>> file = EncodeLmap(grid, options);
    ASSERT_TRUE(file.ok()) << file.status().ToString();
    const CellsChunk chunk = CellsChunkOf(*file);
    EXPECT_EQ(chunk.type, c.tolerance == 0 ? kCellChunk : kBlockChunk);
    EXPECT_EQ(chunk.tile_side, c.expected);
    EXPECT_EQ(chunk.block_side, c.tolerance == 0 ? 0 : c.tolerance + 1);
    StatusOr<Grid> decoded = DecodeLmap(*file);
    ASSERT_TRUE(decoded.ok()) << decoded.status().ToString();
    if (c.tolerance == 0) {
      EXPECT_EQ(*decoded, grid);
    } else {
      EXPECT_TRUE(CheckTolerance(grid, *decoded, c.tolerance).Holds());
    }
  }
}

// The cells of `window` of `grid`, row by row.
std::vector<Cell> CellsIn(const Grid& grid, const CellWindow& w) {
  std::vector<Cell> cells;
  for (int r = w.row0; r < w.row1; ++r) {
    for (int c = w.col0; c < w.col1; ++c) cells.push_back(grid.at(c, r));
  }
  return cells;
}

// A tile whose canvas rows lie a multiple of 2048 cells apart has its hints
// drawn into a buffer of its own, other tiles into the canvas: both decode
// the map, whole and by windows, on one thread and on two (which share the
// buffers). Maps 2048, 4096 and 2047 cells wide, windows 2048 cells wide
// and not, tiles of 256 cells with the layers' walls, rooms and furniture.
TEST(CellTilesTest, TilesDecodeAlikeWhateverTheCanvasStride) {
  for (const int width : {2048, 4096, 2047}) {
    SCOPED_TRACE("width " + std::to_string(width));
    const Grid grid = testing::TiledMap(Depot(), width, 600);
    EncodeOptions options;
    options.tile_size_cells = 256;
    StatusOr<std::vector<std::uint8_t>> file = EncodeLmap(grid, options);
    ASSERT_TRUE(file.ok()) << file.status().ToString();
    StatusOr<LmapVectors> vectors = DecodeLmapVectors(*file);
    ASSERT_TRUE(vectors.ok()) << vectors.status().ToString();
    ASSERT_FALSE(vectors->walls.empty());
    for (const int threads : {1, 2}) {
      SCOPED_TRACE("threads " + std::to_string(threads));
      DecodeLimits limits;
      limits.max_threads = threads;
      StatusOr<Grid> decoded = DecodeLmap(*file, limits);
      ASSERT_TRUE(decoded.ok()) << decoded.status().ToString();
      EXPECT_EQ(decoded->cells(), grid.cells());
      const int row_width = std::min(width, 2048);  // 2047 on the 2047-cell map
      const CellWindow windows[] = {
          {0, 256, row_width, 512},            // whole tiles
          {width - row_width, 0, width, 600},  // whole tiles, every row, at the right edge
          {10, 100, 2000, 590},                // tiles cut by the window
          {0, 0, width, 600},                  // the whole map
      };
      for (const CellWindow& w : windows) {
        SCOPED_TRACE("window " + std::to_string(w.col0) + "," + std::to_string(w.row0) + "," +
                     std::to_string(w.col1) + "," + std::to_string(w.row1));
        StatusOr<Grid> region = DecodeLmapRegion(*file, w, limits);
        ASSERT_TRUE(region.ok()) << region.status().ToString();
        EXPECT_EQ(region->cells(), CellsIn(grid, w));
      }
    }
  }
}

// A window that ends inside a tile 2048 cells wide decodes the tile's rows
// up to the window's last into a scratch copy 2048 cells wide, which
// aliases as a 2048-cell map does: the buffer of hints then holds those
// rows and the one after, which the last row's layer context reads (the
// tiles must be coded with it: lse_arena's are, depot's are not).
TEST(CellTilesTest, WindowsEndingInsideWideTilesDecodeTheirLastRow) {
  StatusOr<Grid> arena = LoadRosMap(testing::BundledMapsDir() + "/navtut/lse_arena.yaml");
  ASSERT_TRUE(arena.ok()) << arena.status().ToString();
  const Grid grid = testing::TiledMap(*arena, 2048, 300);
  EncodeOptions options;
  options.tile_size_cells = 2048;
  StatusOr<std::vector<std::uint8_t>> file = EncodeLmap(grid, options);
  ASSERT_TRUE(file.ok()) << file.status().ToString();
  const TileLayout layout(grid.width(), grid.height(), 2048);
  const CellsChunk chunk = CellsChunkOf(*file);
  ASSERT_EQ(chunk.type, kCellChunk);
  const std::vector<unsigned> models = TileModels(chunk.body, layout);
  ASSERT_EQ(models.size(), 1u);
  // Models 4 and 7 read the wall hints of the row above (the layer class's
  // wall term); the encoder writes those two or 0.
  ASSERT_TRUE(models[0] == 4 || models[0] == 7)
      << "the tile is coded with model " << models[0] << ", not the layer context";
  for (const int row1 : {1, 2, 37, 150, 299}) {
    SCOPED_TRACE("rows 0.." + std::to_string(row1));
    const CellWindow w{0, 0, 2048, row1};
    StatusOr<Grid> region = DecodeLmapRegion(*file, w);
    ASSERT_TRUE(region.ok()) << region.status().ToString();
    EXPECT_EQ(region->cells(), CellsIn(grid, w));
  }
}

// Written by the encoder of 2.0 (tile model 0 in every tile, before the
// layer context): it decodes to its map forever.
TEST(CellTilesTest, TemplateModelFileDecodes) {
  StatusOr<Grid> decoded = LoadLmap(testing::SourceDir() + "/tests/data/lmap/depot_v2_0.lmap");
  ASSERT_TRUE(decoded.ok()) << decoded.status().ToString();
  EXPECT_EQ(*decoded, Depot());
}

}  // namespace
}  // namespace linemap
