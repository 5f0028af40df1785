// The tile cell coder's entry points: exact round trips on random and real
// grids, tiles decoding on their own, and malformed data refused without
// crashing. Its bytes against the spec: tile_coding_spec_test.cc.
#include "codec/cells/tile_coder.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "codec/cells/tile_hints.h"
#include "tests/codec/cells/tile_test_grids.h"

namespace linemap {
namespace {

using tile_test::BundledMaps;
using tile_test::Bytes;
using tile_test::RandomCell;
using tile_test::RandomGrid;
using tile_test::RandomTile;

// `n` hint bytes, a third of them with random bits.
std::vector<std::uint8_t> RandomHints(std::mt19937& rng, std::size_t n) {
  std::vector<std::uint8_t> hints(n);
  for (auto& h : hints) h = rng() % 3 == 0 ? static_cast<std::uint8_t>(rng() % 16) : 0;
  return hints;
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

}  // namespace
}  // namespace linemap
