// ForEachInRange (range_scan.h) against a plain loop over every cell.
#include "codec/segment/range_scan.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

namespace linemap::segment_internal {
namespace {

std::vector<std::size_t> Visited(const std::vector<std::uint16_t>& dist, std::uint16_t lo,
                                 std::uint16_t hi) {
  std::vector<std::size_t> out;
  ForEachInRange(dist.data(), dist.size(), lo, hi, [&](std::size_t i) { out.push_back(i); });
  return out;
}

std::vector<std::size_t> Reference(const std::vector<std::uint16_t>& dist, std::uint16_t lo,
                                   std::uint16_t hi) {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < dist.size(); ++i) {
    if (lo <= dist[i] && dist[i] <= hi) out.push_back(i);
  }
  return out;
}

// Lengths around multiples of 8 (the vector part and the tail), values and
// bounds at both ends of 16 bits and across 0x8000, where a signed
// comparison would go wrong.
TEST(RangeScanTest, VisitsTheCellsInRangeInOrder) {
  std::mt19937 rng(7);
  const std::uint16_t edges[] = {0, 1, 2, 0x7ffe, 0x7fff, 0x8000, 0x8001, 0xfffe, 0xffff};
  for (const std::size_t n : {0u, 1u, 7u, 8u, 9u, 15u, 16u, 17u, 100u}) {
    std::vector<std::uint16_t> dist(n);
    for (std::uint16_t& d : dist) {
      d = rng() % 2 ? edges[rng() % 9] : static_cast<std::uint16_t>(rng());
    }
    for (const std::uint16_t lo : edges) {
      for (const std::uint16_t hi : edges) {
        SCOPED_TRACE("n " + std::to_string(n) + " lo " + std::to_string(lo) + " hi " +
                     std::to_string(hi));
        EXPECT_EQ(Visited(dist, lo, hi), Reference(dist, lo, hi));
      }
    }
  }
}

}  // namespace
}  // namespace linemap::segment_internal
