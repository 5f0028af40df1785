// The small cell types' helpers (include/linemap/cells.h), on rings whose
// turn is known by construction.
#include "linemap/cells.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

namespace linemap {
namespace {

std::vector<CellIndex> Reversed(std::vector<CellIndex> ring) {
  std::reverse(ring.begin(), ring.end());
  return ring;
}

TEST(CellsTest, RunsClockwiseFollowsTheTurnOfTheRing) {
  // East, then north, then west: anticlockwise with rows north.
  const std::vector<CellIndex> square = {{0, 0}, {3, 0}, {3, 3}, {0, 3}};
  EXPECT_FALSE(RunsClockwise(square));
  EXPECT_TRUE(RunsClockwise(Reversed(square)));
  // An L-shaped room's 8-connected chain, traced anticlockwise.
  const std::vector<CellIndex> l_shape = {{0, 0}, {1, 0}, {2, 0}, {2, 1},
                                          {1, 1}, {1, 2}, {0, 2}, {0, 1}};
  EXPECT_FALSE(RunsClockwise(l_shape));
  EXPECT_TRUE(RunsClockwise(Reversed(l_shape)));
}

TEST(CellsTest, RingsEnclosingNothingAreNotClockwise) {
  EXPECT_FALSE(RunsClockwise({}));
  EXPECT_FALSE(RunsClockwise({{5, 5}}));
  EXPECT_FALSE(RunsClockwise({{5, 5}, {6, 6}}));
  EXPECT_FALSE(RunsClockwise({{0, 0}, {1, 0}, {2, 0}, {1, 0}}));  // out and back
}

// Near 2^31 the big square's shoelace terms are near 2^62 and their sum
// passes 2^63: 64-bit arithmetic would wrap and give the wrong turn. (The
// corner ring's products are near 2^62 too, but each term's two cancel.)
TEST(CellsTest, RunsClockwiseIsExactAtTheLargestIndices) {
  const int far = 2147483647;
  const std::vector<CellIndex> big = {{0, 0}, {far, 0}, {far, far}, {0, far}};
  EXPECT_FALSE(RunsClockwise(big));
  EXPECT_TRUE(RunsClockwise(Reversed(big)));
  const std::vector<CellIndex> corner = {{far - 2, far - 2}, {far, far - 2}, {far, far}};
  EXPECT_FALSE(RunsClockwise(corner));
  EXPECT_TRUE(RunsClockwise(Reversed(corner)));
}

}  // namespace
}  // namespace linemap
