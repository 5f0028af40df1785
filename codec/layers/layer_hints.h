// What the vector layers of a 2.0 file draw into one tile, as the hint
// bytes the tile coder conditions on (spec/format.md section 6.2). Encoder
// and decoder build the same hints from the same layers, tile by tile, so a
// tile decodes without the rest of the map.
#ifndef LINEMAP_CODEC_LAYERS_LAYER_HINTS_H_
#define LINEMAP_CODEC_LAYERS_LAYER_HINTS_H_

#include <cstddef>
#include <cstdint>
#include <mutex>
#include <utility>
#include <vector>

#include "codec/cells/tile_coder.h"
#include "linemap/cells.h"
#include "linemap/vector_layers.h"

namespace linemap {

// The layers with what each tile needs to find them quickly: segment and
// polygon boxes, and a coarse grid of buckets listing the items whose box
// meets each bucket. Hints are drawn from the polygons' edges directly: a
// tile reads only the edges of the polygons that meet it and, of each edge,
// only the cells and row crossings inside the tile's rows, so no polygon's
// chain (ChainOfPolygon) is ever made (on a 282-Mcell map with 20,000
// rooms, remaking the chains per tile was half the decode time).
//
// The index points into `walls`, `rooms` and `furniture`, which must
// outlive it.
class LayerIndex {
 public:
  LayerIndex(const std::vector<WallPolyline>& walls, const std::vector<RoomOutline>& rooms,
             const std::vector<FurnitureObject>& furniture);

  // The hint bytes of `tile`, (x1 - x0) x (y1 - y0), row-major from y0.
  std::vector<std::uint8_t> TileHints(CellRect tile) const;
  // The same into `out` (that many bytes, row r of the tile at
  // out + r * stride), which the call clears first.
  void DrawTileHints(CellRect tile, std::uint8_t* out, std::ptrdiff_t stride) const;
  bool empty() const { return segments_.empty() && outlines_.empty(); }

 private:
  // A wall segment: its two ends, consecutive points of a wall (8 bytes
  // a segment rather than a copy of both ends and a box: 312,896 segments
  // on the 282-Mcell map).
  struct Segment {
    const CellIndex* ends;
    CellIndex a() const { return ends[0]; }
    CellIndex b() const { return ends[1]; }
    BoundingBox box() const;
  };
  struct Outline {
    const std::vector<CellIndex>* polygon;
    BoundingBox box_;  // of the polygon's vertices, which holds its chain
    const BoundingBox& box() const { return box_; }
    std::uint8_t fill_bits;       // set inside the fill
    std::uint8_t chain_bits;      // set on the chain's cells
    std::uint8_t clear_on_chain;  // cleared on the chain's cells
  };
  // Items (segment or outline numbers) whose box meets each bucket, as one
  // array with offsets (bucket b's items are items[starts[b], starts[b+1]),
  // increasing), and the items too wide to list per bucket.
  struct Buckets {
    int cols = 0, rows = 0;
    std::vector<std::uint32_t> starts;
    std::vector<std::uint32_t> items;
    std::vector<std::uint32_t> wide;
  };
  void AddOutline(const std::vector<CellIndex>& polygon, std::uint8_t fill_bits,
                  std::uint8_t chain_bits, std::uint8_t clear_on_chain);
  template <typename Item>
  static Buckets MakeBuckets(const std::vector<Item>& list);
  // The items of `buckets` whose bucket meets `tile`, increasing, each once.
  static std::vector<std::uint32_t> ItemsNear(const Buckets& buckets, CellRect tile);
  // Buffers one tile's outlines reuse.
  struct Scratch {
    std::vector<std::uint8_t> flip;
    std::vector<std::pair<int, int>> crossings;
    std::vector<std::uint32_t> starts, next;
    std::vector<int> cols;
  };
  static void DrawOutline(const Outline& outline, CellRect tile, std::uint8_t* out,
                          std::ptrdiff_t stride, Scratch* scratch);

  // Calls draw(i) for each item i of `list` whose box overlaps `tile`, in
  // increasing order (the drawing order); `buckets` is read only when the
  // tile does not cover every item.
  template <typename Item, typename Draw>
  void ForItemsMeeting(const std::vector<Item>& list, const Buckets& buckets, CellRect tile,
                       Draw&& draw) const;
  bool Covers(CellRect tile) const;

  std::vector<Segment> segments_;
  std::vector<Outline> outlines_;  // rooms first, then furniture (drawing order)
  // The box around every item's box (none: {0, 0, -1, -1}).
  BoundingBox extent_{0, 0, -1, -1};
  // The buckets are made by the first tile that does not cover `extent_`,
  // once (tiles may be drawn from several threads): a tile that covers it
  // looks at every item, and a map of one tile (18 of the 25 maps of
  // ../shared/maps) never needs them; making them and looking items up in
  // them was 2.5 % of the decode time of the median maps.
  mutable std::once_flag buckets_once_;
  mutable Buckets segment_buckets_;
  mutable Buckets outline_buckets_;
};

}  // namespace linemap

#endif  // LINEMAP_CODEC_LAYERS_LAYER_HINTS_H_
