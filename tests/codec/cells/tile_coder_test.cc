// The tile cell coder: exact round trips on random and real grids, tiles
// decoding on their own, and malformed data refused without crashing.
#include "codec/cells/tile_coder.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "codec/cells/tile_hints.h"
#include "linemap/map_io.h"
#include "tests/testing/test_support.h"

namespace linemap {
namespace {

using Bytes = std::vector<std::uint8_t>;

Cell RandomCell(std::mt19937& rng) { return static_cast<Cell>(rng() % 3); }

// A width x height grid of one of three kinds: independent random cells
// (nothing to predict), rectangles of one value over a background (rows and
// blocks equal to the row below, the copy paths), or rectangles with a
// sprinkle of noise.
// `n` hint bytes, a third of them with random bits.
std::vector<std::uint8_t> RandomHints(std::mt19937& rng, std::size_t n) {
  std::vector<std::uint8_t> hints(n);
  for (auto& h : hints) h = rng() % 3 == 0 ? static_cast<std::uint8_t>(rng() % 16) : 0;
  return hints;
}

std::vector<Cell> RandomGrid(std::mt19937& rng, int width, int height) {
  const std::size_t n = static_cast<std::size_t>(width) * height;
  std::vector<Cell> cells(n, RandomCell(rng));
  const int kind = static_cast<int>(rng() % 3);
  if (kind == 0) {
    for (Cell& c : cells) c = RandomCell(rng);
    return cells;
  }
  const int rects = static_cast<int>(rng() % 6);
  for (int k = 0; k < rects && width > 0 && height > 0; ++k) {
    const int x0 = static_cast<int>(rng() % width);
    const int y0 = static_cast<int>(rng() % height);
    const int x1 = x0 + 1 + static_cast<int>(rng() % (width - x0));
    const int y1 = y0 + 1 + static_cast<int>(rng() % (height - y0));
    const Cell v = RandomCell(rng);
    for (int y = y0; y < y1; ++y) {
      for (int x = x0; x < x1; ++x) cells[static_cast<std::size_t>(y) * width + x] = v;
    }
  }
  if (kind == 2) {
    for (Cell& c : cells) {
      if (rng() % 20 == 0) c = RandomCell(rng);
    }
  }
  return cells;
}

CellRect RandomTile(std::mt19937& rng, int width, int height) {
  CellRect t;
  t.x0 = static_cast<int>(rng() % (width + 1));
  t.x1 = t.x0 + static_cast<int>(rng() % (width - t.x0 + 1));
  t.y0 = static_cast<int>(rng() % (height + 1));
  t.y1 = t.y0 + static_cast<int>(rng() % (height - t.y0 + 1));
  return t;
}

bool Inside(CellRect t, int x, int y) { return x >= t.x0 && x < t.x1 && y >= t.y0 && y < t.y1; }

// Decodes `data` for `tile` onto a canvas holding `background` and checks
// that the tile's cells equal `cells` and every other cell is untouched.
void ExpectDecodes(const Bytes& data, const std::vector<Cell>& cells,
                   const std::vector<Cell>& background, const std::uint8_t* hints, int width,
                   int height, CellRect tile) {
  std::vector<Cell> canvas = background;
  const Status s =
      DecodeTileCells(data.data(), data.size(), hints, width, height, tile, canvas.data());
  ASSERT_TRUE(s.ok()) << s.ToString();
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * width + x;
      ASSERT_EQ(canvas[i], Inside(tile, x, y) ? cells[i] : background[i])
          << "cell (" << x << ", " << y << ") of tile [" << tile.x0 << ", " << tile.x1 << ") x ["
          << tile.y0 << ", " << tile.y1 << ")";
    }
  }
}

TEST(TileCoderTest, RandomGridsAndTilesRoundTrip) {
  std::mt19937 rng(20261125);
  for (int iter = 0; iter < 400; ++iter) {
    const int width = static_cast<int>(rng() % 41);
    const int height = static_cast<int>(rng() % 41);
    const std::vector<Cell> cells = RandomGrid(rng, width, height);
    const std::vector<Cell> background = RandomGrid(rng, width, height);
    std::vector<std::uint8_t> hints(cells.size());
    for (auto& h : hints) h = static_cast<std::uint8_t>(rng() % 16);
    const std::uint8_t* hint_ptr = iter % 2 ? hints.data() : nullptr;
    CellRect tile = RandomTile(rng, width, height);
    if (iter % 5 == 0) tile = CellRect{0, 0, width, height};
    if (iter % 7 == 0 && width > 0 && height > 0) {
      tile = CellRect{width - 1, height - 1, width, height};  // the corner cell
    }
    SCOPED_TRACE("iteration " + std::to_string(iter));
    for (TileModel model : {TileModel::kTemplate, TileModel::kMixed, TileModel::kTemplateAllCells,
                            TileModel::kMixedAllCells, TileModel::kLayerContext,
                            LayerContextWithout(kLayerTermWestChange | kLayerTermNorthChange),
                            TileModel::kLayerContextLast, TileModel::kMixedLayerAllCells}) {
      const Bytes data = EncodeTileCells(cells.data(), hint_ptr, width, height, tile, model);
      ExpectDecodes(data, cells, background, hint_ptr, width, height, tile);
    }
  }
}

TEST(TileCoderTest, EmptyTileHasNoBytes) {
  const std::vector<Cell> cells(12, Cell::kOccupied);
  for (const CellRect t : {CellRect{0, 0, 0, 3}, CellRect{2, 1, 4, 1}, CellRect{4, 3, 4, 3}}) {
    EXPECT_TRUE(EncodeTileCells(cells.data(), nullptr, 4, 3, t).empty());
    std::vector<Cell> canvas(12, Cell::kFree);
    EXPECT_TRUE(DecodeTileCells(nullptr, 0, nullptr, 4, 3, t, canvas.data()).ok());
    const std::uint8_t extra = 0;
    EXPECT_FALSE(DecodeTileCells(&extra, 1, nullptr, 4, 3, t, canvas.data()).ok());
    EXPECT_EQ(canvas, std::vector<Cell>(12, Cell::kFree));
  }
}

TEST(TileCoderTest, TileOutsideTheGridIsRefused) {
  std::vector<Cell> canvas(12, Cell::kFree);
  const std::uint8_t byte = 0;
  for (const CellRect t :
       {CellRect{-1, 0, 2, 2}, CellRect{0, 0, 5, 3}, CellRect{0, 2, 4, 4}, CellRect{3, 0, 2, 3}}) {
    const Status s = DecodeTileCells(&byte, 1, nullptr, 4, 3, t, canvas.data());
    EXPECT_EQ(s.code(), StatusCode::kInvalidArgument) << s.ToString();
  }
}

// The encoder reads only the tile's own cells: changing every cell outside
// it leaves the bytes as they were.
TEST(TileCoderTest, BytesDependOnlyOnTheTilesCells) {
  std::mt19937 rng(7);
  for (int iter = 0; iter < 50; ++iter) {
    const int width = 1 + static_cast<int>(rng() % 30);
    const int height = 1 + static_cast<int>(rng() % 30);
    std::vector<Cell> cells = RandomGrid(rng, width, height);
    const CellRect tile = RandomTile(rng, width, height);
    const Bytes before = EncodeTileCells(cells.data(), nullptr, width, height, tile);
    for (int y = 0; y < height; ++y) {
      for (int x = 0; x < width; ++x) {
        if (!Inside(tile, x, y)) cells[static_cast<std::size_t>(y) * width + x] = RandomCell(rng);
      }
    }
    EXPECT_EQ(EncodeTileCells(cells.data(), nullptr, width, height, tile), before);
  }
}

// A tile copied into buffers of its own (with a wider stride than the
// tile, as a band buffer would have) codes to the same bytes, and decodes
// into such a buffer.
TEST(TileCoderTest, TileRowsInBuffersOfTheirOwn) {
  std::mt19937 rng(5);
  for (int iter = 0; iter < 60; ++iter) {
    const int width = 1 + static_cast<int>(rng() % 300);
    const int height = 1 + static_cast<int>(rng() % 30);
    const std::vector<Cell> cells = RandomGrid(rng, width, height);
    const std::vector<std::uint8_t> hints = RandomHints(rng, cells.size());
    const CellRect t = RandomTile(rng, width, height);
    const int tw = t.x1 - t.x0, th = t.y1 - t.y0, stride = tw + 3;
    std::vector<Cell> local_cells(static_cast<std::size_t>(stride) * th + 1, Cell::kFree);
    std::vector<std::uint8_t> local_hints(local_cells.size(), 0);
    for (int y = 0; y < th; ++y) {
      for (int x = 0; x < tw; ++x) {
        const std::size_t from = static_cast<std::size_t>(t.y0 + y) * width + t.x0 + x;
        local_cells[static_cast<std::size_t>(y) * stride + x] = cells[from];
        local_hints[static_cast<std::size_t>(y) * stride + x] = hints[from];
      }
    }
    for (TileModel model :
         {TileModel::kTemplate, TileModel::kMixed, TileModel::kLayerContext,
          LayerContextWithout(kLayerTermNorthChange), TileModel::kMixedLayerAllCells}) {
      const Bytes data =
          EncodeTileRows(local_cells.data(), stride, local_hints.data(), stride, tw, th, model);
      ASSERT_EQ(data, EncodeTileCells(cells.data(), hints.data(), width, height, t, model));
      std::vector<Cell> out(local_cells.size(), Cell::kUnknown);
      ASSERT_TRUE(DecodeTileRows(data.data(), data.size(), local_hints.data(), stride, tw, th, th,
                                 out.data(), stride)
                      .ok());
      for (int y = 0; y < th; ++y) {
        for (int x = 0; x < stride; ++x) {
          const std::size_t i = static_cast<std::size_t>(y) * stride + x;
          ASSERT_EQ(out[i], x < tw ? local_cells[i] : Cell::kUnknown) << x << ", " << y;
        }
      }
      // The same cells decoded over the hints drawn where they go.
      std::vector<Cell> over(local_cells.size(), Cell::kUnknown);
      for (int y = 0; y < th; ++y) {
        for (int x = 0; x < tw; ++x) {
          const std::size_t i = static_cast<std::size_t>(y) * stride + x;
          std::memcpy(&over[i], &local_hints[i], 1);
        }
      }
      ASSERT_TRUE(
          DecodeTileRowsOverHints(data.data(), data.size(), tw, th, th, over.data(), stride).ok());
      ASSERT_EQ(over, out);
    }
  }
}

// A window that ends inside a tile decodes only the tile's first rows: they
// equal the tile's cells, and the hints of the rows after the one following
// them are not read (they hold other bytes here).
TEST(TileCoderTest, FirstRowsOfATileDecodeAsInTheWholeTile) {
  std::mt19937 rng(23);
  for (int iter = 0; iter < 80; ++iter) {
    const int tw = 1 + static_cast<int>(rng() % 120);
    const int th = 2 + static_cast<int>(rng() % 40);
    const std::vector<Cell> cells = RandomGrid(rng, tw, th);
    const std::vector<std::uint8_t> hints = RandomHints(rng, cells.size());
    const int rows = 1 + static_cast<int>(rng() % static_cast<unsigned>(th - 1));
    for (TileModel model : {TileModel::kTemplate, TileModel::kLayerContext,
                            TileModel::kMixedAllCells, TileModel::kMixedLayerAllCells}) {
      const Bytes data = EncodeTileRows(cells.data(), tw, hints.data(), tw, tw, th, model);
      std::vector<Cell> part(cells.size(), Cell::kUnknown);
      ASSERT_TRUE(
          DecodeTileRows(data.data(), data.size(), hints.data(), tw, tw, th, rows, part.data(), tw)
              .ok());
      // Over hints drawn for the rows decoded and the one after only.
      std::vector<Cell> over(cells.size(), Cell::kOccupied);
      std::memcpy(over.data(), hints.data(), static_cast<std::size_t>(tw) * (rows + 1));
      ASSERT_TRUE(
          DecodeTileRowsOverHints(data.data(), data.size(), tw, th, rows, over.data(), tw).ok());
      const auto first = cells.begin() + static_cast<std::ptrdiff_t>(tw) * rows;
      ASSERT_TRUE(std::equal(cells.begin(), first, part.begin())) << iter;
      ASSERT_TRUE(std::equal(cells.begin(), first, over.begin())) << iter;
      // Nothing is written past the rows wanted (the decoder writes each
      // row's cells one row late, over hints the row above has read): the
      // row after them keeps its hints, the others their bytes.
      const std::ptrdiff_t done = first - cells.begin();
      ASSERT_TRUE(
          std::all_of(part.begin() + done, part.end(), [](Cell c) { return c == Cell::kUnknown; }));
      ASSERT_EQ(std::memcmp(over.data() + done, hints.data() + done, static_cast<std::size_t>(tw)),
                0);
      ASSERT_TRUE(std::all_of(over.begin() + done + tw, over.end(),
                              [](Cell c) { return c == Cell::kOccupied; }));
      // Rows past those wanted are refused, as is none of a non-empty tile.
      EXPECT_FALSE(DecodeTileRows(data.data(), data.size(), hints.data(), tw, tw, th, th + 1,
                                  part.data(), tw)
                       .ok());
      EXPECT_FALSE(
          DecodeTileRows(data.data(), data.size(), hints.data(), tw, tw, th, 0, part.data(), tw)
              .ok());
    }
  }
}

std::vector<CellRect> Tiles(int width, int height, int size) {
  std::vector<CellRect> out;
  for (int y = 0; y < height; y += size) {
    for (int x = 0; x < width; x += size) {
      out.push_back(CellRect{x, y, std::min(x + size, width), std::min(y + size, height)});
    }
  }
  return out;
}

std::vector<Grid> BundledMaps() {
  std::vector<Grid> maps;
  for (const std::string& yaml : testing::FindYamlFiles(testing::BundledMapsDir())) {
    StatusOr<Grid> g = LoadRosMap(yaml);
    EXPECT_TRUE(g.ok()) << yaml << ": " << g.status().ToString();
    if (g.ok()) maps.push_back(std::move(*g));
  }
  EXPECT_GE(maps.size(), 4u);
  return maps;
}

// Every bundled map, in tiles of several sizes (the whole map, 1024, 256,
// and 97, whose tiles end mid-block), with and without the layers' hints,
// decodes to its cells; decoding a single tile gives the full decode's crop.
TEST(TileCoderTest, BundledMapsRoundTripInTiles) {
  for (const Grid& g : BundledMaps()) {
    const int w = g.width();
    const int h = g.height();
    StatusOr<std::vector<std::uint8_t>> hints = BuildLayerHints(g);
    ASSERT_TRUE(hints.ok()) << hints.status().ToString();
    for (const std::uint8_t* hint_ptr : {static_cast<const std::uint8_t*>(nullptr),
                                         static_cast<const std::uint8_t*>(hints->data())}) {
      for (int size : {std::max(w, h), 1024, 256, 97}) {
        // The thirteen models in turn over the tiles: the decoder reads each.
        const std::vector<CellRect> tiles = Tiles(w, h, size);
        std::vector<Bytes> data;
        for (const CellRect& t : tiles) {
          const TileModel model = static_cast<TileModel>(data.size() % 13);
          data.push_back(EncodeTileCells(g.cells().data(), hint_ptr, w, h, t, model));
        }
        std::vector<Cell> full(g.size(), Cell::kUnknown);
        for (std::size_t k = tiles.size(); k-- > 0;) {
          const Status s = DecodeTileCells(data[k].data(), data[k].size(), hint_ptr, w, h, tiles[k],
                                           full.data());
          ASSERT_TRUE(s.ok()) << s.ToString();
        }
        ASSERT_EQ(full, g.cells())
            << "tile size " << size << (hint_ptr ? " with" : " without") << " hints";
        const std::size_t k = tiles.size() / 2;
        ExpectDecodes(data[k], full, std::vector<Cell>(g.size(), Cell::kFree), hint_ptr, w, h,
                      tiles[k]);
      }
    }
  }
}

// The layer context pays where the layers are drawn: over the bundled
// maps with their hints, model 4 codes fewer bytes than model 0.
TEST(TileCoderTest, LayerContextIsSmallerThanTheTemplateWithHints) {
  std::size_t template_bytes = 0, layer_bytes = 0;
  for (const Grid& g : BundledMaps()) {
    StatusOr<std::vector<std::uint8_t>> hints = BuildLayerHints(g);
    ASSERT_TRUE(hints.ok()) << hints.status().ToString();
    for (const CellRect& t : Tiles(g.width(), g.height(), 1024)) {
      template_bytes += EncodeTileCells(g.cells().data(), hints->data(), g.width(), g.height(), t,
                                        TileModel::kTemplate)
                            .size();
      layer_bytes += EncodeTileCells(g.cells().data(), hints->data(), g.width(), g.height(), t,
                                     TileModel::kLayerContext)
                         .size();
    }
  }
  EXPECT_LT(layer_bytes, template_bytes);
}

// Every truncation and every appended byte is an error; random byte flips
// never crash (they may decode to other cells: the container's checksum
// catches those).
TEST(TileCoderTest, MalformedDataIsRefusedWithoutCrashing) {
  const std::vector<Grid> maps = BundledMaps();
  ASSERT_FALSE(maps.empty());
  const Grid& g = maps.front();
  const CellRect all{0, 0, g.width(), g.height()};
  const Bytes data = EncodeTileCells(g.cells().data(), nullptr, g.width(), g.height(), all);
  ASSERT_GT(data.size(), 10u);
  std::vector<Cell> canvas(g.size());
  const Bytes mixed =
      EncodeTileCells(g.cells().data(), nullptr, g.width(), g.height(), all, TileModel::kMixed);
  for (const Bytes* d : {&data, &mixed}) {
    for (std::size_t n = 0; n < d->size(); ++n) {
      EXPECT_FALSE(
          DecodeTileCells(d->data(), n, nullptr, g.width(), g.height(), all, canvas.data()).ok())
          << "truncated to " << n << " of " << d->size() << " bytes";
    }
  }
  for (std::uint8_t extra : {0, 1, 255}) {
    Bytes longer = data;
    longer.push_back(extra);
    EXPECT_FALSE(DecodeTileCells(longer.data(), longer.size(), nullptr, g.width(), g.height(), all,
                                 canvas.data())
                     .ok());
  }
  for (std::uint8_t model : {13, 14, 31}) {  // models 13 and up do not exist
    Bytes bad_model = data;
    bad_model[0] = static_cast<std::uint8_t>((bad_model[0] & ~31) | model);
    EXPECT_FALSE(DecodeTileCells(bad_model.data(), bad_model.size(), nullptr, g.width(), g.height(),
                                 all, canvas.data())
                     .ok());
  }
  std::mt19937 rng(99);
  for (int iter = 0; iter < 200; ++iter) {
    Bytes flipped = data;
    flipped[1 + rng() % (flipped.size() - 1)] ^= static_cast<std::uint8_t>(1 + rng() % 255);
    (void)DecodeTileCells(flipped.data(), flipped.size(), nullptr, g.width(), g.height(), all,
                          canvas.data());
    for (Cell c : canvas) ASSERT_LE(static_cast<int>(c), 2);
  }
}

// An independent encoder written from spec/tile_coding.md's words, plainly
// (no row buffers, no padding, bounds tested per cell): the library's bytes
// must equal it, so the spec and the code say the same thing.
class SpecEncoder {
 public:
  // `model` as the tile's model id: for 0-3 bit 0 mixed, bit 1 every cell;
  // 4-11 the layer context without the terms of the bits of model - 4; 12
  // every cell with the mixed layer context.
  SpecEncoder(const std::vector<Cell>& cells, const std::vector<std::uint8_t>& hints, int width,
              CellRect tile, int model)
      : cells_(cells),
        hints_(hints),
        width_(width),
        t_(tile),
        model_(model),
        mixed_(model < 4 && (model & 1) != 0),
        all_cells_((model < 4 && (model & 2) != 0) || model == 12),
        layer_(model >= 4 && model <= 11),
        mixed_layer_(model == 12),
        dropped_(model >= 4 && model <= 11 ? model - 4 : 0) {}

  Bytes Encode() {
    const int tw = t_.x1 - t_.x0;
    const int th = t_.y1 - t_.y0;
    if (tw == 0 || th == 0) return {};
    const int blocks = (tw + 15) / 16;
    std::vector<int> above_block(blocks, 2), above_super((blocks + 15) / 16, 2);
    int row_state = 2;
    for (int r = 0; r < th; ++r) {
      const bool row_copy = RangeEqualsBelow(0, tw, r);
      Bit(0 + row_state * 2 + HintsSame(0, tw, r), row_copy);
      if (row_copy) {
        row_state = 1;
        std::fill(above_block.begin(), above_block.end(), 1);
        std::fill(above_super.begin(), above_super.end(), 1);
        continue;
      }
      row_state = 0;
      if (all_cells_) {
        for (int c = 0; c < tw; ++c) CodeCell(c, r);
        continue;
      }
      const std::vector<int> below_block = above_block;  // states after the row below
      int left = 2, left_super = 2;
      for (int k = 0; k * 16 < blocks; ++k) {
        const int b_end = std::min(16 * k + 16, blocks);
        const int a = 256 * k, e = std::min(256 * k + 256, tw);
        const bool super_copy = RangeEqualsBelow(a, e, r);
        Bit(kSuper + ((above_super[k] * 3 + left_super) * 2 + HintsSame(a, e, r)) * 4 +
                Uniform(a, e, r),
            super_copy);
        above_super[k] = left_super = super_copy ? 1 : 0;
        if (super_copy) {
          for (int b = 16 * k; b < b_end; ++b) above_block[b] = 1;
          left = 1;
          continue;
        }
        bool changed = false;
        for (int b = 16 * k; b < b_end; ++b) {
          const int ba = 16 * b, be = std::min(16 * b + 16, tw);
          const int above_right = b + 1 < blocks ? below_block[b + 1] : 2;
          bool copy = RangeEqualsBelow(ba, be, r);
          if (b + 1 == b_end && !changed) {
            copy = false;  // implied
          } else {
            // Model 4: LBLOCK (after LEQUAL and LOTHER) next to a drawn wall.
            const int table = layer_ && WallNear(ba, be, r) ? kEqual + 2 * 3240 : kBlock;
            Bit(table +
                    (((below_block[b] * 3 + left) * 3 + above_right) * 2 + HintsSame(ba, be, r)) *
                        4 +
                    Uniform(ba, be, r),
                copy);
          }
          if (!copy) {
            changed = true;
            for (int c = ba; c < be; ++c) CodeCell(c, r);
          }
          above_block[b] = left = copy ? 1 : 0;
        }
      }
    }
    for (int b = 15; b >= 0; --b) Code(32768, (0xA55A >> b) & 1);  // end marker
    return Finish();
  }

 private:
  static constexpr int kBlock = 6, kSuper = kBlock + 216, kEqual = kSuper + 72,
                       kOther = kEqual + 32805, kNear = kOther + 405;
  // Model 12's LEQUAL, LOTHER and WIDE (any place of their own will do).
  static constexpr int kMixedLayer = kNear + 405, kWide = kMixedLayer + 2 * 3240;
  struct Model {
    std::uint32_t fast = 32768, slow = 32768, n = 0;
  };

  int V(int c, int r) const {
    if (c < 0 || r < 0 || c >= t_.x1 - t_.x0) return 2;
    return static_cast<int>(cells_[static_cast<std::size_t>(t_.y0 + r) * width_ + t_.x0 + c]);
  }
  int H(int c, int r) const {
    return hints_.empty() ? 0 : hints_[static_cast<std::size_t>(t_.y0 + r) * width_ + t_.x0 + c];
  }
  bool RangeEqualsBelow(int a, int e, int r) const {
    for (int c = a; c < e; ++c) {
      if (V(c, r) != V(c, r - 1)) return false;
    }
    return true;
  }
  int HintsSame(int a, int e, int r) const {
    if (r == 0) return 0;
    for (int c = a; c < e; ++c) {
      if (H(c, r) != H(c, r - 1)) return 0;
    }
    return 1;
  }
  int Uniform(int a, int e, int r) const {
    for (int c = a - 1; c <= e; ++c) {
      if (V(c, r - 1) != V(a, r - 1)) return 0;
    }
    return 1 + V(a, r - 1);
  }
  // Whether bit 0 is set in a hint of columns [a, e) of rows r - 1 .. r + 1
  // (inside the tile).
  bool WallNear(int a, int e, int r) const {
    for (int rr = r - 1; rr <= r + 1; ++rr) {
      for (int c = a; c < e; ++c) {
        if (LayerH(c, rr) & 1) return true;
      }
    }
    return false;
  }
  // Model 4's hint: bits 0-3 inside the tile, 0 outside it.
  int LayerH(int c, int r) const {
    if (c < 0 || r < 0 || c >= t_.x1 - t_.x0 || r >= t_.y1 - t_.y0) return 0;
    return H(c, r) & 15;
  }
  // Model 4 ("Layer context"): class and pattern as the spec's table says.
  void CodeLayerCell(int c, int r) {
    const int h = LayerH(c, r);
    const int hc = h & 1 ? 1 : h & 4 ? 2 : h & 8 ? 3 : h & 2 ? 4 : 0;
    const bool wall_next =
        ((LayerH(c - 1, r) | LayerH(c + 1, r) | LayerH(c, r - 1) | LayerH(c, r + 1)) & 1) != 0;
    int other_class = hc;
    if (!(dropped_ & 4) && hc != 1 && !wall_next) other_class += 20;
    int layer_class = other_class;
    if (!(dropped_ & 1) && LayerH(c - 1, r) != h) layer_class += 5;
    if (!(dropped_ & 2) && LayerH(c, r - 1) != h) layer_class += 10;
    const int w = V(c - 1, r), v = V(c, r);
    const int pattern = ((w * 3 + V(c, r - 1)) * 3 + V(c - 1, r - 1)) * 3 + V(c + 1, r - 1);
    const int ctx = pattern * 40 + layer_class;
    Bit(kEqual + ctx, v == w);
    if (v == w) return;
    const int hi = w == 2 ? 1 : 2;
    Bit(kEqual + 3240 + pattern * 40 + other_class, v == hi);
  }
  // The layer classes of section 5.2 (`dropped_` terms left out).
  void LayerClasses(int c, int r, int* layer_class, int* other_class) const {
    const int h = LayerH(c, r);
    const int hc = h & 1 ? 1 : h & 4 ? 2 : h & 8 ? 3 : h & 2 ? 4 : 0;
    const bool wall_next =
        ((LayerH(c - 1, r) | LayerH(c + 1, r) | LayerH(c, r - 1) | LayerH(c, r + 1)) & 1) != 0;
    *other_class = hc;
    if (!(dropped_ & 4) && hc != 1 && !wall_next) *other_class += 20;
    *layer_class = *other_class;
    if (!(dropped_ & 1) && LayerH(c - 1, r) != h) *layer_class += 5;
    if (!(dropped_ & 2) && LayerH(c, r - 1) != h) *layer_class += 10;
  }
  // Step 4's template T of cell (c, r) (W the least significant digit).
  int Template(int c, int r) const {
    return V(c - 1, r) +
           3 * (V(c - 2, r) +
                3 * (V(c - 2, r - 1) +
                     3 * (V(c - 1, r - 1) +
                          3 * (V(c, r - 1) +
                               3 * (V(c + 1, r - 1) + 3 * (V(c + 2, r - 1) + 3 * V(c, r - 2)))))));
  }
  // Model 12 (section 5.3): EQUAL, LEQUAL, NEAR and WIDE mixed where EQUAL
  // is unsure; LEQUAL learns from every cell.
  void CodeMixedLayerCell(int c, int r) {
    const int h = H(c, r);
    const int hc = h & 1 ? 1 : h & 4 ? 2 : h & 8 ? 3 : h & 2 ? 4 : 0;
    int layer_class = 0, other_class = 0;
    LayerClasses(c, r, &layer_class, &other_class);
    const int w = V(c - 1, r), v = V(c, r);
    const int t = Template(c, r);
    const int pattern = ((w * 3 + V(c, r - 1)) * 3 + V(c - 1, r - 1)) * 3 + V(c + 1, r - 1);
    const int a = kEqual + t * 5 + hc;
    const int b = kMixedLayer + pattern * 40 + layer_class;
    const int near = kNear + pattern * 5 + hc;
    const int wide = kWide + t * 9 + V(c - 1, r - 2) * 3 + V(c + 1, r - 2);
    const std::uint32_t p_equal = P0(models_[a]);
    if (p_equal < 2048 || p_equal > 63488) {
      Bit(a, v == w);
      Update(models_[b], v == w);
    } else {
      const int inputs[4] = {a, b, near, wide};
      const int set = other_class * 2 + (w == V(c, r - 1) ? 1 : 0);
      MixedBitOf(inputs, 4, &weights12_[static_cast<std::size_t>(set) * 4], v == w);
    }
    if (v == w) return;
    const int hi = w == 2 ? 1 : 2;
    Bit(kMixedLayer + 3240 + pattern * 40 + other_class, v == hi);
  }
  void CodeCell(int c, int r) {
    if (layer_) return CodeLayerCell(c, r);
    if (mixed_layer_) return CodeMixedLayerCell(c, r);
    const int h = H(c, r);
    const int hc = h & 1 ? 1 : h & 4 ? 2 : h & 8 ? 3 : h & 2 ? 4 : 0;
    const int w = V(c - 1, r), v = V(c, r);
    const int t = Template(c, r);
    const int near = (((w * 3 + V(c, r - 1)) * 3 + V(c - 1, r - 1)) * 3 + V(c + 1, r - 1)) * 5 + hc;
    const std::uint32_t p_equal = P0(models_[kEqual + t * 5 + hc]);
    if (mixed_ && p_equal >= 2048 && p_equal <= 63488) {
      MixedBit(kEqual + t * 5 + hc, kNear + near, hc * 2 + (w == V(c, r - 1) ? 1 : 0), v == w);
    } else {
      Bit(kEqual + t * 5 + hc, v == w);
    }
    if (v == w) return;
    const int hi = w == 2 ? 1 : 2;
    Bit(kOther + near, v == hi);
  }
  static std::uint32_t P0(const Model& m) { return (m.fast + m.slow) >> 1; }
  static int Squash(int d) {
    static const int kT[33] = {1,    2,    3,    6,    10,   16,   27,   45,   73,   120,  194,
                               310,  488,  747,  1101, 1546, 2047, 2549, 2994, 3348, 3607, 3785,
                               3901, 3975, 4022, 4050, 4068, 4079, 4085, 4089, 4092, 4093, 4094};
    const int k = static_cast<int>(std::floor(d / 128.0)) + 16;
    const int w = d - (k - 16) * 128;
    return (kT[k] * (128 - w) + kT[k + 1] * w + 64) / 128;
  }
  // The least d in [-2047, 2047] with Squash(d) >= p, else 2047 (found by
  // search, once per p).
  int Stretch(int p) {
    std::vector<int>& memo = stretch_memo_;
    if (memo[p] == 4096) {
      memo[p] = 2047;
      for (int d = -2047; d <= 2047; ++d) {
        if (Squash(d) >= p) {
          memo[p] = d;
          break;
        }
      }
    }
    return memo[p];
  }
  void MixedBit(int equal, int near, int set, bool one) {
    const int inputs[2] = {equal, near};
    MixedBitOf(inputs, 2, weights_[set], one);
  }
  // Section 5.1 with `n` inputs (the models at `inputs`) and weights `w`.
  void MixedBitOf(const int* inputs, int n, std::int64_t* w, bool one) {
    int st[4] = {};
    std::int64_t dot = 0;
    for (int k = 0; k < n; ++k) {
      st[k] = Stretch(static_cast<int>((65535 - P0(models_[inputs[k]])) / 16));
      dot += w[k] * st[k];
    }
    const std::int64_t d = std::clamp<std::int64_t>(
        static_cast<std::int64_t>(std::floor(static_cast<double>(dot) / 65536.0)), -2047, 2047);
    const int p1 = std::clamp(Squash(static_cast<int>(d)), 1, 4095);
    Code(static_cast<std::uint32_t>(4096 - p1) * 16, one);
    const int err = ((one ? 4096 : 0) - p1) * 2;
    for (int k = 0; k < n; ++k) {
      w[k] = std::clamp<std::int64_t>(
          w[k] + static_cast<std::int64_t>(std::floor(st[k] * err / 1024.0)), -(1 << 24), 1 << 24);
    }
    for (int k = 0; k < n; ++k) Update(models_[inputs[k]], one);
  }
  void Code(std::uint32_t p0, bool one) {
    const std::uint32_t bound = (range_ >> 16) * p0;
    if (!one) {
      range_ = bound;
    } else {
      low_ += bound;
      range_ -= bound;
    }
    while (range_ < (1u << 24)) {
      range_ <<= 8;
      ShiftLow();
    }
  }
  static void Update(Model& m, bool one) {
    const std::uint32_t ss =
        std::min(static_cast<std::uint32_t>(std::floor(std::log2(m.n + 2.0))), 7u);
    const std::uint32_t fs = std::min(ss, 2u);
    if (!one) {
      m.fast += (65536 - m.fast) >> fs;
      m.slow += (65536 - m.slow) >> ss;
    } else {
      m.fast -= m.fast >> fs;
      m.slow -= m.slow >> ss;
    }
    m.n = std::min(m.n + 1, 126u);
  }
  void Bit(int context, bool one) {
    Model& m = models_[context];
    const std::uint32_t bound = (range_ >> 16) * ((m.fast + m.slow) >> 1);
    if (!one) {
      range_ = bound;
    } else {
      low_ += bound;
      range_ -= bound;
    }
    const std::uint32_t ss =
        std::min(static_cast<std::uint32_t>(std::floor(std::log2(m.n + 2.0))), 7u);
    const std::uint32_t fs = std::min(ss, 2u);
    if (!one) {
      m.fast += (65536 - m.fast) >> fs;
      m.slow += (65536 - m.slow) >> ss;
    } else {
      m.fast -= m.fast >> fs;
      m.slow -= m.slow >> ss;
    }
    m.n = std::min(m.n + 1, 126u);
    while (range_ < (1u << 24)) {
      range_ <<= 8;
      ShiftLow();
    }
  }
  void ShiftLow() {
    if (low_ < 0xFF000000u || low_ >= (std::uint64_t{1} << 32)) {
      const int carry = static_cast<int>(low_ >> 32);
      out_.push_back(static_cast<std::uint8_t>(cache_ + carry));
      for (; pending_ff_ > 0; --pending_ff_)
        out_.push_back(static_cast<std::uint8_t>(0xFF + carry));
      cache_ = static_cast<std::uint8_t>(low_ >> 24);
    } else {
      ++pending_ff_;
    }
    low_ = (low_ & 0x00FFFFFFu) << 8;
  }
  Bytes Finish() {
    for (int k = 32; k >= 0; --k) {
      const std::uint64_t v = (low_ + range_ - 1) & ~((std::uint64_t{1} << k) - 1);
      if (v >= low_) {
        low_ = v;
        break;
      }
    }
    for (int i = 0; i < 5; ++i) ShiftLow();
    out_.erase(out_.begin());
    int dropped = 0;
    while (!out_.empty() && out_.back() == 0 && dropped < 7) {
      out_.pop_back();
      ++dropped;
    }
    out_.insert(out_.begin(), static_cast<std::uint8_t>(dropped << 5 | model_));
    return out_;
  }

  const std::vector<Cell>& cells_;
  const std::vector<std::uint8_t>& hints_;
  int width_;
  CellRect t_;
  int model_;
  bool mixed_;
  bool all_cells_;
  bool layer_;
  bool mixed_layer_;
  int dropped_;  // layer terms left out: 1 change from W, 2 from N, 4 wall
  std::vector<int> stretch_memo_ = std::vector<int>(4096, 4096);  // 4096: not searched yet
  std::vector<Model> models_ = std::vector<Model>(kWide + 59049);
  std::vector<std::int64_t> weights12_ = std::vector<std::int64_t>(50 * 4, 19661);  // model 12
  std::int64_t weights_[10][2] = {{19661, 19661}, {19661, 19661}, {19661, 19661}, {19661, 19661},
                                  {19661, 19661}, {19661, 19661}, {19661, 19661}, {19661, 19661},
                                  {19661, 19661}, {19661, 19661}};
  std::uint64_t low_ = 0;
  std::uint32_t range_ = 0xFFFFFFFFu;
  std::uint8_t cache_ = 0;
  int pending_ff_ = 0;
  Bytes out_;
};

TEST(TileCoderTest, BytesFollowTheSpec) {
  std::mt19937 rng(31337);
  for (int iter = 0; iter < 200; ++iter) {
    // Up to 600 columns, so rows hold several super-blocks.
    const int width = static_cast<int>(rng() % 600);
    const int height = static_cast<int>(rng() % 12);
    const std::vector<Cell> cells = RandomGrid(rng, width, height);
    std::vector<std::uint8_t> hints;
    if (iter % 2) {
      hints.resize(cells.size());
      // Bits 4-7 are set in some tiles: they count in the flags' "hints same"
      // and are ignored by model 4's layer class.
      const unsigned values = iter % 4 == 1 ? 256 : 16;
      for (auto& h : hints) h = rng() % 4 == 0 ? static_cast<std::uint8_t>(rng() % values) : 0;
    }
    const CellRect tile = iter % 3 ? RandomTile(rng, width, height) : CellRect{0, 0, width, height};
    SCOPED_TRACE("iteration " + std::to_string(iter));
    const std::uint8_t* hint_ptr = hints.empty() ? nullptr : hints.data();
    EXPECT_EQ(EncodeTileCells(cells.data(), hint_ptr, width, height, tile),
              SpecEncoder(cells, hints, width, tile, 0).Encode());
    for (int model = 0; model <= 12; ++model) {
      EXPECT_EQ(EncodeTileCells(cells.data(), hint_ptr, width, height, tile,
                                static_cast<TileModel>(model)),
                SpecEncoder(cells, hints, width, tile, model).Encode())
          << "model " << model;
    }
  }
  for (const Grid& g : BundledMaps()) {
    StatusOr<std::vector<std::uint8_t>> hints = BuildLayerHints(g);
    ASSERT_TRUE(hints.ok()) << hints.status().ToString();
    const std::vector<std::uint8_t> none;
    const CellRect all{0, 0, g.width(), g.height()};
    EXPECT_EQ(EncodeTileCells(g.cells().data(), nullptr, g.width(), g.height(), all),
              SpecEncoder(g.cells(), none, g.width(), all, 0).Encode());
    for (int model = 1; model <= 12; ++model) {
      EXPECT_EQ(EncodeTileCells(g.cells().data(), hints->data(), g.width(), g.height(), all,
                                static_cast<TileModel>(model)),
                SpecEncoder(g.cells(), *hints, g.width(), all, model).Encode())
          << "model " << model;
    }
  }
}

}  // namespace
}  // namespace linemap
