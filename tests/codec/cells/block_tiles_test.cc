// The BLKS chunk (spec/format.md 6.4): round trips of blocks with restored
// cells, windows, and a body laid out by hand from the spec's tables (the
// tile coder called on the parts the spec names) that the decoder must
// read; malformed bodies fail.
#include "codec/cells/block_tiles.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "codec/layers/layer_hints.h"
#include "format/byte_io.h"

namespace linemap {
namespace {

Cell RandomCell(std::mt19937* rng) { return static_cast<Cell>((*rng)() % 3); }

const std::vector<WallPolyline> kNoWalls;
const std::vector<RoomOutline> kNoRooms;
const std::vector<FurnitureObject> kNoFurniture;

const LayerIndex& NoLayers() {
  static const LayerIndex index(kNoWalls, kNoRooms, kNoFurniture);
  return index;
}

// Two walls across the grid: their hints change how the blocks are coded.
const std::vector<WallPolyline> kTwoWalls = {{{{0, 3}, {39, 3}, {39, 17}}}, {{{5, 0}, {5, 19}}}};

// Blocks of side f over a w x h grid with random values, and random cells
// restored to a random original.
struct Case {
  Grid original;
  BlockCells blocks;
};

Case RandomCase(std::uint32_t seed, int w, int h, int f, double restored_share) {
  std::mt19937 rng(seed);
  Case c{Grid(w, h), BlockCells{}};
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) c.original.set(x, y, RandomCell(&rng));
  }
  BlockCells& b = c.blocks;
  b.block_cells = f;
  b.blocks_x = (w + f - 1) / f;
  b.blocks_y = (h + f - 1) / f;
  for (int i = 0; i < b.blocks_x * b.blocks_y; ++i) b.blocks.push_back(RandomCell(&rng));
  std::bernoulli_distribution restore(restored_share);
  for (int i = 0; i < w * h; ++i) b.restored.push_back(restore(rng) ? 1 : 0);
  return c;
}

// The composition by its definition: the original where restored, else the
// value of the block holding the cell.
Grid ReferenceCompose(const Case& c) {
  Grid out(c.original.width(), c.original.height());
  const int f = c.blocks.block_cells;
  for (int y = 0; y < out.height(); ++y) {
    for (int x = 0; x < out.width(); ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * out.width() + x;
      out.set(x, y,
              c.blocks.restored[i] ? c.original.at(x, y)
                                   : c.blocks.blocks[(y / f) * c.blocks.blocks_x + x / f]);
    }
  }
  return out;
}

StatusOr<std::vector<Cell>> Decode(const std::vector<std::uint8_t>& body, int w, int h,
                                   CellRect window, int threads = 1,
                                   const LayerIndex& layers = NoLayers()) {
  std::vector<Cell> out(static_cast<std::size_t>(window.x1 - window.x0) * (window.y1 - window.y0),
                        Cell::kUnknown);
  LINEMAP_RETURN_IF_ERROR(DecodeBlockChunk(body, layers, w, h, window, threads, out.data()));
  return out;
}

TEST(BlockTilesTest, ComposeFollowsTheDefinition) {
  for (int f = kMinBlockCells; f <= kMaxBlockCells; ++f) {
    const Case c = RandomCase(10 + f, 37, 23, f, 0.2);
    const Grid composed = ComposeBlockCells(c.original, c.blocks);
    EXPECT_EQ(composed.cells(), ReferenceCompose(c).cells()) << "F=" << f;
  }
}

TEST(BlockTilesTest, RoundTripsEveryBlockSideAndTileSide) {
  for (int f = kMinBlockCells; f <= kMaxBlockCells; ++f) {
    for (const double share : {0.0, 0.05, 1.0}) {
      const Case c = RandomCase(100 + f, 83, 61, f, share);
      const Grid expected = ReferenceCompose(c);
      for (const int tile : {f * (16 / f + 1), 60, 1024 / f * f}) {
        if (tile % f != 0 || tile < 16) continue;
        auto body = EncodeBlockChunk(c.original, c.blocks, NoLayers(), tile, 2);
        ASSERT_TRUE(body.ok()) << body.status().ToString();
        auto cells = Decode(*body, 83, 61, CellRect{0, 0, 83, 61}, 2);
        ASSERT_TRUE(cells.ok()) << cells.status().ToString();
        EXPECT_EQ(*cells, expected.cells()) << "F=" << f << " share " << share << " tile " << tile;
      }
    }
  }
}

TEST(BlockTilesTest, WindowsAreCropsAndThreadsDoNotMatter) {
  const Case c = RandomCase(7, 90, 70, 2, 0.03);
  const Grid expected = ReferenceCompose(c);
  auto body = EncodeBlockChunk(c.original, c.blocks, NoLayers(), 32, 1);
  ASSERT_TRUE(body.ok());
  auto body4 = EncodeBlockChunk(c.original, c.blocks, NoLayers(), 32, 4);
  ASSERT_TRUE(body4.ok());
  EXPECT_EQ(*body, *body4);
  for (const CellRect w : {CellRect{0, 0, 1, 1}, CellRect{31, 31, 33, 33}, CellRect{5, 40, 90, 70},
                           CellRect{89, 69, 90, 70}}) {
    auto cells = Decode(*body, 90, 70, w, 3);
    ASSERT_TRUE(cells.ok());
    std::size_t k = 0;
    for (int y = w.y0; y < w.y1; ++y) {
      for (int x = w.x0; x < w.x1; ++x)
        EXPECT_EQ((*cells)[k++], expected.at(x, y)) << x << "," << y;
    }
  }
}

// A body written from the spec's tables: F, T, the tile lengths, then per
// tile the block data length, the blocks coded with the union of the layer
// hints of their cells (here two walls; none for a file without layers),
// and the cells coded with hint 1 / 2 / 0 for an occupied / free / unknown
// block. The encoder writes the same bytes.
void ExpectBodyAsTheSpecSays(const std::vector<WallPolyline>& walls) {
  const LayerIndex layers(walls, kNoRooms, kNoFurniture);
  const int w = 40, h = 20, f = 3, tile = 24;
  const Case c = RandomCase(3, w, h, f, 0.1);
  const Grid decoded = ReferenceCompose(c);
  std::vector<std::vector<std::uint8_t>> tiles;
  for (int ty = 0; ty * tile < h; ++ty) {
    for (int tx = 0; tx * tile < w; ++tx) {
      const int x0 = tx * tile, y0 = ty * tile;
      const int tw = std::min(tile, w - x0), th = std::min(tile, h - y0);
      const int bw = (tw + f - 1) / f, bh = (th + f - 1) / f;
      const std::vector<std::uint8_t> layer_hints =
          layers.TileHints(CellRect{x0, y0, x0 + tw, y0 + th});
      std::vector<std::uint8_t> block_hints(static_cast<std::size_t>(bw) * bh, 0);
      for (int r = 0; r < th; ++r) {
        for (int col = 0; col < tw; ++col)
          block_hints[(r / f) * bw + col / f] |= layer_hints[r * tw + col];
      }
      std::vector<Cell> blocks;
      for (int by = 0; by < bh; ++by) {
        for (int bx = 0; bx < bw; ++bx) {
          blocks.push_back(c.blocks.blocks[(y0 / f + by) * c.blocks.blocks_x + x0 / f + bx]);
        }
      }
      std::vector<Cell> cells;
      std::vector<std::uint8_t> hints;
      for (int r = 0; r < th; ++r) {
        for (int col = 0; col < tw; ++col) {
          cells.push_back(decoded.at(x0 + col, y0 + r));
          const Cell b = blocks[(r / f) * bw + col / f];
          hints.push_back(b == Cell::kOccupied ? 1 : b == Cell::kFree ? 2 : 0);
        }
      }
      // Each part with the smaller of models 3 and 12 (3 on a tie).
      const auto smaller = [](std::vector<std::uint8_t> a, std::vector<std::uint8_t> b) {
        return b.size() < a.size() ? b : a;
      };
      const auto block_data =
          smaller(EncodeTileCells(blocks.data(), block_hints.data(), bw, bh, CellRect{0, 0, bw, bh},
                                  TileModel::kMixedAllCells),
                  EncodeTileCells(blocks.data(), block_hints.data(), bw, bh, CellRect{0, 0, bw, bh},
                                  TileModel::kMixedLayerAllCells));
      const auto cell_data =
          smaller(EncodeTileCells(cells.data(), hints.data(), tw, th, CellRect{0, 0, tw, th},
                                  TileModel::kMixedAllCells),
                  EncodeTileCells(cells.data(), hints.data(), tw, th, CellRect{0, 0, tw, th},
                                  TileModel::kMixedLayerAllCells));
      ByteWriter t;
      t.PutVarint(block_data.size());
      t.PutBytes(block_data);
      t.PutBytes(cell_data);
      tiles.push_back(t.bytes());
    }
  }
  ByteWriter body;
  body.PutU8(f);
  body.PutVarint(tile);
  for (const auto& t : tiles) body.PutVarint(t.size());
  for (const auto& t : tiles) body.PutBytes(t);
  auto out = Decode(body.bytes(), w, h, CellRect{0, 0, w, h}, 1, layers);
  ASSERT_TRUE(out.ok()) << out.status().ToString();
  EXPECT_EQ(*out, decoded.cells());
  auto encoded = EncodeBlockChunk(c.original, c.blocks, layers, tile, 1);
  ASSERT_TRUE(encoded.ok());
  EXPECT_EQ(*encoded, body.bytes());
}

TEST(BlockTilesTest, ReadsABodyLaidOutAsTheSpecSays) {
  ExpectBodyAsTheSpecSays(kNoWalls);
  ExpectBodyAsTheSpecSays(kTwoWalls);
}

TEST(BlockTilesTest, MalformedBodiesAreCorrupt) {
  const Case c = RandomCase(5, 30, 30, 2, 0.1);
  auto body = EncodeBlockChunk(c.original, c.blocks, NoLayers(), 16, 1);
  ASSERT_TRUE(body.ok());
  const CellRect all{0, 0, 30, 30};
  auto expect_corrupt = [&](std::vector<std::uint8_t> bytes, const char* what) {
    auto out = Decode(bytes, 30, 30, all);
    ASSERT_FALSE(out.ok()) << what;
    EXPECT_EQ(out.status().code(), StatusCode::kCorrupt) << what << ": " << out.status().ToString();
  };
  std::vector<std::uint8_t> b = *body;
  b[0] = 6;
  expect_corrupt(b, "block side 6");
  b = *body;
  b[0] = 3;  // 16 is not a multiple of 3
  expect_corrupt(b, "tile side not a multiple");
  b = *body;
  b.pop_back();
  expect_corrupt(b, "one byte short");
  b = *body;
  b.resize(3);
  expect_corrupt(b, "index cut");
  expect_corrupt({}, "empty body");
}

TEST(BlockTilesTest, EncoderRefusesATileSideThatIsNotAMultiple) {
  const Case c = RandomCase(5, 30, 30, 3, 0.0);
  auto body = EncodeBlockChunk(c.original, c.blocks, NoLayers(), 16, 1);
  ASSERT_FALSE(body.ok());
  EXPECT_EQ(body.status().code(), StatusCode::kInvalidArgument);
}

}  // namespace
}  // namespace linemap
