// The tile index of CELL and BLKS (spec/format.md 6.1).
#include "codec/cells/tile_index.h"

#include <algorithm>
#include <string>

namespace linemap {

void WriteTiles(const TileLayout& layout, int threads,
                const std::function<std::vector<std::uint8_t>(CellRect)>& encode, ByteWriter* out) {
  std::vector<std::vector<std::uint8_t>> tiles(layout.count());
  ForEachIndexParallel(layout.count(), threads,
                       [&](std::uint64_t i) { tiles[i] = encode(layout.Tile(i)); });
  for (const std::vector<std::uint8_t>& tile : tiles) out->PutVarint(tile.size());
  for (const std::vector<std::uint8_t>& tile : tiles) out->PutBytes(tile);
}

StatusOr<TileIndex> ReadTileIndex(const std::vector<std::uint8_t>& body, const TileLayout& layout,
                                  ByteCursor* cursor) {
  if (layout.count() > cursor->remaining()) return CorruptError("tile index past the chunk's end");
  // Every check of spec 6.1 is made in a first pass, before the offsets
  // are allocated (the sum stays below 2^64: each length is at most the
  // body's size, and there are fewer lengths than bytes).
  ByteCursor lengths = *cursor;
  std::uint64_t sum = 0;
  for (std::uint64_t i = 0; i < layout.count(); ++i) {
    LINEMAP_ASSIGN_OR_RETURN(std::uint64_t len, lengths.ReadVarint("tile length"));
    if (len > body.size()) return CorruptError("tile length past the chunk's end");
    sum += len;
  }
  if (sum != lengths.remaining()) {
    return CorruptError("tile lengths do not add up to the chunk's size");
  }
  TileIndex index;
  index.offsets.assign(layout.count() + 1, 0);
  for (std::uint64_t i = 0; i < layout.count(); ++i) {
    LINEMAP_ASSIGN_OR_RETURN(std::uint64_t len, cursor->ReadVarint("tile length"));
    index.offsets[i + 1] = index.offsets[i] + len;
  }
  index.base = cursor->position();
  return index;
}

std::vector<std::uint64_t> TilesMeeting(const TileLayout& layout, CellRect window) {
  std::vector<std::uint64_t> wanted;
  for (std::uint64_t i = 0; i < layout.count(); ++i) {
    const CellRect t = layout.Tile(i);
    if (t.x1 > window.x0 && t.x0 < window.x1 && t.y1 > window.y0 && t.y0 < window.y1) {
      wanted.push_back(i);
    }
  }
  return wanted;
}

Status DecodeTilesInWindow(const std::vector<std::uint8_t>& body, const TileLayout& layout,
                           const TileIndex& index, CellRect window, int threads, Cell* out,
                           const TileDecoder& decode) {
  const std::vector<std::uint64_t> wanted = TilesMeeting(layout, window);
  const int ww = window.x1 - window.x0;
  std::vector<Status> status(wanted.size());
  ForEachIndexParallel(wanted.size(), threads, [&](std::uint64_t k) {
    const std::uint64_t i = wanted[k];
    const CellRect t = layout.Tile(i);
    const int tw = t.x1 - t.x0, th = t.y1 - t.y0;
    const std::uint8_t* data = body.data() + index.base + index.offsets[i];
    const std::size_t size = index.offsets[i + 1] - index.offsets[i];
    if (t.x0 >= window.x0 && t.x1 <= window.x1 && t.y0 >= window.y0 && t.y1 <= window.y1) {
      // A tile inside the window decodes straight into it.
      status[k] =
          decode(t, data, size, th,
                 out + static_cast<std::ptrdiff_t>(t.y0 - window.y0) * ww + (t.x0 - window.x0), ww);
      return;
    }
    // Rows are coded from the tile's first: those after the window's last
    // are not needed (a window near a tile's first rows decodes a fraction).
    const int rows = std::min(t.y1, window.y1) - t.y0;
    // Room for those rows and the one after, whose hints the last reads.
    std::vector<Cell> cells(static_cast<std::size_t>(tw) * std::min(th, rows + 1), Cell::kUnknown);
    status[k] = decode(t, data, size, rows, cells.data(), tw);
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
