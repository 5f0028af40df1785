// TEMPORARY stand-in for the tile coder (replaced by the coder branch).
#ifndef LINEMAP_CODEC_CODEC_TILE_CODER_H_
#define LINEMAP_CODEC_CODEC_TILE_CODER_H_

#include <cstddef>
#include <cstdint>
#include <vector>

#include "linemap/grid.h"
#include "linemap/status.h"

namespace linemap {

struct CellRect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

enum LayerHintBits : std::uint8_t {
  kHintWall = 1,
  kHintRoomInside = 2,
  kHintRoomBorder = 4,
  kHintFurniture = 8,
};

std::vector<std::uint8_t> EncodeTileCells(const Cell* cells, const std::uint8_t* hints, int width,
                                          int height, CellRect tile);
Status DecodeTileCells(const std::uint8_t* data, std::size_t size, const std::uint8_t* hints,
                       int width, int height, CellRect tile, Cell* canvas);

}  // namespace linemap

#endif  // LINEMAP_CODEC_CODEC_TILE_CODER_H_
