#include "codec/cells/tile_hints.h"

#include <cmath>

#include "codec/cells/tile_coder.h"
#include "codec/layers/raster.h"
#include "linemap/lines.h"
#include "linemap/segmentation.h"

namespace linemap {
namespace {

CellIndex Rounded(double col, double row) {
  return CellIndex{static_cast<int>(std::lround(col)), static_cast<int>(std::lround(row))};
}

// ORs `bit` into every cell of `mask` that is set.
void MarkMask(const BinaryMask& mask, std::uint8_t bit, std::vector<std::uint8_t>* hints) {
  for (std::size_t i = 0; i < mask.bits.size(); ++i) {
    if (mask.bits[i]) (*hints)[i] |= bit;
  }
}

}  // namespace

StatusOr<std::vector<std::uint8_t>> BuildLayerHints(const Grid& grid) {
  const int w = grid.width();
  const int h = grid.height();
  std::vector<std::uint8_t> hints(grid.size(), 0);
  const auto inside = [&](int c, int r) { return c >= 0 && r >= 0 && c < w && r < h; };

  LINEMAP_ASSIGN_OR_RETURN(LineExtraction lines,
                           ExtractLines(grid, StraightWalls(LineExtractionOptions{})));
  for (const LineSegment& s : lines.segments) {
    RasterizeSegment(Rounded(s.x1, s.y1), Rounded(s.x2, s.y2), [&](int c, int r) {
      if (inside(c, r)) hints[grid.Index(c, r)] |= kHintWall;
    });
  }

  LINEMAP_ASSIGN_OR_RETURN(Segmentation seg, SegmentMap(grid));
  for (const RoomBorder& room : seg.rooms) {
    MarkMask(FillChainPolygon(room.chain, w, h), kHintRoomInside, &hints);
    for (const CellIndex& c : room.chain) {
      if (!inside(c.col, c.row)) continue;
      std::uint8_t& hint = hints[grid.Index(c.col, c.row)];
      hint = static_cast<std::uint8_t>((hint & ~kHintRoomInside) | kHintRoomBorder);
    }
  }
  for (const FurnitureBlob& blob : seg.blobs) {
    MarkMask(FillChainPolygon(blob.outline, w, h), kHintFurniture, &hints);
  }
  return hints;
}

}  // namespace linemap
