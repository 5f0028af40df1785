// What the vector layers of a 2.0 file draw into one tile, as the hint
// bytes the tile coder conditions on (spec/format.md section 6.2). Encoder
// and decoder build the same hints from the same layers, tile by tile, so a
// tile decodes without the rest of the map.
#ifndef LINEMAP_CODEC_CODEC_LAYER_HINTS_H_
#define LINEMAP_CODEC_CODEC_LAYER_HINTS_H_

#include <cstdint>
#include <utility>
#include <vector>

#include "codec/codec/tile_coder.h"
#include "linemap/cells.h"
#include "linemap/vector_layers.h"

namespace linemap {

// The layers with what each tile needs to find them quickly: segment and
// polygon boxes. A polygon's chain (ChainOfPolygon) and its row crossings
// are made for each tile it meets and dropped again, so the index holds no
// chain cells: on a 282-Mcell map with 20,000 rooms those were 180 MB.
class LayerIndex {
 public:
  LayerIndex(const std::vector<WallPolyline>& walls, const std::vector<RoomOutline>& rooms,
             const std::vector<FurnitureObject>& furniture);

  // The hint bytes of `tile`, (x1 - x0) x (y1 - y0), row-major from y0.
  std::vector<std::uint8_t> TileHints(CellRect tile) const;
  bool empty() const { return segments_.empty() && outlines_.empty(); }

 private:
  struct Segment {
    CellIndex a, b;
    BoundingBox box;
  };
  struct Outline {
    const std::vector<CellIndex>* polygon;
    BoundingBox box;              // of the polygon's vertices, which holds its chain
    std::uint8_t fill_bits;       // set inside the fill
    std::uint8_t chain_bits;      // set on the chain's cells
    std::uint8_t clear_on_chain;  // cleared on the chain's cells
  };
  void AddOutline(const std::vector<CellIndex>& polygon, std::uint8_t fill_bits,
                  std::uint8_t chain_bits, std::uint8_t clear_on_chain);

  std::vector<Segment> segments_;
  std::vector<Outline> outlines_;  // rooms first, then furniture (drawing order)
};

}  // namespace linemap

#endif  // LINEMAP_CODEC_CODEC_LAYER_HINTS_H_
