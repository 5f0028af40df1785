// The cell coder of .lmap 2.0: codes the cells of one rectangular tile of a
// trinary grid exactly, in the context of what the file's vector layers drew
// (the layer hints), so that every tile decodes on its own (region decoding,
// one thread per tile). Normative description: spec/tile_coding.md.
//
// Speed comes from skipping settled cells: a row equal to the row below it,
// or a 16-cell block equal to the block below it, costs one binary decision;
// only the remaining cells are coded one by one with a context model over
// their trinary neighbours and their layer hint.
#ifndef LINEMAP_CODEC_CELLS_TILE_CODER_H_
#define LINEMAP_CODEC_CELLS_TILE_CODER_H_

#include <cstddef>
#include <cstdint>
#include <vector>

#include "linemap/grid.h"
#include "linemap/status.h"

namespace linemap {

// A half-open rectangle of cells [x0, x1) x [y0, y1) (columns, grid rows;
// row 0 at the origin).
struct CellRect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

// What the vector layers drew, one byte per cell of the WHOLE grid
// (width*height, grid-row order), known to the decoder before any tile is
// decoded. Bits may combine.
enum LayerHintBits : std::uint8_t {
  kHintWall = 1,        // on the rasterisation of a wall polyline segment: mostly occupied
  kHintRoomInside = 2,  // strictly inside a room-border chain's fill: mostly free
  kHintRoomBorder = 4,  // a cell of a room-border chain: mostly occupied, sometimes a doorway
  kHintFurniture = 8,   // inside a furniture outline's fill: occupied, or free between legs
};

// The cell model a tile is coded with (stored in the tile's first byte; the
// decoder reads any). Figures: tools/bench_tiles on ../shared/maps.
enum class TileModel : std::uint8_t {
  // One adaptive model per context: the fast default.
  kTemplate = 0,
  // Where the template's model is unsure, the logistic mix of it and a
  // model of the nearest cells: 2.2 % smaller without hints and 5.7 %
  // smaller with them (tuning median), but ~1.55x the decode time.
  kMixed = 1,
  // As the two above, but every cell of a row that differs from the row
  // below is coded (no block flags): 5-13 % smaller on most maps, 2-5x the
  // decode time. kMixedAllCells is the smallest exact coding (tuning median
  // 0.435x PNG-9 without hints, 0.334x with; ~6 ns per cell to decode).
  kTemplateAllCells = 2,
  kMixedAllCells = 3,
  // As kTemplate (the same row, super-block and block decisions; a block
  // next to a drawn wall has flag contexts of its own), but each coded
  // cell's context is the 4 nearest cells x a class of the layers around it
  // (hint changes from W and from N, a wall next to it): with the layers a
  // 2.x file stores 3.8 % smaller than kTemplate (tuning median; 9.7 % with
  // BuildLayerHints), ~4 % more decode time. The CELL encoder writes it in
  // every tile where it is the smaller of the two.
  kLayerContext = 4,
  // Models 5-11: the layer context without some of its class terms (ids
  // 4 + the LayerTerm bits dropped; LayerContextWithout). The encoder keeps
  // whichever codes a tile smallest: the terms that pay differ by map.
  kLayerContextLast = 11,
  // Every cell of a row that differs from the row below is coded (as model
  // 3), "equals W" by the mix of the 8-cell template, the layer context,
  // the nearest cells and a 10-cell template where the 8-cell one is
  // unsure: the smallest coding, with layers or without, about 7x the
  // decode time of kTemplate. Written by EncodeOptions::compact.
  kMixedLayerAllCells = 12,
};

// The layer context's class terms a tile may drop (spec/tile_coding.md 5.2).
enum LayerTerm : unsigned {
  kLayerTermWestChange = 1,   // the hint differs from W's
  kLayerTermNorthChange = 2,  // the hint differs from N's
  kLayerTermWallNear = 4,     // no wall on or next to the cell
};

// The model of the layer context without the terms `dropped` (LayerTerm
// bits): kLayerContext for none.
constexpr TileModel LayerContextWithout(unsigned dropped) {
  return static_cast<TileModel>(static_cast<unsigned>(TileModel::kLayerContext) + (dropped & 7u));
}

// Every call below allocates about 0.2 MB of model state (kLayerContext
// 42 kB, kMixedLayerAllCells 0.6 MB) and three rows of the tile, and shares nothing with other
// calls: tiles may be coded on several threads at once.

// Codes the cells of `cells` (width*height Cell values, grid-row order)
// inside `tile` exactly. Reads cells and hints only inside `tile`
// (spec/tile_coding.md section 1), so every tile decodes on its own.
// Deterministic. `tile` must lie inside the grid (an empty tile gives no
// bytes); `hints` may be null (= all zero).
std::vector<std::uint8_t> EncodeTileCells(const Cell* cells, const std::uint8_t* hints, int width,
                                          int height, CellRect tile);
// The same with a chosen model (the one above uses TileModel::kTemplate).
std::vector<std::uint8_t> EncodeTileCells(const Cell* cells, const std::uint8_t* hints, int width,
                                          int height, CellRect tile, TileModel model);

// Writes the tile's cells into canvas (width*height). Reads only `hints`
// (null = all zero) and the tile's own `size` bytes. Malformed or truncated
// data, or a tile outside the grid, gives a kCorrupt / kInvalidArgument
// error; cells of the tile may then hold partial results.
Status DecodeTileCells(const std::uint8_t* data, std::size_t size, const std::uint8_t* hints,
                       int width, int height, CellRect tile, Cell* canvas);

// The same for a tile held in buffers of its own, e.g. a band of rows of a
// map too large to hold whole: row r of the tile (grid row y0 + r) starts at
// cells + r * cell_stride, hints + r * hint_stride (hints null = all zero)
// and canvas + r * canvas_stride. Gives and reads the same bytes as the
// whole-grid calls for the same tile. The decoders write only the tile's
// first `rows_wanted` rows (1..tile_height; 0 for an empty tile), as a
// full decode would: a window that ends inside a tile stops there, and its
// buffers need only those rows and the one after (whose hints are read). A
// tile decoded in part is not checked for its end (its chunk's CRC checks
// the bytes).
std::vector<std::uint8_t> EncodeTileRows(const Cell* cells, std::ptrdiff_t cell_stride,
                                         const std::uint8_t* hints, std::ptrdiff_t hint_stride,
                                         int tile_width, int tile_height,
                                         TileModel model = TileModel::kTemplate);
Status DecodeTileRows(const std::uint8_t* data, std::size_t size, const std::uint8_t* hints,
                      std::ptrdiff_t hint_stride, int tile_width, int tile_height, int rows_wanted,
                      Cell* canvas, std::ptrdiff_t canvas_stride);

// The same with the hints already drawn into `canvas` (row r of the
// tile's hints at canvas + r * canvas_stride, as bytes): each row's hints
// are read before its cells are written over them, so a tile needs no
// buffer of hints of its own (a megabyte for a 1024-cell tile, whose pages
// cost more to fault in than drawing the hints; DecodeCellChunk keeps one
// per thread for tiles of up to 2^22 cells on canvases whose rows would
// share cache sets). On an error
// every cell of the rows wanted (and of the row after them) is unknown.
Status DecodeTileRowsOverHints(const std::uint8_t* data, std::size_t size, int tile_width,
                               int tile_height, int rows_wanted, Cell* canvas,
                               std::ptrdiff_t canvas_stride);

}  // namespace linemap

#endif  // LINEMAP_CODEC_CELLS_TILE_CODER_H_
