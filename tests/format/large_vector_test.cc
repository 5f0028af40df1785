#include "format/large_vector.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "linemap/grid.h"

namespace linemap {
namespace {

// 24 MiB of int32: above the size from which the storage is advised.
constexpr std::size_t kLarge = std::size_t{6} << 20;

bool AllEqual(const std::vector<std::int32_t>& v, std::int32_t value) {
  return std::all_of(v.begin(), v.end(), [&](std::int32_t x) { return x == value; });
}

TEST(LargeVectorTest, HoldsNCopiesLargeOrSmall) {
  for (const std::size_t n : {std::size_t{0}, std::size_t{1}, std::size_t{1000}, kLarge}) {
    const std::vector<std::int32_t> v = LargeVector<std::int32_t>(n, -1);
    EXPECT_EQ(v.size(), n);
    EXPECT_TRUE(AllEqual(v, -1)) << n;
  }
}

TEST(LargeVectorTest, AssignKeepsStorageLargeEnough) {
  std::vector<std::int32_t> v = LargeVector<std::int32_t>(kLarge, 5);
  const std::int32_t* storage = v.data();
  AssignLarge<std::int32_t>(&v, kLarge / 2, 9);
  EXPECT_EQ(v.data(), storage);
  EXPECT_EQ(v.size(), kLarge / 2);
  EXPECT_TRUE(AllEqual(v, 9));
}

TEST(LargeVectorTest, GrowsFromAValueItHolds) {
  // The value is read before the old storage is freed (ASan would report
  // the use after free otherwise).
  std::vector<std::int32_t> v(3, 7);
  AssignLarge(&v, kLarge, v[1]);
  EXPECT_EQ(v.size(), kLarge);
  EXPECT_TRUE(AllEqual(v, 7));
}

TEST(LargeVectorTest, LargeGridIsFilled) {
  const Grid grid(4096, 3000, Cell::kOccupied);
  EXPECT_EQ(grid.size(), std::size_t{4096} * 3000);
  EXPECT_EQ(grid.Count().occupied, grid.size());
}

}  // namespace
}  // namespace linemap
