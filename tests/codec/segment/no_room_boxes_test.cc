// NoRoomBoxes (codec/segment/no_room_boxes.h): whether a box holds a cell in
// no room, by scanning and, past its scan budget, by the summed-area table,
// each against a brute-force count over random room maps and boxes.
#include "codec/segment/no_room_boxes.h"

#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

namespace linemap::segment_internal {
namespace {

// Room ids of a w x h map: mostly rooms 1..3, with no-room cells at the
// given density.
std::vector<std::int32_t> RandomRooms(int w, int h, double no_room_share, std::mt19937* rng) {
  std::vector<std::int32_t> room_of(static_cast<std::size_t>(w) * h);
  std::bernoulli_distribution none(no_room_share);
  std::uniform_int_distribution<int> room(1, 3);
  for (std::int32_t& r : room_of) r = none(*rng) ? 0 : room(*rng);
  return room_of;
}

bool BruteForceAny(const std::vector<std::int32_t>& room_of, int w, const BoundingBox& b) {
  int count = 0;
  for (int r = b.min_row; r <= b.max_row; ++r) {
    for (int c = b.min_col; c <= b.max_col; ++c) count += room_of[r * w + c] == 0;
  }
  return count > 0;
}

BoundingBox RandomBox(int w, int h, std::mt19937* rng) {
  std::uniform_int_distribution<int> col(0, w - 1), row(0, h - 1);
  int c0 = col(*rng), c1 = col(*rng), r0 = row(*rng), r1 = row(*rng);
  if (c1 < c0) std::swap(c0, c1);
  if (r1 < r0) std::swap(r0, r1);
  return {c0, r0, c1, r1};
}

TEST(NoRoomBoxesTest, ScansAndTableAgreeWithABruteForceCount) {
  std::mt19937 rng(7);
  for (const double share : {0.0, 0.0005, 0.01, 0.2}) {
    const int w = 37, h = 23;
    const std::vector<std::int32_t> room_of = RandomRooms(w, h, share, &rng);
    NoRoomBoxes scans(room_of, w, h, /*scan_budget=*/std::int64_t{1} << 40);
    NoRoomBoxes table(room_of, w, h, /*scan_budget=*/0);
    for (int k = 0; k < 500; ++k) {
      const BoundingBox b = RandomBox(w, h, &rng);
      const bool expected = BruteForceAny(room_of, w, b);
      EXPECT_EQ(scans.Any(b), expected) << "share " << share << " box " << b.min_col << ","
                                        << b.min_row << "-" << b.max_col << "," << b.max_row;
      EXPECT_EQ(table.Any(b), expected) << "share " << share;
    }
    EXPECT_FALSE(scans.built_table());
    EXPECT_TRUE(table.built_table());
  }
}

TEST(NoRoomBoxesTest, BuildsTheTableOnceTheScansPassTheBudget) {
  std::mt19937 rng(11);
  const int w = 50, h = 40;
  const std::vector<std::int32_t> room_of = RandomRooms(w, h, 0.0, &rng);
  // The default budget is twice the map: whole-map boxes (no cell in no
  // room, so each is read to its end) are scanned twice, then the table
  // answers.
  NoRoomBoxes boxes(room_of, w, h);
  const BoundingBox whole{0, 0, w - 1, h - 1};
  EXPECT_FALSE(boxes.Any(whole));
  EXPECT_FALSE(boxes.Any(whole));
  EXPECT_FALSE(boxes.built_table());
  EXPECT_FALSE(boxes.Any(whole));
  EXPECT_TRUE(boxes.built_table());
  // Scans are charged their whole box: after two whole-map scans (charged
  // exactly the budget) even a one-cell box goes to the table.
  NoRoomBoxes charged(room_of, w, h);
  EXPECT_FALSE(charged.Any(whole));
  EXPECT_FALSE(charged.Any(whole));
  EXPECT_FALSE(charged.built_table());
  EXPECT_FALSE(charged.Any({3, 4, 3, 4}));
  EXPECT_TRUE(charged.built_table());
  // The table's corners: one-cell boxes at the first and the last cell.
  std::vector<std::int32_t> with_corner = room_of;
  with_corner[static_cast<std::size_t>(h - 1) * w + (w - 1)] = 0;
  NoRoomBoxes corner(with_corner, w, h, /*scan_budget=*/0);
  EXPECT_TRUE(corner.Any({w - 1, h - 1, w - 1, h - 1}));
  EXPECT_FALSE(corner.Any({0, 0, 0, 0}));
  EXPECT_TRUE(corner.Any(whole));
}

}  // namespace
}  // namespace linemap::segment_internal
