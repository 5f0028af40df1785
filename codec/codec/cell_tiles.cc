// CELL chunk: tile layout, tile index and the tiles (spec/format.md section 6).
#include "codec/codec/cell_tiles.h"

#include <algorithm>
#include <atomic>
#include <string>
#include <system_error>
#include <thread>

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

namespace {

// The tile's cells as a tile-sized array (the tile coder sees the tile as a
// grid of its own, so it cannot read past it).
std::vector<Cell> TileCells(const Grid& grid, CellRect t) {
  const int tw = t.x1 - t.x0;
  std::vector<Cell> cells(static_cast<std::size_t>(tw) * (t.y1 - t.y0));
  for (int r = t.y0; r < t.y1; ++r) {
    std::copy_n(grid.cells().begin() + static_cast<std::ptrdiff_t>(grid.Index(t.x0, r)), tw,
                cells.begin() + static_cast<std::ptrdiff_t>(r - t.y0) * tw);
  }
  return cells;
}

}  // namespace

std::vector<std::uint8_t> EncodeCellChunk(const Grid& grid, const LayerIndex& layers, int tile_size,
                                          int threads) {
  const TileLayout layout(grid.width(), grid.height(), tile_size);
  std::vector<std::vector<std::uint8_t>> tiles(layout.count());
  ForEachIndexParallel(layout.count(), threads, [&](std::uint64_t i) {
    const CellRect t = layout.Tile(i);
    const int tw = t.x1 - t.x0, th = t.y1 - t.y0;
    const std::vector<Cell> cells = TileCells(grid, t);
    const std::vector<std::uint8_t> hints = layers.TileHints(t);
    tiles[i] = EncodeTileCells(cells.data(), hints.data(), tw, th, CellRect{0, 0, tw, th});
  });
  ByteWriter out;
  out.PutVarint(static_cast<std::uint64_t>(tile_size));
  for (const std::vector<std::uint8_t>& tile : tiles) out.PutVarint(tile.size());
  for (const std::vector<std::uint8_t>& tile : tiles) out.PutBytes(tile);
  return std::move(out.mutable_bytes());
}

Status DecodeCellChunk(const std::vector<std::uint8_t>& body, const LayerIndex& layers, int width,
                       int height, CellRect window, int threads, Cell* out) {
  ByteCursor cursor(body);
  LINEMAP_ASSIGN_OR_RETURN(std::uint64_t tile_size, cursor.ReadVarint("tile size"));
  if (tile_size < kMinTileSize || tile_size > kMaxTileSize) {
    return CorruptError("tile size " + std::to_string(tile_size) + " outside 16..65536");
  }
  const TileLayout layout(width, height, static_cast<int>(tile_size));
  // Every tile's length takes at least one byte: a count the body cannot
  // hold is corrupt before anything is allocated for it.
  if (layout.count() > cursor.remaining()) return CorruptError("tile index past the chunk's end");
  std::vector<std::uint64_t> offsets(layout.count() + 1, 0);
  for (std::uint64_t i = 0; i < layout.count(); ++i) {
    LINEMAP_ASSIGN_OR_RETURN(std::uint64_t len, cursor.ReadVarint("tile length"));
    if (len > body.size()) return CorruptError("tile length past the chunk's end");
    offsets[i + 1] = offsets[i] + len;
  }
  const std::size_t base = cursor.position();
  if (offsets.back() != body.size() - base) {
    return CorruptError("tile lengths do not add up to the chunk's size");
  }
  std::vector<std::uint64_t> wanted;
  for (std::uint64_t i = 0; i < layout.count(); ++i) {
    const CellRect t = layout.Tile(i);
    if (t.x1 > window.x0 && t.x0 < window.x1 && t.y1 > window.y0 && t.y0 < window.y1) {
      wanted.push_back(i);
    }
  }
  const int ww = window.x1 - window.x0;
  std::vector<Status> status(wanted.size());
  ForEachIndexParallel(wanted.size(), threads, [&](std::uint64_t k) {
    const std::uint64_t i = wanted[k];
    const CellRect t = layout.Tile(i);
    const int tw = t.x1 - t.x0, th = t.y1 - t.y0;
    const std::vector<std::uint8_t> hints = layers.TileHints(t);
    const std::uint8_t* data = body.data() + base + offsets[i];
    const std::size_t size = offsets[i + 1] - offsets[i];
    if (t.x0 >= window.x0 && t.x1 <= window.x1 && t.y0 >= window.y0 && t.y1 <= window.y1) {
      // A tile inside the window decodes straight into it.
      status[k] = DecodeTileRows(
          data, size, hints.data(), tw, tw, th,
          out + static_cast<std::ptrdiff_t>(t.y0 - window.y0) * ww + (t.x0 - window.x0), ww);
      return;
    }
    std::vector<Cell> cells(static_cast<std::size_t>(tw) * th, Cell::kUnknown);
    status[k] = DecodeTileRows(data, size, hints.data(), tw, tw, th, cells.data(), tw);
    if (!status[k].ok()) return;
    const int c0 = std::max(t.x0, window.x0), c1 = std::min(t.x1, window.x1);
    for (int r = std::max(t.y0, window.y0); r < std::min(t.y1, window.y1); ++r) {
      std::copy_n(cells.begin() + static_cast<std::ptrdiff_t>(r - t.y0) * tw + (c0 - t.x0), c1 - c0,
                  out + static_cast<std::ptrdiff_t>(r - window.y0) * ww + (c0 - window.x0));
    }
  });
  for (std::size_t k = 0; k < wanted.size(); ++k) {
    if (!status[k].ok()) return status[k].WithContext("tile " + std::to_string(wanted[k]));
  }
  return Status::Ok();
}

}  // namespace linemap
