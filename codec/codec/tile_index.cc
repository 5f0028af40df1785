// The tile index of CELL and BLKS (spec/format.md 6.1).
#include "codec/codec/tile_index.h"

namespace linemap {

StatusOr<TileIndex> ReadTileIndex(const std::vector<std::uint8_t>& body, const TileLayout& layout,
                                  ByteCursor* cursor) {
  if (layout.count() > cursor->remaining()) return CorruptError("tile index past the chunk's end");
  TileIndex index;
  index.offsets.assign(layout.count() + 1, 0);
  for (std::uint64_t i = 0; i < layout.count(); ++i) {
    LINEMAP_ASSIGN_OR_RETURN(std::uint64_t len, cursor->ReadVarint("tile length"));
    if (len > body.size()) return CorruptError("tile length past the chunk's end");
    index.offsets[i + 1] = index.offsets[i] + len;
  }
  index.base = cursor->position();
  if (index.offsets.back() != body.size() - index.base) {
    return CorruptError("tile lengths do not add up to the chunk's size");
  }
  return index;
}

std::vector<std::uint64_t> TilesMeeting(const TileLayout& layout, CellRect window) {
  std::vector<std::uint64_t> wanted;
  for (std::uint64_t i = 0; i < layout.count(); ++i) {
    const CellRect t = layout.Tile(i);
    if (t.x1 > window.x0 && t.x0 < window.x1 && t.y1 > window.y0 && t.y0 < window.y1) {
      wanted.push_back(i);
    }
  }
  return wanted;
}

}  // namespace linemap
