// The exact 2.x encoder for maps given a row at a time (row_encoder.h).
//
// Why a block row's tiles can be coded before the rest of the map is read: the
// hints a tile is coded against (spec/format.md 6.2) are drawn from the
// items that reach it, and every item lies inside the layer block it was
// extracted from (ExtractBlockLayers checks it), so only the items of the
// block rows holding the tile's rows reach it. The file lists them in
// another order (grouped by section, walls and objects toured within each,
// OrderItemsInSections), but the hints do not depend on it: walls and
// objects are ORed into the hint bits (a segment's cells are the same in
// either direction, spec 8.1, and an outline's whatever vertex it starts
// at), and only rooms, whose chains clear the room fill of rooms drawn
// before, are drawn in order; grouping keeps the rooms of a block in the
// order they were extracted (a block lies in one section: EncodesByRows
// takes sections of whole blocks only), and rooms of two blocks share no
// cell.
#include "codec/lmap/row_encoder.h"

#include <algorithm>
#include <iterator>
#include <string>
#include <utility>

#include "codec/cells/cell_tiles.h"
#include "codec/layers/layer_hints.h"
#include "codec/layers/section_order.h"
#include "codec/lmap/chunk_coding.h"
#include "format/byte_io.h"

namespace linemap {
namespace {

int SectionSide(int width, int height, const EncodeOptions& options) {
  return LayerSectionSide(width, height, options.layer_section_cells);
}

// The map's rows read so far and still needed, each held on its own so
// that a row is freed as soon as no band or tile needs it; or the rows of a
// grid the caller holds, read in place.
class RowStore {
 public:
  RowStore(int width, int height, CellRowSource* source)
      : width_(width),
        rows_(static_cast<std::size_t>(height)),
        next_(height - 1),
        freed_from_(height),
        source_(source) {}
  explicit RowStore(const Grid* grid) : width_(grid->width()), grid_(grid) {}

  // Reads rows down to `row` (rows come top first).
  Status ReadDownTo(int row) {
    if (grid_ != nullptr) return Status::Ok();
    for (; next_ >= row; --next_) {
      std::vector<Cell>& cells = rows_[static_cast<std::size_t>(next_)];
      cells.resize(static_cast<std::size_t>(width_));
      LINEMAP_RETURN_IF_ERROR(source_->ReadRow(cells.data()));
    }
    return Status::Ok();
  }
  // Frees rows [row, height).
  void FreeFrom(int row) {
    if (grid_ != nullptr) return;
    for (; freed_from_ > std::max(row, 0); --freed_from_) {
      std::vector<Cell>().swap(rows_[static_cast<std::size_t>(freed_from_ - 1)]);
    }
  }
  // The cells of `rect` (rows read), row-major from its lowest row.
  std::vector<Cell> Cells(CellRect rect) const {
    const int w = rect.x1 - rect.x0;
    std::vector<Cell> cells(static_cast<std::size_t>(w) * (rect.y1 - rect.y0));
    for (int r = rect.y0; r < rect.y1; ++r) {
      const Cell* row = grid_ != nullptr ? grid_->cells().data() + grid_->Index(0, r)
                                         : rows_[static_cast<std::size_t>(r)].data();
      std::copy_n(row + rect.x0, w, cells.begin() + static_cast<std::ptrdiff_t>(r - rect.y0) * w);
    }
    return cells;
  }

 private:
  int width_;
  std::vector<std::vector<Cell>> rows_;
  int next_ = 0;        // the next row to read
  int freed_from_ = 0;  // rows [freed_from_, height) are freed
  CellRowSource* source_ = nullptr;
  const Grid* grid_ = nullptr;
};

// The layers of block row [y0, y1), block by block on the threads the
// options allow, appended in block order. Room ids continue past
// *last_room_id, which ends as the row's largest: unique over the map
// until NumberItemsInOrder numbers them.
StatusOr<VectorLayers> BlockRowLayers(const RowStore& rows, const MapFrame& frame,
                                      const EncodeOptions& options, int y0, int y1,
                                      std::uint32_t* last_room_id) {
  const int blocks = (frame.width + kLayerBlockCells - 1) / kLayerBlockCells;
  EncodeOptions block_options = options;
  block_options.max_threads = 1;
  std::vector<StatusOr<VectorLayers>> block_layers(static_cast<std::size_t>(blocks),
                                                   VectorLayers{});
  const int threads = options.max_threads == 1 ? 1 : kMaxBlocksAtOnce;
  ForEachIndexParallel(blocks, threads, [&](std::uint64_t k) {
    const int x0 = static_cast<int>(k) * kLayerBlockCells;
    const CellRect rect{x0, y0, std::min(x0 + kLayerBlockCells, frame.width), y1};
    Grid block(rect.x1 - rect.x0, rect.y1 - rect.y0);
    block.meta = frame.meta;
    block.mutable_cells() = rows.Cells(rect);
    block_layers[k] = ExtractBlockLayers(block, x0, y0, block_options, /*with_chains=*/false);
  });
  VectorLayers row;
  for (StatusOr<VectorLayers>& layers : block_layers) {
    if (!layers.ok()) return layers.status();
    AppendBlockLayers(std::move(*layers), &row);
  }
  const std::uint32_t offset = *last_room_id;
  for (RoomOutline& room : row.rooms) room.id += offset;
  for (FurnitureObject& object : row.furniture) {
    if (object.room_id >= 0) object.room_id += static_cast<std::int32_t>(offset);
  }
  if (!row.rooms.empty()) *last_room_id = row.rooms.back().id;
  return row;
}

// Appends `from`'s items to `to`.
void AppendItems(VectorLayers from, VectorLayers* to) {
  std::move(from.walls.begin(), from.walls.end(), std::back_inserter(to->walls));
  std::move(from.rooms.begin(), from.rooms.end(), std::back_inserter(to->rooms));
  std::move(from.furniture.begin(), from.furniture.end(), std::back_inserter(to->furniture));
}

// Codes the tiles of tile row `ty` into `tiles` (by tile index), against
// the hints of `layers`.
void CodeTileRow(const RowStore& rows, const TileLayout& layout, int ty, const VectorLayers& layers,
                 const EncodeOptions& options, std::vector<std::vector<std::uint8_t>>* tiles) {
  const LayerIndex index(layers.walls, layers.rooms, layers.furniture);
  const std::uint64_t first = static_cast<std::uint64_t>(ty) * layout.tiles_x;
  ForEachIndexParallel(layout.tiles_x, options.max_threads, [&](std::uint64_t tx) {
    const CellRect t = layout.Tile(first + tx);
    (*tiles)[first + tx] = EncodeCellTile(rows.Cells(t), index.TileHints(t), t.x1 - t.x0,
                                          t.y1 - t.y0, options.compact);
  });
}

// The CELL body (spec/format.md 6.1) of the coded tiles.
std::vector<std::uint8_t> CellBody(int tile_size,
                                   const std::vector<std::vector<std::uint8_t>>& tiles) {
  ByteWriter out;
  out.PutVarint(static_cast<std::uint64_t>(tile_size));
  for (const std::vector<std::uint8_t>& tile : tiles) out.PutVarint(tile.size());
  for (const std::vector<std::uint8_t>& tile : tiles) out.PutBytes(tile);
  return std::move(out.mutable_bytes());
}

}  // namespace

bool EncodesByRows(int width, int height, const EncodeOptions& options) {
  // Sections of whole blocks keep each block's items in one section, so
  // the file keeps a block's rooms in the order they were extracted, which
  // the hints are drawn in (see the top of this file): with sections of
  // 1000 cells willow-2010 decoded 3 cells wrong. They also make the map
  // larger than a block, whose layers are extracted block by block anyway.
  const int side = SectionSide(width, height, options);
  return options.tolerance_cells == 0 && side % kLayerBlockCells == 0 &&
         (width > side || height > side);
}

namespace {

StatusOr<std::vector<std::uint8_t>> EncodeBands(const MapFrame& frame, const EncodeOptions& options,
                                                RowStore* rows) {
  const int block_rows = (frame.height + kLayerBlockCells - 1) / kLayerBlockCells;
  const TileLayout layout(frame.width, frame.height,
                          TileSide(frame.width, frame.height, options.tile_size_cells));
  // Each block row's items in the order extracted; a tile row is coded
  // once every block row its rows meet is read (top first), against their
  // items.
  std::vector<VectorLayers> items(static_cast<std::size_t>(block_rows));
  std::vector<std::vector<std::uint8_t>> tiles(layout.count());
  int next_tile_row = layout.tiles_y - 1;
  std::uint32_t last_room_id = 0;
  LayerCounts counts;
  for (int j = block_rows - 1; j >= 0; --j) {
    const int y0 = j * kLayerBlockCells;
    const int y1 = std::min(frame.height, y0 + kLayerBlockCells);
    LINEMAP_RETURN_IF_ERROR(rows->ReadDownTo(y0));
    if (options.vector_layers) {
      VectorLayers& row = items[static_cast<std::size_t>(j)];
      LINEMAP_ASSIGN_OR_RETURN(row, BlockRowLayers(*rows, frame, options, y0, y1, &last_room_id));
      // A file the decoders' default limits refuse fails before the rest
      // of the map is coded.
      counts.Add(row);
      LINEMAP_RETURN_IF_ERROR(CheckLayerCountsWithinDefaultLimits(counts));
    }
    for (; next_tile_row >= 0 && next_tile_row * layout.tile_size >= y0; --next_tile_row) {
      const int t0 = next_tile_row * layout.tile_size;
      const int t1 = std::min(frame.height, t0 + layout.tile_size);
      // The block rows the tile row meets: one, unless its side does not
      // divide the blocks'.
      const int j0 = t0 / kLayerBlockCells;
      const int j1 = (t1 - 1) / kLayerBlockCells;
      if (j0 == j1) {
        CodeTileRow(*rows, layout, next_tile_row, items[static_cast<std::size_t>(j0)], options,
                    &tiles);
      } else {
        VectorLayers reaching;
        for (int k = j0; k <= j1; ++k) AppendItems(items[static_cast<std::size_t>(k)], &reaching);
        CodeTileRow(*rows, layout, next_tile_row, reaching, options, &tiles);
      }
      rows->FreeFrom(t0);
    }
    if (options.progress) {
      options.progress(static_cast<double>(block_rows - j) / (block_rows + 1));
    }
  }
  VectorLayers all;
  for (VectorLayers& row : items) AppendItems(std::move(row), &all);
  const int side = SectionSide(frame.width, frame.height, options);
  OrderItemsInSections(frame.width, frame.height, side, &all.walls, &all.rooms, &all.furniture);
  // Room ids from the blocks are unique but follow the reading order, top
  // first: numbered 1, 2, ... in file order.
  NumberItemsInOrder(/*renumber_rooms=*/true, &all.rooms, &all.furniture);
  return WriteV2(frame, options, all, side, /*exact=*/true, kCellChunk,
                 CellBody(layout.tile_size, tiles));
}

}  // namespace

StatusOr<std::vector<std::uint8_t>> EncodeLmapByRows(const MapFrame& frame,
                                                     const EncodeOptions& options,
                                                     CellRowSource* source) {
  RowStore rows(frame.width, frame.height, source);
  return EncodeBands(frame, options, &rows);
}

StatusOr<std::vector<std::uint8_t>> EncodeGridByRows(const Grid& grid,
                                                     const EncodeOptions& options) {
  RowStore rows(&grid);
  return EncodeBands(MapFrame{grid.width(), grid.height(), grid.meta}, options, &rows);
}

}  // namespace linemap
