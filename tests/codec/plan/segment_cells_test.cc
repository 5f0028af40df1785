#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "linemap/plan.h"
#include "tests/codec/plan/plan_test_util.h"

namespace linemap {
namespace {

using plan_test::Pairs;

TEST(SegmentCellsTest, KnownLines) {
  using P = std::vector<std::pair<int, int>>;
  EXPECT_EQ(Pairs(SegmentCells({0, 0}, {2, 0})), (P{{0, 0}, {1, 0}, {2, 0}}));
  EXPECT_EQ(Pairs(SegmentCells({0, 0}, {0, -2})), (P{{0, 0}, {0, -1}, {0, -2}}));
  // Through the corner at (0.5, 0.5): both side cells are touched.
  EXPECT_EQ(Pairs(SegmentCells({0, 0}, {1, 1})), (P{{0, 0}, {1, 0}, {0, 1}, {1, 1}}));
  // y = x / 2 crosses x = 0.5 at y = 0.25, y = 0.5 at x = 1, x = 1.5 at 0.75.
  EXPECT_EQ(Pairs(SegmentCells({0, 0}, {2, 1})), (P{{0, 0}, {1, 0}, {1, 1}, {2, 1}}));
  EXPECT_EQ(Pairs(SegmentCells({3, 3}, {3, 3})), (P{{3, 3}}));
}

// Every cell a dense sampling of the segment meets is in SegmentCells.
TEST(SegmentCellsTest, CoversDenseSampling) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> coord(-12, 12);
  for (int trial = 0; trial < 300; ++trial) {
    const CellIndex a{coord(rng), coord(rng)}, b{coord(rng), coord(rng)};
    const std::vector<CellIndex> cells = SegmentCells(a, b);
    std::set<std::pair<int, int>> set;
    for (const CellIndex& c : cells) set.insert({c.col, c.row});
    const int steps = 4000;
    for (int i = 0; i <= steps; ++i) {
      const double t = static_cast<double>(i) / steps;
      const int c = static_cast<int>(std::floor(a.col + t * (b.col - a.col) + 0.5));
      const int r = static_cast<int>(std::floor(a.row + t * (b.row - a.row) + 0.5));
      ASSERT_TRUE(set.count({c, r})) << a.col << "," << a.row << " -> " << b.col << "," << b.row;
    }
    // 4-connected walk from a to b: no cell twice.
    EXPECT_EQ(set.size(), cells.size());
  }
}

}  // namespace
}  // namespace linemap
