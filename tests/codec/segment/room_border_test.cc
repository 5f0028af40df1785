// Internal pieces of the room-border closure: the paper's mid-line rule and
// the point-in-polygon test.
#include <gtest/gtest.h>

#include "codec/segment/segment_internal.h"

namespace linemap::segment_internal {
namespace {

Labeling LabelRows(const std::vector<std::string>& rows) {
  BinaryMask mask(static_cast<int>(rows[0].size()), static_cast<int>(rows.size()));
  for (int r = 0; r < mask.height; ++r) {
    for (int c = 0; c < mask.width; ++c) mask.set(c, r, rows[r][c] == '#');
  }
  return LabelComponents(mask, Connectivity::kEight);
}

TEST(MidLineEntriesTest, RingBlobAndU) {
  // Mid-line of a 5-row box is row 2.
  const Labeling ring = LabelRows({"#####", "#...#", "#...#", "#...#", "#####"});
  EXPECT_EQ(MidLineEntries(ring, 1), 2);  // a room border
  const Labeling blob = LabelRows({".###.", "#####", "#####", ".###."});
  EXPECT_EQ(MidLineEntries(blob, 1), 1);  // furniture
  // A U also gives two entries: the rule alone would call it a room border,
  // which is why SegmentMap() decides by enclosure.
  const Labeling u = LabelRows({"#####", "#...#", "#...#"});
  EXPECT_EQ(MidLineEntries(u, 1), 2);
}

TEST(PolygonContainsTest, SquareWithVerticesOnTheScanRow) {
  const std::vector<CellIndex> square = {{0, 0}, {4, 0}, {4, 4}, {0, 4}};
  EXPECT_TRUE(PolygonContains(square, 2, 2));
  EXPECT_TRUE(PolygonContains(square, 1, 3));
  EXPECT_FALSE(PolygonContains(square, 5, 2));
  EXPECT_FALSE(PolygonContains(square, -1, 2));
  // A diamond whose left and right vertices lie on the test row.
  const std::vector<CellIndex> diamond = {{2, 0}, {4, 2}, {2, 4}, {0, 2}};
  EXPECT_TRUE(PolygonContains(diamond, 2, 2));
  EXPECT_FALSE(PolygonContains(diamond, 5, 2));
  EXPECT_FALSE(PolygonContains(diamond, -1, 2));
}

}  // namespace
}  // namespace linemap::segment_internal
