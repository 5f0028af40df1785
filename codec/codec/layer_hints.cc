// Hint bytes of a tile (spec/format.md section 6.2).
#include "codec/codec/layer_hints.h"

#include <algorithm>

#include "codec/codec/raster.h"

namespace linemap {
namespace {

BoundingBox BoxOf(const std::vector<CellIndex>& cells) {
  BoundingBox box{cells[0].col, cells[0].row, cells[0].col, cells[0].row};
  for (const CellIndex& c : cells) {
    box.min_col = std::min(box.min_col, c.col);
    box.max_col = std::max(box.max_col, c.col);
    box.min_row = std::min(box.min_row, c.row);
    box.max_row = std::max(box.max_row, c.row);
  }
  return box;
}

bool Overlaps(const BoundingBox& box, CellRect t) {
  return box.max_col >= t.x0 && box.min_col < t.x1 && box.max_row >= t.y0 && box.min_row < t.y1;
}

// The row crossings of a closed chain as FillChain (raster.h) defines them:
// each step p -> q between rows r and r + 1 crosses at the column of its end
// on row r.
std::vector<std::pair<int, int>> Crossings(const std::vector<CellIndex>& chain) {
  std::vector<std::pair<int, int>> crossings;
  const std::size_t n = chain.size();
  for (std::size_t i = 0; i < n; ++i) {
    const CellIndex p = chain[i];
    const CellIndex q = chain[(i + 1) % n];
    if (std::abs(p.row - q.row) != 1) continue;
    const int r = std::min(p.row, q.row);
    crossings.emplace_back(r, p.row == r ? p.col : q.col);
  }
  std::sort(crossings.begin(), crossings.end());
  return crossings;
}

}  // namespace

LayerIndex::LayerIndex(const std::vector<WallPolyline>& walls,
                       const std::vector<RoomOutline>& rooms,
                       const std::vector<FurnitureObject>& furniture) {
  for (const WallPolyline& wall : walls) {
    for (std::size_t i = 1; i < wall.points.size(); ++i) {
      const CellIndex a = wall.points[i - 1], b = wall.points[i];
      segments_.push_back({a, b, BoxOf({a, b})});
    }
  }
  for (const RoomOutline& room : rooms) {
    AddOutline(room.polygon, kHintRoomInside, kHintRoomBorder, kHintRoomInside);
  }
  for (const FurnitureObject& object : furniture) {
    AddOutline(object.polygon, kHintFurniture, kHintFurniture, 0);
  }
}

void LayerIndex::AddOutline(const std::vector<CellIndex>& polygon, std::uint8_t fill_bits,
                            std::uint8_t chain_bits, std::uint8_t clear_on_chain) {
  if (polygon.empty()) return;
  outlines_.push_back({&polygon, BoxOf(polygon), fill_bits, chain_bits, clear_on_chain});
}

std::vector<std::uint8_t> LayerIndex::TileHints(CellRect t) const {
  const int tw = t.x1 - t.x0;
  const int th = t.y1 - t.y0;
  std::vector<std::uint8_t> hints(static_cast<std::size_t>(tw) * th, 0);
  const auto at = [&](int c, int r) -> std::uint8_t& {
    return hints[static_cast<std::size_t>(r - t.y0) * tw + (c - t.x0)];
  };
  const auto in = [&](int c, int r) { return c >= t.x0 && c < t.x1 && r >= t.y0 && r < t.y1; };
  for (const Outline& outline : outlines_) {
    if (!Overlaps(outline.box, t)) continue;
    const std::vector<CellIndex> chain = ChainOfPolygon(*outline.polygon);
    const std::vector<std::pair<int, int>> crossings = Crossings(chain);
    // Fill: on each row, the cells in [x0, x1), [x2, x3), ... of its
    // sorted crossings, clipped to the tile.
    auto it = std::lower_bound(crossings.begin(), crossings.end(), std::make_pair(t.y0, -1));
    while (it != crossings.end() && it->first < t.y1) {
      const int row = it->first;
      auto end = it;
      while (end != crossings.end() && end->first == row) ++end;
      for (auto p = it; p + 1 < end; p += 2) {
        const int lo = std::max(p->second, t.x0);
        const int hi = std::min((p + 1)->second, t.x1);
        for (int c = lo; c < hi; ++c) at(c, row) |= outline.fill_bits;
      }
      it = end;
    }
    for (const CellIndex& c : chain) {
      if (!in(c.col, c.row)) continue;
      at(c.col, c.row) = static_cast<std::uint8_t>((at(c.col, c.row) & ~outline.clear_on_chain) |
                                                   outline.chain_bits);
    }
  }
  for (const Segment& s : segments_) {
    if (!Overlaps(s.box, t)) continue;
    RasterizeSegment(s.a, s.b, [&](int c, int r) {
      if (in(c, r)) at(c, r) |= kHintWall;
    });
  }
  return hints;
}

}  // namespace linemap
