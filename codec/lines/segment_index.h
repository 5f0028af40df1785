// Exact nearest-segment distance queries over many segments: segments are
// bucketed into square tiles, and a query scans rings of tiles outwards until
// no unscanned tile can hold a closer segment. Used by MeasureLineFidelity
// (Eq. 5 over every edge cell), by linemap's bound check and by the wall
// cover (whether a wall lies within a cell of each edge cell, AnyWithin),
// where a brute force over all pairs would be quadratic.
#ifndef LINEMAP_CODEC_LINES_SEGMENT_INDEX_H_
#define LINEMAP_CODEC_LINES_SEGMENT_INDEX_H_

#include <cstdint>
#include <utility>
#include <vector>

#include "linemap/lines.h"

namespace linemap::lines_internal {

class SegmentIndex {
 public:
  // `width` x `height` is the area the queries come from (cell units);
  // segments may extend beyond it. tile_cells: tile side in cells (16 is a
  // good default for maps of 5 cm cells).
  SegmentIndex(const std::vector<LineSegment>* segments, int width, int height,
               int tile_cells = 16);

  // Distance from (x, y) to the nearest segment; +infinity without segments.
  // Segments with skip[id] != 0 are ignored when `skip` is given; the id of
  // the nearest one goes to *nearest_id when given (unchanged if none).
  double NearestDistance(double x, double y, const std::vector<std::uint8_t>* skip = nullptr,
                         std::uint32_t* nearest_id = nullptr);

  // Whether some segment lies within `radius` of (x, y): the same answer as
  // NearestDistance(x, y) <= radius, from the tiles that square of side
  // 2 radius meets, stopping at the first segment found.
  bool AnyWithin(double x, double y, double radius) const;

 private:
  // Appends (tile, id) for every tile segment s may touch.
  void AddToTiles(std::uint32_t id, const LineSegment& s,
                  std::vector<std::pair<std::uint32_t, std::uint32_t>>* entries);
  int TileOf(double coordinate, int tiles) const;
  // Distance from (x, y), in tile (qx, qy), to the nearest point outside the
  // square of tiles within `ring` of that tile (infinity past the map's border
  // tiles, which own everything clamped into them).
  double DistanceOutside(double x, double y, int qx, int qy, int ring) const;

  const std::vector<LineSegment>* segments_;
  int tile_ = 16;
  int tiles_x_ = 1;
  int tiles_y_ = 1;
  // Tile t's segment ids, in increasing order: bucket_ids_[bucket_begin_[t],
  // bucket_begin_[t + 1]).
  std::vector<std::uint32_t> bucket_begin_;  // tiles_x_ * tiles_y_ + 1
  std::vector<std::uint32_t> bucket_ids_;
  std::vector<std::uint32_t> seen_stamp_;  // per segment: last query that saw it
  std::uint32_t stamp_ = 0;
};

}  // namespace linemap::lines_internal

#endif  // LINEMAP_CODEC_LINES_SEGMENT_INDEX_H_
