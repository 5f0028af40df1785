// Whether a box of the map holds a cell in no room: the test that keeps a
// group of furniture pieces in room space (room_chains.cc, GroupPieces).
#ifndef LINEMAP_CODEC_SEGMENT_NO_ROOM_BOXES_H_
#define LINEMAP_CODEC_SEGMENT_NO_ROOM_BOXES_H_

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "linemap/cells.h"

namespace linemap::segment_internal {

// The boxes asked about are furniture-sized (at most max_furniture_area_m2)
// and few, so each is scanned in `room_of` itself, stopping at the first
// cell in no room: on real maps the scans read a fraction of the map, where
// a summed-area table of the whole map (4 bytes a cell, most of its cost
// the page faults of fresh memory) costs more than all the answers. Once
// the scans would read more than `scan_budget` cells (default: twice the
// map), the table is built after all, so a map of many specks costs at most
// a few passes over it.
class NoRoomBoxes {
 public:
  // `room_of`: the room of each cell (row-major, width * height), 0 for
  // none; it must outlive this object. The budget is twice the map.
  NoRoomBoxes(const std::vector<std::int32_t>& room_of, int width, int height)
      : NoRoomBoxes(room_of, width, height, 2 * static_cast<std::int64_t>(width) * height) {}
  NoRoomBoxes(const std::vector<std::int32_t>& room_of, int width, int height,
              std::int64_t scan_budget)
      : room_of_(room_of), width_(width), height_(height), scan_budget_(scan_budget) {}
  NoRoomBoxes(const NoRoomBoxes&) = delete;
  NoRoomBoxes& operator=(const NoRoomBoxes&) = delete;

  // Whether a cell of `b` (inside the map) has room 0.
  bool Any(const BoundingBox& b) {
    const std::int64_t area =
        static_cast<std::int64_t>(b.max_col - b.min_col + 1) * (b.max_row - b.min_row + 1);
    if (sums_.empty() && scanned_ + area > scan_budget_) BuildSums();
    if (!sums_.empty()) return Count(b) > 0;
    scanned_ += area;
    for (int r = b.min_row; r <= b.max_row; ++r) {
      const std::int32_t* row = room_of_.data() + static_cast<std::size_t>(r) * width_;
      if (std::find(row + b.min_col, row + b.max_col + 1, 0) != row + b.max_col + 1) return true;
    }
    return false;
  }
  bool built_table() const { return !sums_.empty(); }

 private:
  void BuildSums() {
    sums_.assign(static_cast<std::size_t>(width_ + 1) * (height_ + 1), 0);
    for (int r = 0; r < height_; ++r) {
      std::int32_t row_sum = 0;
      for (int c = 0; c < width_; ++c) {
        row_sum += room_of_[static_cast<std::size_t>(r) * width_ + c] == 0;
        At(c + 1, r + 1) = At(c + 1, r) + row_sum;
      }
    }
  }
  std::int32_t Count(const BoundingBox& b) const {
    return Get(b.max_col + 1, b.max_row + 1) - Get(b.min_col, b.max_row + 1) -
           Get(b.max_col + 1, b.min_row) + Get(b.min_col, b.min_row);
  }
  std::int32_t& At(int c, int r) { return sums_[static_cast<std::size_t>(r) * (width_ + 1) + c]; }
  std::int32_t Get(int c, int r) const {
    return sums_[static_cast<std::size_t>(r) * (width_ + 1) + c];
  }

  const std::vector<std::int32_t>& room_of_;
  int width_, height_;
  std::int64_t scan_budget_;  // cells scanned before the table pays
  std::int64_t scanned_ = 0;
  std::vector<std::int32_t> sums_;  // summed-area table of no-room cells, once built
};

}  // namespace linemap::segment_internal

#endif  // LINEMAP_CODEC_SEGMENT_NO_ROOM_BOXES_H_
