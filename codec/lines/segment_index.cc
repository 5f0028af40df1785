#include "codec/lines/segment_index.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "codec/lines/line_fit.h"

namespace linemap::lines_internal {

SegmentIndex::SegmentIndex(const std::vector<LineSegment>* segments, int width, int height,
                           int tile_cells)
    : segments_(segments), tile_(std::max(1, tile_cells)) {
  tiles_x_ = std::max(1, (width + tile_ - 1) / tile_);
  tiles_y_ = std::max(1, (height + tile_ - 1) / tile_);
  seen_stamp_.assign(segments->size(), 0);
  // (tile, id) pairs in id order, then a stable counting sort by tile: one
  // array for all buckets instead of a vector per tile.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> entries;
  entries.reserve(2 * segments->size());
  for (std::size_t id = 0; id < segments->size(); ++id) {
    AddToTiles(static_cast<std::uint32_t>(id), (*segments)[id], &entries);
  }
  const std::size_t tiles = static_cast<std::size_t>(tiles_x_) * tiles_y_;
  bucket_begin_.assign(tiles + 1, 0);
  for (const auto& [tile, id] : entries) ++bucket_begin_[tile + 1];
  for (std::size_t t = 0; t < tiles; ++t) bucket_begin_[t + 1] += bucket_begin_[t];
  bucket_ids_.resize(entries.size());
  std::vector<std::uint32_t> fill(bucket_begin_.begin(), bucket_begin_.end() - 1);
  for (const auto& [tile, id] : entries) bucket_ids_[fill[tile]++] = id;
}

// Tile of a coordinate in cell units; cell c covers [c-0.5, c+0.5), so tile
// t covers cells [t*tile, (t+1)*tile). Coordinates off the area are clamped
// to the border tiles, which keeps the ring bound valid (see NearestDistance).
int SegmentIndex::TileOf(double coordinate, int tiles) const {
  const double t = std::floor((coordinate + 0.5) / tile_);
  return static_cast<int>(std::clamp(t, 0.0, static_cast<double>(tiles - 1)));
}

// A segment goes into every tile whose square it may touch: the tiles of its
// bounding box whose centre lies within half a tile diagonal of it.
void SegmentIndex::AddToTiles(std::uint32_t id, const LineSegment& s,
                              std::vector<std::pair<std::uint32_t, std::uint32_t>>* entries) {
  const int tx0 = TileOf(std::min(s.x1, s.x2), tiles_x_);
  const int tx1 = TileOf(std::max(s.x1, s.x2), tiles_x_);
  const int ty0 = TileOf(std::min(s.y1, s.y2), tiles_y_);
  const int ty1 = TileOf(std::max(s.y1, s.y2), tiles_y_);
  const double half_diagonal = tile_ * std::numbers::sqrt2 / 2;
  for (int ty = ty0; ty <= ty1; ++ty) {
    for (int tx = tx0; tx <= tx1; ++tx) {
      const double cx = (tx + 0.5) * tile_ - 0.5;
      const double cy = (ty + 0.5) * tile_ - 0.5;
      // Border tiles also own everything clamped into them.
      const bool border = tx == 0 || ty == 0 || tx == tiles_x_ - 1 || ty == tiles_y_ - 1;
      if (border || PointSegmentDistance(cx, cy, s) <= half_diagonal + 1e-9) {
        entries->push_back({static_cast<std::uint32_t>(ty) * tiles_x_ + tx, id});
      }
    }
  }
}

double SegmentIndex::DistanceOutside(double x, double y, int qx, int qy, int ring) const {
  constexpr double kFar = std::numeric_limits<double>::infinity();
  const double left = qx - ring > 0 ? x - ((qx - ring) * tile_ - 0.5) : kFar;
  const double right = qx + ring < tiles_x_ - 1 ? (qx + ring + 1) * tile_ - 0.5 - x : kFar;
  const double top = qy - ring > 0 ? y - ((qy - ring) * tile_ - 0.5) : kFar;
  const double bottom = qy + ring < tiles_y_ - 1 ? (qy + ring + 1) * tile_ - 0.5 - y : kFar;
  return std::min(std::min(left, right), std::min(top, bottom));
}

double SegmentIndex::NearestDistance(double x, double y, const std::vector<std::uint8_t>* skip,
                                     std::uint32_t* nearest_id) {
  double best = std::numeric_limits<double>::infinity();
  if (segments_->empty()) return best;
  if (++stamp_ == 0) {  // wrapped: reset the stamps
    std::fill(seen_stamp_.begin(), seen_stamp_.end(), 0);
    stamp_ = 1;
  }
  const int qx = TileOf(x, tiles_x_);
  const int qy = TileOf(y, tiles_y_);
  const int max_ring = std::max(tiles_x_, tiles_y_);
  for (int ring = 0; ring <= max_ring; ++ring) {
    for (int ty = qy - ring; ty <= qy + ring; ++ty) {
      if (ty < 0 || ty >= tiles_y_) continue;
      const bool full_row = ty == qy - ring || ty == qy + ring;
      for (int tx = qx - ring; tx <= qx + ring; tx += full_row ? 1 : 2 * std::max(ring, 1)) {
        if (tx < 0 || tx >= tiles_x_) continue;
        const std::size_t tile = static_cast<std::size_t>(ty) * tiles_x_ + tx;
        for (std::uint32_t k = bucket_begin_[tile]; k < bucket_begin_[tile + 1]; ++k) {
          const std::uint32_t id = bucket_ids_[k];
          if (seen_stamp_[id] == stamp_) continue;
          seen_stamp_[id] = stamp_;
          if (skip != nullptr && (*skip)[id]) continue;
          const double d = PointSegmentDistance(x, y, (*segments_)[id]);
          if (d < best) {
            best = d;
            if (nearest_id != nullptr) *nearest_id = id;
          }
        }
        if (ring == 0) break;
      }
    }
    // Any segment not yet seen touches only tiles outside this ring: it is at
    // least as far as the border of the rings' square (at least ring * tile
    // away; the map's border tiles own everything beyond them).
    if (best <= DistanceOutside(x, y, qx, qy, ring)) break;
  }
  return best;
}

// A segment within `radius` has a point q at most `radius` from (x, y) in
// each coordinate; q lies in the tile TileOf gives it, which is within the
// tiles scanned (TileOf is monotone), and the segment is in that tile's
// list (AddToTiles: the tile's square holds q, so its centre is within half
// a diagonal of the segment; clamped points fall in border tiles, which
// own every segment of their range).
bool SegmentIndex::AnyWithin(double x, double y, double radius) const {
  const int tx0 = TileOf(x - radius, tiles_x_), tx1 = TileOf(x + radius, tiles_x_);
  const int ty0 = TileOf(y - radius, tiles_y_), ty1 = TileOf(y + radius, tiles_y_);
  for (int ty = ty0; ty <= ty1; ++ty) {
    for (int tx = tx0; tx <= tx1; ++tx) {
      const std::size_t tile = static_cast<std::size_t>(ty) * tiles_x_ + tx;
      for (std::uint32_t k = bucket_begin_[tile]; k < bucket_begin_[tile + 1]; ++k) {
        if (PointSegmentDistance(x, y, (*segments_)[bucket_ids_[k]]) <= radius) return true;
      }
    }
  }
  return false;
}

}  // namespace linemap::lines_internal
