// ForEachInRange, ForEachRunAbove and FirstOtherThan (range_scan.h) against
// plain loops over every cell.
#include "codec/segment/range_scan.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <string>
#include <utility>
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

using Runs = std::vector<std::pair<std::size_t, std::size_t>>;

Runs RunsAbove(const std::vector<std::uint16_t>& dist, std::uint16_t t) {
  Runs out;
  ForEachRunAbove(dist.data(), dist.size(), t, [&](std::size_t begin, std::size_t end) {
    out.push_back({begin, end});
  });
  return out;
}

Runs ReferenceRuns(const std::vector<std::uint16_t>& dist, std::uint16_t t) {
  Runs out;
  for (std::size_t i = 0; i < dist.size(); ++i) {
    if (dist[i] <= t) continue;
    if (i > 0 && dist[i - 1] > t) {
      out.back().second = i + 1;
    } else {
      out.push_back({i, i + 1});
    }
  }
  return out;
}

// Runs that start and end inside the eight-cell blocks and on their edges,
// long runs over several blocks, and thresholds across 0x8000 and at the
// ends of 16 bits.
TEST(RangeScanTest, FindsTheRunsAboveAValue) {
  std::mt19937 rng(11);
  const std::uint16_t edges[] = {0, 1, 2, 0x7ffe, 0x7fff, 0x8000, 0x8001, 0xfffe, 0xffff};
  for (const std::size_t n : {0u, 1u, 7u, 8u, 9u, 15u, 16u, 17u, 64u, 100u}) {
    for (const int mean_run : {1, 3, 9, 40}) {
      std::vector<std::uint16_t> dist(n);
      std::uint16_t value = 0;
      for (std::uint16_t& d : dist) {
        if (rng() % mean_run == 0) value = rng() % 2 ? edges[rng() % 9] : rng();
        d = value;
      }
      for (const std::uint16_t t : edges) {
        SCOPED_TRACE("n " + std::to_string(n) + " run " + std::to_string(mean_run) + " t " +
                     std::to_string(t));
        EXPECT_EQ(RunsAbove(dist, t), ReferenceRuns(dist, t));
      }
    }
  }
}

TEST(RangeScanTest, FirstWhereAboveStartsAtItsIndex) {
  const std::vector<std::uint16_t> dist = {5, 0, 5, 5, 5, 5, 5, 5, 5, 5, 0, 0, 0, 0, 0, 0, 0, 0, 5};
  for (std::size_t from = 0; from <= dist.size(); ++from) {
    for (const bool above : {false, true}) {
      std::size_t expected = from;
      while (expected < dist.size() && (dist[expected] > 3) != above) ++expected;
      EXPECT_EQ(FirstWhereAbove(dist.data(), from, dist.size(), 3, above), expected)
          << "from " << from << " above " << above;
    }
  }
}

// Stretches of the skipped value of every length, starting anywhere
// against the four-entry blocks, from every start index; values that
// differ from it in one byte only.
TEST(RangeScanTest, FirstOtherThanSkipsTheValue) {
  std::mt19937 rng(5);
  const std::int32_t others[] = {0, 1, -1, 0x100, 0x10000, 0x1000000, -0x7fffffff - 1};
  for (const std::int32_t skipped : {0, -1, 7}) {
    for (const std::size_t n : {0u, 1u, 3u, 4u, 5u, 8u, 9u, 33u}) {
      for (int trial = 0; trial < 20; ++trial) {
        std::vector<std::int32_t> values(n);
        std::int32_t value = skipped;
        for (std::int32_t& v : values) {
          if (rng() % 5 == 0) value = rng() % 2 ? skipped : skipped ^ others[rng() % 7];
          v = value;
        }
        for (std::size_t from = 0; from <= n; ++from) {
          std::size_t expected = from;
          while (expected < n && values[expected] == skipped) ++expected;
          EXPECT_EQ(FirstOtherThan(values.data(), from, n, skipped), expected)
              << "skipped " << skipped << " n " << n << " trial " << trial << " from " << from;
        }
      }
    }
  }
}

}  // namespace
}  // namespace linemap::segment_internal
