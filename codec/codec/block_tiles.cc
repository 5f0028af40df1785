// BLKS chunk: block side, tile layout, tile index and the tiles
// (spec/format.md section 6.4).
#include "codec/codec/block_tiles.h"

#include <algorithm>
#include <string>

#include "codec/codec/cell_tiles.h"
#include "codec/codec/tile_index.h"
#include "format/byte_io.h"

namespace linemap {
namespace {

// Both passes use the tile coder's smallest model: the block grid has
// 1/F^2 of the map's cells, and the cells' pass is mostly settled by the
// blocks' hints. Files within a tolerance are for bandwidth, so a slower
// decode than the exact file's is the right trade.
constexpr TileModel kBlockModel = TileModel::kMixedAllCells;
constexpr TileModel kCellModel = TileModel::kMixedAllCells;

int CeilDiv(int a, int b) { return (a + b - 1) / b; }

// A tile's blocks (bw x bh, row 0 first) and the hints they draw into its
// cells: the block's value as the layer hint of that value (occupied ->
// wall, free -> room inside, unknown -> none), so the tile coder's cell
// contexts know where the blocks say the map changes.
struct TileBlocks {
  int bw = 0, bh = 0;
  std::vector<Cell> blocks;
};

TileBlocks EmptyBlocks(int w, int h, int f) {
  TileBlocks b;
  b.bw = CeilDiv(w, f);
  b.bh = CeilDiv(h, f);
  b.blocks.assign(static_cast<std::size_t>(b.bw) * b.bh, Cell::kUnknown);
  return b;
}

std::uint8_t HintOfBlock(Cell block) {
  return block == Cell::kOccupied ? kHintWall : block == Cell::kFree ? kHintRoomInside : 0;
}

std::vector<std::uint8_t> HintsOfBlocks(const TileBlocks& b, int w, int h, int f) {
  std::vector<std::uint8_t> hints(static_cast<std::size_t>(w) * h);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      hints[static_cast<std::size_t>(y) * w + x] =
          HintOfBlock(b.blocks[static_cast<std::size_t>(y / f) * b.bw + x / f]);
    }
  }
  return hints;
}

// Tile t's blocks, which are the grid's because its corner is a multiple
// of the block side.
TileBlocks GatherBlocks(const BlockCells& cells, CellRect t) {
  const int f = cells.block_cells;
  TileBlocks b = EmptyBlocks(t.x1 - t.x0, t.y1 - t.y0, f);
  for (int by = 0; by < b.bh; ++by) {
    for (int bx = 0; bx < b.bw; ++bx) {
      b.blocks[static_cast<std::size_t>(by) * b.bw + bx] =
          cells.blocks[static_cast<std::size_t>(t.y0 / f + by) * cells.blocks_x + t.x0 / f + bx];
    }
  }
  return b;
}

std::vector<Cell> TileCellsOf(const Grid& grid, CellRect t) {
  const int tw = t.x1 - t.x0;
  std::vector<Cell> cells(static_cast<std::size_t>(tw) * (t.y1 - t.y0));
  for (int r = t.y0; r < t.y1; ++r) {
    std::copy_n(grid.cells().begin() + static_cast<std::ptrdiff_t>(grid.Index(t.x0, r)), tw,
                cells.begin() + static_cast<std::ptrdiff_t>(r - t.y0) * tw);
  }
  return cells;
}

std::vector<std::uint8_t> EncodeTile(const Grid& decoded, const BlockCells& cells, CellRect t) {
  const int w = t.x1 - t.x0, h = t.y1 - t.y0, f = cells.block_cells;
  const TileBlocks b = GatherBlocks(cells, t);
  const std::vector<std::uint8_t> blocks = EncodeTileCells(b.blocks.data(), nullptr, b.bw, b.bh,
                                                           CellRect{0, 0, b.bw, b.bh}, kBlockModel);
  const std::vector<Cell> tile = TileCellsOf(decoded, t);
  const std::vector<std::uint8_t> hints = HintsOfBlocks(b, w, h, f);
  ByteWriter out;
  out.PutVarint(blocks.size());
  out.PutBytes(blocks);
  out.PutBytes(EncodeTileCells(tile.data(), hints.data(), w, h, CellRect{0, 0, w, h}, kCellModel));
  return std::move(out.mutable_bytes());
}

// Decodes one tile's data into `cells` (w x h, row-major).
Status DecodeTile(const std::uint8_t* data, std::size_t size, int w, int h, int f,
                  std::vector<Cell>* cells) {
  ByteCursor cursor(data, size);
  LINEMAP_ASSIGN_OR_RETURN(std::uint64_t blocks_len, cursor.ReadVarint("block data length"));
  if (blocks_len > cursor.remaining()) return CorruptError("block data past the tile's end");
  TileBlocks b = EmptyBlocks(w, h, f);
  const std::uint8_t* at = data + cursor.position();
  LINEMAP_RETURN_IF_ERROR(DecodeTileCells(at, blocks_len, nullptr, b.bw, b.bh,
                                          CellRect{0, 0, b.bw, b.bh}, b.blocks.data()));
  const std::vector<std::uint8_t> hints = HintsOfBlocks(b, w, h, f);
  cells->assign(static_cast<std::size_t>(w) * h, Cell::kUnknown);
  return DecodeTileCells(at + blocks_len, cursor.remaining() - blocks_len, hints.data(), w, h,
                         CellRect{0, 0, w, h}, cells->data());
}

}  // namespace

Grid ComposeBlockCells(const Grid& original, const BlockCells& b) {
  Grid out(original.width(), original.height());
  out.meta = original.meta;
  const int f = b.block_cells;
  for (int y = 0; y < original.height(); ++y) {
    for (int x = 0; x < original.width(); ++x) {
      out.set(x, y,
              b.restored[original.Index(x, y)]
                  ? original.at(x, y)
                  : b.blocks[static_cast<std::size_t>(y / f) * b.blocks_x + x / f]);
    }
  }
  return out;
}

StatusOr<std::vector<std::uint8_t>> EncodeBlockChunk(const Grid& original, const BlockCells& blocks,
                                                     int tile_size, int threads) {
  const int f = blocks.block_cells;
  if (f < kMinBlockCells || f > kMaxBlockCells || tile_size % f != 0) {
    return InvalidArgumentError("tile size " + std::to_string(tile_size) +
                                " is not a multiple of the block side " + std::to_string(f));
  }
  const TileLayout layout(original.width(), original.height(), tile_size);
  std::vector<std::vector<std::uint8_t>> tiles(layout.count());
  const Grid decoded = ComposeBlockCells(original, blocks);
  ForEachIndexParallel(layout.count(), threads, [&](std::uint64_t i) {
    tiles[i] = EncodeTile(decoded, blocks, layout.Tile(i));
  });
  ByteWriter out;
  out.PutU8(static_cast<std::uint8_t>(f));
  out.PutVarint(static_cast<std::uint64_t>(tile_size));
  for (const std::vector<std::uint8_t>& tile : tiles) out.PutVarint(tile.size());
  for (const std::vector<std::uint8_t>& tile : tiles) out.PutBytes(tile);
  return std::move(out.mutable_bytes());
}

Status DecodeBlockChunk(const std::vector<std::uint8_t>& body, int width, int height,
                        CellRect window, int threads, Cell* out) {
  ByteCursor cursor(body);
  LINEMAP_ASSIGN_OR_RETURN(std::uint8_t f, cursor.ReadU8("block side"));
  if (f < kMinBlockCells || f > kMaxBlockCells) {
    return CorruptError("block side " + std::to_string(f) + " outside 2..5");
  }
  LINEMAP_ASSIGN_OR_RETURN(std::uint64_t tile_size, cursor.ReadVarint("tile size"));
  if (tile_size < kMinTileSize || tile_size > kMaxTileSize || tile_size % f != 0) {
    return CorruptError("tile size " + std::to_string(tile_size) +
                        " outside 16..65536 or not a multiple of the block side");
  }
  const TileLayout layout(width, height, static_cast<int>(tile_size));
  LINEMAP_ASSIGN_OR_RETURN(TileIndex index, ReadTileIndex(body, layout, &cursor));
  const std::vector<std::uint64_t> wanted = TilesMeeting(layout, window);
  const int ww = window.x1 - window.x0;
  std::vector<Status> status(wanted.size());
  ForEachIndexParallel(wanted.size(), threads, [&](std::uint64_t k) {
    const std::uint64_t i = wanted[k];
    const CellRect t = layout.Tile(i);
    const int tw = t.x1 - t.x0;
    std::vector<Cell> cells;
    status[k] = DecodeTile(body.data() + index.base + index.offsets[i],
                           index.offsets[i + 1] - index.offsets[i], tw, t.y1 - t.y0, f, &cells);
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
