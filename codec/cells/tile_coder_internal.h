// What the tile coder's two source files share: a tile's rows as the scan
// reads and writes them (TileRows), and the coding of one tile's bytes
// (tile_scan.cc), which the entry points of tile_coder.h (tile_coder.cc)
// call for a tile of the whole grid or a tile in buffers of its own.
#ifndef LINEMAP_CODEC_CELLS_TILE_CODER_INTERNAL_H_
#define LINEMAP_CODEC_CELLS_TILE_CODER_INTERNAL_H_

#include <cstddef>
#include <cstdint>
#include <vector>

#include "codec/cells/tile_coder.h"
#include "linemap/grid.h"
#include "linemap/status.h"

namespace linemap::tile_coder_internal {

// The addends of the layer class's terms (LayerClassesOf): a tile of model
// 4 + d drops the terms of the LayerTerm bits of d (their addend is 0).
struct LayerTerms {
  unsigned west_change = 5, north_change = 10, far_from_walls = 20;
};

// A tile's rows as the scan reads and writes them (the encoder reads
// `cells`, the decoder writes `canvas`; `hints` null = all zero).
struct TileRows {
  int width = 0, height = 0;
  const Cell* cells = nullptr;
  std::ptrdiff_t cell_stride = 0;
  Cell* canvas = nullptr;
  std::ptrdiff_t canvas_stride = 0;
  // Decoder: `hints` may be the canvas's own rows (DecodeTileRowsOverHints):
  // the scan writes row r's cells only once row r + 1 has read row r's
  // hints, and reads no hints of the rows below that.
  const std::uint8_t* hints = nullptr;
  std::ptrdiff_t hint_stride = 0;
  LayerTerms layer_terms;  // of the layer context (models 4-11)
  // Decoder: the rows to decode, from the tile's first (1..height; a
  // window that ends inside the tile needs no more; DecodeTile refuses
  // others). The scan is the same up to there, so those rows decode
  // exactly as in a full decode.
  int rows_wanted = -1;
};

// Codes the tile's cells and the end marker; returns the tile's bytes.
std::vector<std::uint8_t> EncodeTile(const TileRows& rows, TileModel model);
// Decodes the tile's bytes into rows.canvas (its first rows.rows_wanted
// rows); checks the end marker when the whole tile is decoded.
Status DecodeTile(const std::uint8_t* data, std::size_t size, const TileRows& rows);

}  // namespace linemap::tile_coder_internal

#endif  // LINEMAP_CODEC_CELLS_TILE_CODER_INTERNAL_H_
