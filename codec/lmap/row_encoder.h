// The exact 2.x encoder for maps given a row at a time, top row first (as a
// PGM or PNG stores them), which never holds the whole grid: the map is
// read a row of layer blocks at a time (2048 rows); each block row's layers
// are extracted block by block, and the tiles whose rows the read block
// rows cover are coded at once; the layers are ordered by section at the
// end. What it holds is a block row of cells (or a tile row, with tiles
// taller than a block), the tiles' coded bytes and the layers.
//
// The file is the one EncodeLmap writes for the same grid: EncodeLmap codes
// every map that EncodesByRows() accepts through this encoder.
#ifndef LINEMAP_CODEC_LMAP_ROW_ENCODER_H_
#define LINEMAP_CODEC_LMAP_ROW_ENCODER_H_

#include <cstdint>
#include <vector>

#include "codec/lmap/v2_file.h"
#include "linemap/codec.h"
#include "linemap/grid.h"
#include "linemap/status.h"

namespace linemap {

// The rows of a map, grid row height - 1 first (image row 0).
class CellRowSource {
 public:
  virtual ~CellRowSource() = default;
  // Fills `cells` (the map's width) with the next row.
  virtual Status ReadRow(Cell* cells) = 0;
};

// Whether EncodeLmapByRows codes a width x height map with `options`: an
// exact 2.x file (tolerance 0) of a map of more than one layer section
// (more than 4096 cells a side with the default sections). Other files are
// coded from the whole grid: a tolerance's guarantees are checked on the
// whole map, and the layers of a map of one section are ordered over the
// whole map.
bool EncodesByRows(int width, int height, const EncodeOptions& options);

// The file of the map `frame` whose rows `source` gives; `options` as
// checked by EncodeLmap and accepted by EncodesByRows.
StatusOr<std::vector<std::uint8_t>> EncodeLmapByRows(const MapFrame& frame,
                                                     const EncodeOptions& options,
                                                     CellRowSource* source);
// The same from a grid in memory, read in place.
StatusOr<std::vector<std::uint8_t>> EncodeGridByRows(const Grid& grid,
                                                     const EncodeOptions& options);

}  // namespace linemap

#endif  // LINEMAP_CODEC_LMAP_ROW_ENCODER_H_
