// CELL chunk: tile layout, tile index and the tiles (spec/format.md section 6).
#include "codec/cells/cell_tiles.h"

#include <algorithm>
#include <atomic>
#include <mutex>
#include <string>
#include <system_error>
#include <thread>
#include <utility>

#include "codec/cells/tile_index.h"
#include "format/byte_io.h"

namespace linemap {

TileLayout::TileLayout(int w, int h, int size) : width(w), height(h), tile_size(size) {
  tiles_x = w == 0 ? 0 : static_cast<int>((std::int64_t{w} + size - 1) / size);
  tiles_y = h == 0 ? 0 : static_cast<int>((std::int64_t{h} + size - 1) / size);
}

CellRect TileLayout::Tile(std::uint64_t i) const {
  const int tx = static_cast<int>(i % static_cast<std::uint64_t>(tiles_x));
  const int ty = static_cast<int>(i / static_cast<std::uint64_t>(tiles_x));
  CellRect r;
  r.x0 = tx * tile_size;
  r.y0 = ty * tile_size;
  r.x1 = static_cast<int>(std::min<std::int64_t>(std::int64_t{r.x0} + tile_size, width));
  r.y1 = static_cast<int>(std::min<std::int64_t>(std::int64_t{r.y0} + tile_size, height));
  return r;
}

void ForEachIndexParallel(std::uint64_t n, int threads,
                          const std::function<void(std::uint64_t)>& body) {
  // One item runs here, without asking for the cores: glibc reads
  // /sys/devices/system/cpu/online on every hardware_concurrency() call,
  // an open, read and close that were about 2 % of the CPU time of
  // decoding a median map of one tile (18 of the 25 maps of
  // ../shared/maps), 4 % of the smallest.
  if (n <= 1) {
    if (n == 1) body(0);
    return;
  }
  int workers = threads > 0 ? threads : static_cast<int>(std::thread::hardware_concurrency());
  workers = static_cast<int>(std::clamp<std::uint64_t>(n, 1, std::max(workers, 1)));
  std::atomic<std::uint64_t> next{0};
  const auto run = [&] {
    for (std::uint64_t i = next++; i < n; i = next++) body(i);
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < workers; ++t) {
    try {
      pool.emplace_back(run);
    } catch (const std::system_error&) {
      break;  // no more threads to be had: the others share the work
    }
  }
  run();
  for (std::thread& t : pool) t.join();
}

std::vector<Cell> TileCells(const Grid& grid, CellRect t) {
  const int tw = t.x1 - t.x0;
  // Appended row by row into reserved room: every cell is copied, so none
  // is zeroed first.
  std::vector<Cell> cells;
  cells.reserve(static_cast<std::size_t>(tw) * (t.y1 - t.y0));
  for (int r = t.y0; r < t.y1; ++r) {
    const auto row = grid.cells().begin() + static_cast<std::ptrdiff_t>(grid.Index(t.x0, r));
    cells.insert(cells.end(), row, row + tw);
  }
  return cells;
}

namespace {

// A tile of more than 2 kChoiceRows rows picks its model on its first
// kChoiceRows rows: each candidate codes them, and only the candidates
// within kChoiceSlack or kChoiceSlackBytes (whichever is more) of the
// smallest there code the whole tile. Why: the three whole codings were a
// tenth of an exact encode (the layers aside, nearly all of it), and which
// context function fits a tile shows in its first rows (from row 0, the
// map's bottom edge), unless those rows hold little (levinelobby's are
// nearly empty: 66 against 70 bytes there, and the whole tile then took
// 673 bytes against 630), which the bytes' slack covers. Over ../shared/maps (1024-cell tiles,
// encode CPU time on one thread, best of 7 runs, 4 alternating rounds): 2.7 % less time in all, 3.1
// % at the median map, and the same bytes as coding every candidate whole on all 25 maps (the 2 %
// alone cost 52 bytes, nearly all on levinelobby and avz5floor_plan, for 0.3 % more time saved).
constexpr int kChoiceRows = 128;
constexpr double kChoiceSlack = 0.02;
constexpr double kChoiceSlackBytes = 8;

// The candidates of `models` worth coding whole: all of them for a tile of
// at most 2 kChoiceRows rows, else those whose coding of the first
// kChoiceRows rows is within the slack of the smallest.
std::vector<TileModel> ModelsToTry(const std::vector<Cell>& cells,
                                   const std::vector<std::uint8_t>& hints, int tw, int th,
                                   const std::vector<TileModel>& models) {
  if (th <= 2 * kChoiceRows) return models;
  const CellRect top{0, 0, tw, kChoiceRows};
  std::vector<std::size_t> sizes;
  for (TileModel model : models) {
    sizes.push_back(EncodeTileCells(cells.data(), hints.data(), tw, th, top, model).size());
  }
  const double least = static_cast<double>(*std::min_element(sizes.begin(), sizes.end()));
  const double limit = std::max(least * (1.0 + kChoiceSlack), least + kChoiceSlackBytes);
  std::vector<TileModel> kept;
  for (std::size_t i = 0; i < models.size(); ++i) {
    if (static_cast<double>(sizes[i]) <= limit) kept.push_back(models[i]);
  }
  return kept;
}

}  // namespace

std::vector<std::uint8_t> EncodeCellTile(const std::vector<Cell>& cells,
                                         const std::vector<std::uint8_t>& hints, int tw, int th,
                                         bool compact) {
  const CellRect all{0, 0, tw, th};
  const auto encode = [&](TileModel model) {
    return EncodeTileCells(cells.data(), hints.data(), tw, th, all, model);
  };
  const auto keep_smaller = [&](std::vector<std::uint8_t>* best, TileModel model) {
    std::vector<std::uint8_t> data = encode(model);
    if (data.size() < best->size()) *best = std::move(data);
  };
  std::vector<std::uint8_t> best;
  if (std::all_of(hints.begin(), hints.end(), [](std::uint8_t h) { return h == 0; })) {
    best = encode(TileModel::kTemplate);
    if (compact) {
      keep_smaller(&best, TileModel::kMixedLayerAllCells);
      keep_smaller(&best, TileModel::kMixedAllCells);
    }
    return best;
  }
  if (compact) {
    // Coded for size: every candidate whole.
    best = encode(TileModel::kLayerContext);
    for (TileModel model :
         {LayerContextWithout(kLayerTermWestChange | kLayerTermNorthChange), TileModel::kTemplate,
          TileModel::kMixedLayerAllCells, TileModel::kMixedAllCells}) {
      keep_smaller(&best, model);
    }
    return best;
  }
  const std::vector<TileModel> models = ModelsToTry(
      cells, hints, tw, th,
      {TileModel::kLayerContext, LayerContextWithout(kLayerTermWestChange | kLayerTermNorthChange),
       TileModel::kTemplate});
  best = encode(models.front());
  for (std::size_t i = 1; i < models.size(); ++i) keep_smaller(&best, models[i]);
  return best;
}

int TileSide(int width, int height, int requested) {
  if (requested > 0) return requested;
  return std::max(width, height) <= 4 * kTileCells ? kTileCells : kLargeMapTileCells;
}

std::vector<std::uint8_t> EncodeCellChunk(const Grid& grid, const LayerIndex& layers, int tile_size,
                                          int threads, bool compact) {
  ByteWriter out;
  out.PutVarint(static_cast<std::uint64_t>(tile_size));
  WriteTiles(
      TileLayout(grid.width(), grid.height(), tile_size), threads,
      [&](CellRect t) {
        const int tw = t.x1 - t.x0, th = t.y1 - t.y0;
        // A map of one tile (most maps: up to 1024 cells a side) is its own
        // tile's cells, not copied.
        const bool whole = tw == grid.width() && th == grid.height();
        const std::vector<Cell> copy = whole ? std::vector<Cell>() : TileCells(grid, t);
        return EncodeCellTile(whole ? grid.cells() : copy, layers.TileHints(t), tw, th, compact);
      },
      &out);
  return std::move(out.mutable_bytes());
}

namespace {

// Canvas rows a multiple of 2048 cells (bytes) apart fall on at most two
// sets of a 64-set L1 cache, whose sets recur every 4 KiB, and on few sets
// of L2, so a tile's hints drawn straight into such a canvas evict
// themselves: every vertical wall and room side is walked down the tile a
// row at a time, and the next walk, often a column away, finds its lines
// gone. Generated office maps, tiles of 1024 cells, one thread, decode CPU
// per Mcell with the hints drawn in place: 4096 x 4096 cells 2.1-2.2 ms
// against 1.73-1.77 for 4000 x 4000, and 2048 x 2048 1.8-2.0 against
// 1.65-1.75 for 2560 and 3072 cells a side. Tiles on such a canvas draw
// their hints into a buffer of their own instead (4096 x 4096: 1.77-1.84
// ms; 2048 x 2048: 1.66-1.87), whose rows are kHintPadding bytes longer
// than the tile, so that they start a cache line apart even when the tile
// is a multiple of 2048 cells wide. Other canvases keep drawing in place:
// there the buffer cost 2-5 % more (the 3000- and 4000-cell maps).
constexpr std::ptrdiff_t kAliasingStride = 2048;
constexpr int kHintPadding = 64;
// Tiles of more cells than this (up to 65536 a side in a file, as
// `tile_size_cells` asks; 1024 by default) draw in place whatever the
// canvas: a buffer per thread for them could cost gigabytes.
constexpr std::int64_t kMaxBufferedTileCells = std::int64_t{1} << 22;

bool DrawsIntoBuffer(std::ptrdiff_t stride, int tw, int th) {
  return stride % kAliasingStride == 0 && std::int64_t{tw} * th <= kMaxBufferedTileCells;
}

// Hint buffers of the tiles being decoded at once: a tile takes one and
// gives it back for the next, so that a decode touches one buffer's
// pages per thread rather than a fresh megabyte per tile.
class HintBuffers {
 public:
  std::vector<std::uint8_t> Take() {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (free_.empty()) return {};
    std::vector<std::uint8_t> buffer = std::move(free_.back());
    free_.pop_back();
    return buffer;
  }
  void Give(std::vector<std::uint8_t> buffer) {
    const std::lock_guard<std::mutex> lock(mutex_);
    free_.push_back(std::move(buffer));
  }

 private:
  std::mutex mutex_;
  std::vector<std::vector<std::uint8_t>> free_;
};

// Decodes the first `rows` rows of tile t into `cells` (row r at cells + r
// * stride) against the layers' hints, drawn for those rows and the row
// after them, which the last row decoded reads.
Status DecodeTileOverLayers(const LayerIndex& layers, CellRect t, const std::uint8_t* data,
                            std::size_t size, int rows, Cell* cells, std::ptrdiff_t stride,
                            HintBuffers* buffers) {
  const int tw = t.x1 - t.x0, th = t.y1 - t.y0;
  CellRect drawn = t;
  drawn.y1 = std::min(t.y1, t.y0 + rows + 1);
  if (DrawsIntoBuffer(stride, tw, th)) {
    const int hint_stride = tw + kHintPadding;
    std::vector<std::uint8_t> hints = buffers->Take();
    hints.resize(static_cast<std::size_t>(hint_stride) * (drawn.y1 - drawn.y0));
    layers.DrawTileHints(drawn, hints.data(), hint_stride);
    const Status status =
        DecodeTileRows(data, size, hints.data(), hint_stride, tw, th, rows, cells, stride);
    buffers->Give(std::move(hints));
    return status;
  }
  // Drawn where the cells go, the decode reading each row's hints before
  // writing its cells over them.
  layers.DrawTileHints(drawn, reinterpret_cast<std::uint8_t*>(cells), stride);
  return DecodeTileRowsOverHints(data, size, tw, th, rows, cells, stride);
}

}  // namespace

Status DecodeCellChunk(const std::vector<std::uint8_t>& body, const LayerIndex& layers, int width,
                       int height, CellRect window, int threads, Cell* out) {
  ByteCursor cursor(body);
  LINEMAP_ASSIGN_OR_RETURN(std::uint64_t tile_size, cursor.ReadVarint("tile size"));
  if (tile_size < kMinTileSize || tile_size > kMaxTileSize) {
    return CorruptError("tile size " + std::to_string(tile_size) + " outside 16..65536");
  }
  const TileLayout layout(width, height, static_cast<int>(tile_size));
  LINEMAP_ASSIGN_OR_RETURN(TileIndex index, ReadTileIndex(body, layout, &cursor));
  HintBuffers buffers;
  return DecodeTilesInWindow(body, layout, index, window, threads, out,
                             [&](CellRect t, const std::uint8_t* data, std::size_t size, int rows,
                                 Cell* cells, std::ptrdiff_t stride) {
                               // Without layers every hint is zero: none to draw.
                               if (layers.empty()) {
                                 return DecodeTileRows(data, size, nullptr, 0, t.x1 - t.x0,
                                                       t.y1 - t.y0, rows, cells, stride);
                               }
                               return DecodeTileOverLayers(layers, t, data, size, rows, cells,
                                                           stride, &buffers);
                             });
}

}  // namespace linemap
