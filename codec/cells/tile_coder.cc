// The tile coder's entry points (tile_coder.h): a tile of the whole grid,
// or a tile held in buffers of its own (a band of a map too large to hold
// whole), checked and described as the rows the scan reads and writes
// (TileRows). The scan and a tile's bytes are in tile_scan.cc, with its
// contexts (tile_contexts.h) and per-cell runs (tile_cell_runs.h).
#include "codec/cells/tile_coder.h"

#include <algorithm>
#include <string>
#include <vector>

#include "codec/cells/tile_coder_internal.h"

namespace linemap {
namespace {

using tile_coder_internal::DecodeTile;
using tile_coder_internal::EncodeTile;
using tile_coder_internal::TileRows;

bool TileInside(CellRect t, int width, int height) {
  return width >= 0 && height >= 0 && t.x0 >= 0 && t.y0 >= 0 && t.x0 <= t.x1 && t.y0 <= t.y1 &&
         t.x1 <= width && t.y1 <= height;
}

// The rows of `tile` inside a width-wide grid.
TileRows GridTile(int width, CellRect tile, const std::uint8_t* hints) {
  TileRows rows;
  rows.width = tile.x1 - tile.x0;
  rows.height = tile.y1 - tile.y0;
  const std::size_t origin = static_cast<std::size_t>(tile.y0) * width + tile.x0;
  if (hints != nullptr) rows.hints = hints + origin;
  rows.hint_stride = rows.cell_stride = rows.canvas_stride = width;
  rows.rows_wanted = rows.height;
  return rows;
}

}  // namespace

std::vector<std::uint8_t> EncodeTileCells(const Cell* cells, const std::uint8_t* hints, int width,
                                          int height, CellRect tile) {
  return EncodeTileCells(cells, hints, width, height, tile, TileModel::kTemplate);
}

std::vector<std::uint8_t> EncodeTileCells(const Cell* cells, const std::uint8_t* hints, int width,
                                          int height, CellRect tile, TileModel model) {
  if (!TileInside(tile, width, height) || tile.x0 == tile.x1 || tile.y0 == tile.y1) return {};
  TileRows rows = GridTile(width, tile, hints);
  rows.cells = cells + (static_cast<std::size_t>(tile.y0) * width + tile.x0);
  return EncodeTile(rows, model);
}

Status DecodeTileCells(const std::uint8_t* data, std::size_t size, const std::uint8_t* hints,
                       int width, int height, CellRect tile, Cell* canvas) {
  if (!TileInside(tile, width, height)) {
    return InvalidArgumentError("tile [" + std::to_string(tile.x0) + ", " +
                                std::to_string(tile.x1) + ") x [" + std::to_string(tile.y0) + ", " +
                                std::to_string(tile.y1) + ") lies outside the " +
                                std::to_string(width) + " x " + std::to_string(height) + " grid");
  }
  TileRows rows = GridTile(width, tile, hints);
  rows.canvas = canvas + (static_cast<std::size_t>(tile.y0) * width + tile.x0);
  return DecodeTile(data, size, rows);
}

std::vector<std::uint8_t> EncodeTileRows(const Cell* cells, std::ptrdiff_t cell_stride,
                                         const std::uint8_t* hints, std::ptrdiff_t hint_stride,
                                         int tile_width, int tile_height, TileModel model) {
  TileRows rows;
  rows.width = tile_width;
  rows.height = tile_height;
  rows.cells = cells;
  rows.cell_stride = cell_stride;
  rows.hints = hints;
  rows.hint_stride = hint_stride;
  return EncodeTile(rows, model);
}

namespace {

// The rows a decode writes into `canvas`, reading `hints`; refuses a
// negative size and rows wanted outside 1..tile_height (0 for an empty
// tile).
StatusOr<TileRows> CanvasRows(int tile_width, int tile_height, int rows_wanted, Cell* canvas,
                              std::ptrdiff_t canvas_stride, const std::uint8_t* hints,
                              std::ptrdiff_t hint_stride) {
  if (tile_width < 0 || tile_height < 0) {
    return InvalidArgumentError("tile of " + std::to_string(tile_width) + " x " +
                                std::to_string(tile_height) + " cells");
  }
  if (rows_wanted < std::min(tile_height, 1) || rows_wanted > tile_height) {
    return InvalidArgumentError("rows wanted " + std::to_string(rows_wanted) + " of a tile of " +
                                std::to_string(tile_height));
  }
  TileRows rows;
  rows.width = tile_width;
  rows.height = tile_height;
  rows.canvas = canvas;
  rows.canvas_stride = canvas_stride;
  rows.hints = hints;
  rows.hint_stride = hint_stride;
  rows.rows_wanted = rows_wanted;
  return rows;
}

}  // namespace

Status DecodeTileRows(const std::uint8_t* data, std::size_t size, const std::uint8_t* hints,
                      std::ptrdiff_t hint_stride, int tile_width, int tile_height, int rows_wanted,
                      Cell* canvas, std::ptrdiff_t canvas_stride) {
  LINEMAP_ASSIGN_OR_RETURN(TileRows rows, CanvasRows(tile_width, tile_height, rows_wanted, canvas,
                                                     canvas_stride, hints, hint_stride));
  return DecodeTile(data, size, rows);
}

Status DecodeTileRowsOverHints(const std::uint8_t* data, std::size_t size, int tile_width,
                               int tile_height, int rows_wanted, Cell* canvas,
                               std::ptrdiff_t canvas_stride) {
  LINEMAP_ASSIGN_OR_RETURN(
      TileRows rows, CanvasRows(tile_width, tile_height, rows_wanted, canvas, canvas_stride,
                                reinterpret_cast<const std::uint8_t*>(canvas), canvas_stride));
  const Status status = DecodeTile(data, size, rows);
  if (!status.ok()) {
    // Rows not reached still hold hints, which are no cells: the rows
    // wanted and the one after them, whose hints were read.
    for (int r = 0; r < std::min(tile_height, rows_wanted + 1); ++r) {
      std::fill_n(canvas + r * canvas_stride, tile_width, Cell::kUnknown);
    }
  }
  return status;
}

}  // namespace linemap
