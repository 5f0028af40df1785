// Step 4 of linemap's extractor: the merge's index of groups by the tiles
// their segments pass through, which finds the groups near a segment's ends
// (see MergeGroups).
#ifndef LINEMAP_CODEC_LINES_GROUP_TILES_H_
#define LINEMAP_CODEC_LINES_GROUP_TILES_H_

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "codec/lines/line_groups.h"
#include "linemap/lines.h"

namespace linemap::lines_internal {

// Buckets of group ids by the tiles their segments pass through; entries go
// stale when groups merge and are re-checked by the reader.
class GroupTiles {
 public:
  GroupTiles(int width, int height, int tile) : tile_(tile) {
    tiles_x_ = std::max(1, (width + tile - 1) / tile);
    tiles_y_ = std::max(1, (height + tile - 1) / tile);
    buckets_.resize(static_cast<std::size_t>(tiles_x_) * tiles_y_);
  }

  void Add(std::uint32_t id, const LineSegment& s) {
    ForEachTile(s, [&](int tile) {
      Bucket& bucket = buckets_[tile];
      if (bucket.size == bucket.capacity) Grow(&bucket);
      arena_[bucket.begin + bucket.size++] = id;
    });
  }

  // Add() for groups 0, 1, ... in order, their buckets laid out in tile
  // order, each non-empty one with room for a few merged groups (an empty
  // one grows at its first Add()).
  void AddAll(const std::vector<Group>& groups) {
    for (const Group& group : groups) {
      ForEachTile(group.segment, [&](int tile) { ++buckets_[tile].capacity; });
    }
    std::uint32_t begin = 0;
    for (Bucket& bucket : buckets_) {
      bucket.begin = begin;
      if (bucket.capacity > 0) bucket.capacity += kBucketSlack;
      begin += bucket.capacity;
    }
    arena_.resize(begin);
    for (std::uint32_t id = 0; id < groups.size(); ++id) Add(id, groups[id].segment);
  }

  // Calls visit(id) for the live groups (`alive`, one flag per group id;
  // compact, so the scan touches no Group) registered in the tiles within
  // `radius` of either end of `s` (an id may repeat across tiles; tiles
  // near both ends are scanned once). Dead and repeated entries are dropped
  // from the buckets on the way, so merged groups do not pile up. `visit`
  // must not call Add(): a bucket that grows moves in the arena under the
  // scan.
  template <typename Visit>
  void ForEachNearEnds(const LineSegment& s, double radius, const std::vector<std::uint8_t>& alive,
                       Visit visit) {
    if (mark_.size() < alive.size()) mark_.resize(alive.size(), 0);
    const TileRange first = RangeNear(s.x1, s.y1, radius);
    const TileRange second = RangeNear(s.x2, s.y2, radius);
    for (int ty = first.y0; ty <= first.y1; ++ty) {
      for (int tx = first.x0; tx <= first.x1; ++tx) ScanBucket(tx, ty, alive, visit);
    }
    for (int ty = second.y0; ty <= second.y1; ++ty) {
      for (int tx = second.x0; tx <= second.x1; ++tx) {
        if (!first.Contains(tx, ty)) ScanBucket(tx, ty, alive, visit);
      }
    }
  }

 private:
  struct TileRange {
    int x0, x1, y0, y1;
    bool Contains(int tx, int ty) const { return tx >= x0 && tx <= x1 && ty >= y0 && ty <= y1; }
  };
  TileRange RangeNear(double x, double y, double radius) const {
    return {
        Clamp((x - radius + 0.5) / tile_, tiles_x_), Clamp((x + radius + 0.5) / tile_, tiles_x_),
        Clamp((y - radius + 0.5) / tile_, tiles_y_), Clamp((y + radius + 0.5) / tile_, tiles_y_)};
  }
  template <typename Visit>
  void ScanBucket(int tx, int ty, const std::vector<std::uint8_t>& alive, Visit& visit) {
    Bucket& bucket = buckets_[static_cast<std::size_t>(ty) * tiles_x_ + tx];
    std::uint32_t* ids = arena_.data() + bucket.begin;
    ++stamp_;
    std::uint32_t kept = 0;
    for (std::uint32_t i = 0; i < bucket.size; ++i) {
      const std::uint32_t id = ids[i];
      if (!alive[id] || mark_[id] == stamp_) continue;
      mark_[id] = stamp_;
      ids[kept++] = id;
      visit(id);
    }
    bucket.size = kept;
  }
  // Calls visit(tile) for the tiles of points every half tile along s (each
  // tile once per run of equal tiles).
  template <typename Visit>
  void ForEachTile(const LineSegment& s, Visit visit) const {
    const double length = std::sqrt((s.x2 - s.x1) * (s.x2 - s.x1) + (s.y2 - s.y1) * (s.y2 - s.y1));
    const int steps = 1 + static_cast<int>(length / (0.5 * tile_));
    int last = -1;
    for (int k = 0; k <= steps; ++k) {
      const double t = static_cast<double>(k) / steps;
      const int tile = TileIndex(s.x1 + t * (s.x2 - s.x1), s.y1 + t * (s.y2 - s.y1));
      if (tile != last) visit(tile);
      last = tile;
    }
  }
  // A tile's group ids: arena_[begin, begin + size), room for `capacity`
  // (one arena rather than a vector per tile).
  struct Bucket {
    std::uint32_t begin = 0, size = 0, capacity = 0;
  };
  static constexpr std::uint32_t kBucketSlack = 4;
  // Moves a full bucket to the arena's end with twice the room.
  void Grow(Bucket* bucket) {
    const std::uint32_t capacity = std::max<std::uint32_t>(kBucketSlack, 2 * bucket->capacity);
    const std::uint32_t begin = static_cast<std::uint32_t>(arena_.size());
    arena_.resize(arena_.size() + capacity);
    std::copy_n(arena_.begin() + bucket->begin, bucket->size, arena_.begin() + begin);
    bucket->begin = begin;
    bucket->capacity = capacity;
  }
  // floor(t) clamped to [0, tiles - 1] (truncation is floor for t >= 0).
  static int Clamp(double t, int tiles) {
    if (!(t > 0)) return 0;
    if (t >= tiles - 1) return tiles - 1;
    return static_cast<int>(t);
  }
  int TileIndex(double x, double y) const {
    return Clamp((y + 0.5) / tile_, tiles_y_) * tiles_x_ + Clamp((x + 0.5) / tile_, tiles_x_);
  }

  int tile_;
  int tiles_x_ = 1, tiles_y_ = 1;
  std::vector<Bucket> buckets_;
  std::vector<std::uint32_t> arena_;
  std::vector<std::uint32_t> mark_;  // per group: the last bucket scan that kept it
  std::uint32_t stamp_ = 0;
};

}  // namespace linemap::lines_internal

#endif  // LINEMAP_CODEC_LINES_GROUP_TILES_H_
