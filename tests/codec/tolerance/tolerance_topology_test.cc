// WithinDistance against a brute-force search of each cell's square of
// 2 radius + 1 cells a side: the tolerance checks read "within T cells" from
// it, so any cell it gets wrong at a map's border or for a radius beyond a
// side would pass or fail a guarantee wrongly.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <random>
#include <utility>
#include <vector>

#include "codec/tolerance/tolerance_internal.h"

namespace linemap::tolerance_internal {
namespace {

std::vector<std::uint8_t> BruteForceWithin(int w, int h, const std::vector<std::uint8_t>& mask,
                                           int radius) {
  std::vector<std::uint8_t> out(mask.size(), 0);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      for (int v = 0; v < h && !out[static_cast<std::size_t>(y) * w + x]; ++v) {
        for (int u = 0; u < w; ++u) {
          if (mask[static_cast<std::size_t>(v) * w + u] != 0 && std::abs(u - x) <= radius &&
              std::abs(v - y) <= radius) {
            out[static_cast<std::size_t>(y) * w + x] = 1;
            break;
          }
        }
      }
    }
  }
  return out;
}

TEST(WithinDistanceTest, MatchesABruteForceSearchAtEveryBorderAndRadius) {
  std::mt19937 rng(1234);
  const std::pair<int, int> sizes[] = {{1, 1}, {1, 9}, {9, 1}, {2, 2}, {17, 11}, {5, 23}};
  for (const auto& [w, h] : sizes) {
    const std::size_t n = static_cast<std::size_t>(w) * h;
    for (int kind = 0; kind < 5; ++kind) {
      std::vector<std::uint8_t> mask(n, 0);
      for (std::size_t i = 0; i < n; ++i) {
        // Empty, full, sparse, dense; and bytes other than 0 and 1.
        const unsigned roll = rng() % 100;
        mask[i] = kind == 0   ? 0
                  : kind == 1 ? 1
                  : kind == 2 ? (roll < 4 ? 1 : 0)
                  : kind == 3 ? (roll < 40 ? 1 : 0)
                              : (roll < 10 ? static_cast<std::uint8_t>(2 + roll) : 0);
      }
      for (int radius = 0; radius <= 6; ++radius) {
        EXPECT_EQ(WithinDistance(w, h, mask, radius), BruteForceWithin(w, h, mask, radius))
            << w << "x" << h << " kind " << kind << " radius " << radius;
      }
    }
  }
}

// A map with no columns or no rows has nothing within any distance.
TEST(WithinDistanceTest, EmptyMapsGiveEmptyMasks) {
  EXPECT_TRUE(WithinDistance(0, 5, {}, 2).empty());
  EXPECT_TRUE(WithinDistance(5, 0, {}, 2).empty());
  EXPECT_TRUE(WithinDistance(0, 0, {}, 0).empty());
}

}  // namespace
}  // namespace linemap::tolerance_internal
