// BLKS chunk: block side, tile layout, tile index and the tiles
// (spec/format.md section 6.4).
#include "codec/cells/block_tiles.h"

#include <algorithm>
#include <string>

#include "codec/cells/cell_tiles.h"
#include "codec/cells/tile_index.h"
#include "format/byte_io.h"

namespace linemap {
namespace {

// Both passes use the tile coder's smallest model: the block grid has
// 1/F^2 of the map's cells, and the cells' pass is mostly settled by the
// blocks' hints. Files within a tolerance are for bandwidth, so a slower
// decode than the exact file's is the right trade.
// Tolerance files are for bandwidth: the block grid and the cells are
// coded with whichever of the two smallest codings is smaller for the tile
// (spec/tile_coding.md models 3 and 12; 12 adds the layer context, which
// the blocks have from the layers and the cells from their blocks).
constexpr TileModel kSmallestModels[] = {TileModel::kMixedAllCells, TileModel::kMixedLayerAllCells};

// The smaller of the tile's codings with kSmallestModels (the first on a
// tie).
std::vector<std::uint8_t> EncodeSmallest(const Cell* cells, const std::uint8_t* hints, int w,
                                         int h) {
  std::vector<std::uint8_t> best;
  for (TileModel model : kSmallestModels) {
    std::vector<std::uint8_t> data =
        EncodeTileCells(cells, hints, w, h, CellRect{0, 0, w, h}, model);
    if (best.empty() || data.size() < best.size()) best = std::move(data);
  }
  return best;
}

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

// The hints of a tile's block grid: each block the union of the hint bits
// the layers draw into its cells (spec/format.md 6.4), so the blocks are
// coded knowing where the walls, rooms and furniture are, as exact cells
// are.
std::vector<std::uint8_t> BlockHints(const LayerIndex& layers, CellRect t, int bw, int bh, int f) {
  std::vector<std::uint8_t> out(static_cast<std::size_t>(bw) * bh, 0);
  if (layers.empty()) return out;
  const int w = t.x1 - t.x0, h = t.y1 - t.y0;
  const std::vector<std::uint8_t> cells = layers.TileHints(t);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      out[static_cast<std::size_t>(y / f) * bw + x / f] |=
          cells[static_cast<std::size_t>(y) * w + x];
    }
  }
  return out;
}

std::vector<std::uint8_t> EncodeTile(const Grid& decoded, const BlockCells& cells,
                                     const LayerIndex& layers, CellRect t) {
  const int w = t.x1 - t.x0, h = t.y1 - t.y0, f = cells.block_cells;
  const TileBlocks b = GatherBlocks(cells, t);
  const std::vector<std::uint8_t> block_hints = BlockHints(layers, t, b.bw, b.bh, f);
  const std::vector<std::uint8_t> blocks =
      EncodeSmallest(b.blocks.data(), block_hints.data(), b.bw, b.bh);
  const std::vector<Cell> tile = TileCells(decoded, t);
  const std::vector<std::uint8_t> hints = HintsOfBlocks(b, w, h, f);
  ByteWriter out;
  out.PutVarint(blocks.size());
  out.PutBytes(blocks);
  out.PutBytes(EncodeSmallest(tile.data(), hints.data(), w, h));
  return std::move(out.mutable_bytes());
}

// Decodes tile t's data: row r of its cells at cells + r * stride, for
// its first `rows` rows (the blocks are decoded whole: they are few).
Status DecodeTile(const std::uint8_t* data, std::size_t size, const LayerIndex& layers, CellRect t,
                  int f, int rows, Cell* cells, std::ptrdiff_t stride) {
  const int w = t.x1 - t.x0, h = t.y1 - t.y0;
  ByteCursor cursor(data, size);
  LINEMAP_ASSIGN_OR_RETURN(std::uint64_t blocks_len, cursor.ReadVarint("block data length"));
  if (blocks_len > cursor.remaining()) return CorruptError("block data past the tile's end");
  TileBlocks b = EmptyBlocks(w, h, f);
  const std::uint8_t* at = data + cursor.position();
  const std::vector<std::uint8_t> block_hints = BlockHints(layers, t, b.bw, b.bh, f);
  LINEMAP_RETURN_IF_ERROR(DecodeTileCells(at, blocks_len, block_hints.data(), b.bw, b.bh,
                                          CellRect{0, 0, b.bw, b.bh}, b.blocks.data()));
  const std::vector<std::uint8_t> hints = HintsOfBlocks(b, w, h, f);
  return DecodeTileRows(at + blocks_len, cursor.remaining() - blocks_len, hints.data(), w, w, h,
                        rows, cells, stride);
}

}  // namespace

Grid ComposeBlockCells(const Grid& original, const BlockCells& b) {
  Grid out(original.width(), original.height());
  out.meta = original.meta;
  // A block's run of cells at a time: the tolerance fitting composes the
  // whole map every round, and two divisions per cell were most of it.
  const int f = b.block_cells;
  const std::size_t side = static_cast<std::size_t>(f);
  const std::size_t w = static_cast<std::size_t>(original.width());
  const Cell* cells = original.cells().data();
  const std::uint8_t* restored = b.restored.data();
  Cell* composed = out.mutable_cells().data();
  for (int y = 0; y < original.height(); ++y) {
    const Cell* blocks = b.blocks.data() + static_cast<std::size_t>(y / f) * b.blocks_x;
    const std::size_t row = static_cast<std::size_t>(y) * w;
    for (std::size_t x0 = 0; x0 < w; x0 += side, ++blocks) {
      const std::size_t end = std::min(w, x0 + side);
      for (std::size_t i = row + x0; i < row + end; ++i) {
        composed[i] = restored[i] ? cells[i] : *blocks;
      }
    }
  }
  return out;
}

StatusOr<std::vector<std::uint8_t>> EncodeBlockChunk(const Grid& original, const BlockCells& blocks,
                                                     const LayerIndex& layers, int tile_size,
                                                     int threads) {
  const int f = blocks.block_cells;
  if (f < kMinBlockCells || f > kMaxBlockCells || tile_size < kMinTileSize ||
      tile_size > kMaxTileSize || tile_size % f != 0) {
    return InvalidArgumentError("tile size " + std::to_string(tile_size) +
                                " is outside 16..65536 or not a multiple of the block side " +
                                std::to_string(f));
  }
  const Grid decoded = ComposeBlockCells(original, blocks);
  ByteWriter out;
  out.PutU8(static_cast<std::uint8_t>(f));
  out.PutVarint(static_cast<std::uint64_t>(tile_size));
  WriteTiles(
      TileLayout(original.width(), original.height(), tile_size), threads,
      [&](CellRect t) { return EncodeTile(decoded, blocks, layers, t); }, &out);
  return std::move(out.mutable_bytes());
}

Status DecodeBlockChunk(const std::vector<std::uint8_t>& body, const LayerIndex& layers, int width,
                        int height, CellRect window, int threads, Cell* out) {
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
  return DecodeTilesInWindow(body, layout, index, window, threads, out,
                             [&](CellRect t, const std::uint8_t* data, std::size_t size, int rows,
                                 Cell* cells, std::ptrdiff_t stride) {
                               return DecodeTile(data, size, layers, t, f, rows, cells, stride);
                             });
}

}  // namespace linemap
