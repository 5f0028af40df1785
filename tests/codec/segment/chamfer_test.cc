// The chamfer transform (codec/segment/chamfer.h) against plain reference
// code written here: the row scan (with SSE2 and without) against its
// defining minimum, the whole transform against a brute-force minimum over
// every wall cell.
#include "codec/segment/chamfer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <random>
#include <vector>

namespace linemap::segment_internal {
namespace {

// row[c] = min over k in [1, c] (forward) or [c, pw - 2] (backward) of
// t[k] + 3 |c - k|, and the frame cell beyond the row: 0 + 3 times its
// distance.
std::vector<std::uint16_t> ReferenceScan(const std::vector<std::uint16_t>& t, int pw,
                                         bool forward) {
  std::vector<std::uint16_t> row(t.size(), 0);
  for (int c = 1; c < pw - 1; ++c) {
    long best = forward ? 3L * c : 3L * (pw - 1 - c);
    for (int k = 1; k < pw - 1; ++k) {
      if (forward ? k <= c : k >= c) best = std::min(best, t[k] + 3L * std::abs(c - k));
    }
    row[c] = static_cast<std::uint16_t>(best);
  }
  return row;
}

TEST(ChamferTest, RowScanIsThePrefixMinimumAtEveryWidth) {
  std::mt19937 rng(7);
  for (int pw = 3; pw <= 70; ++pw) {
    for (int trial = 0; trial < 20; ++trial) {
      std::vector<std::uint16_t> t(static_cast<std::size_t>(pw), 0);
      for (int c = 1; c < pw - 1; ++c) {
        const unsigned kind = rng() % 4;
        // Walls, far cells, values near the top of the range, small ones.
        t[c] = kind == 0   ? 0
               : kind == 1 ? 0xfffe
               : kind == 2 ? static_cast<std::uint16_t>(0xfffe - rng() % 40)
                           : static_cast<std::uint16_t>(rng() % 200);
      }
      for (const bool forward : {true, false}) {
        const std::vector<std::uint16_t> expected = ReferenceScan(t, pw, forward);
        std::vector<std::uint16_t> row(t.size(), 0);
        ChamferScanRow(t.data(), row.data(), pw, forward);
        EXPECT_EQ(row, expected) << "width " << pw << (forward ? " >" : " <");
        std::vector<std::uint16_t> serial(t.size(), 0);
        ChamferScanRowSerial(t.data(), serial.data(), pw, forward);
        EXPECT_EQ(serial, expected) << "serial, width " << pw << (forward ? " >" : " <");
      }
    }
  }
}

// Rows of long stretches of walls and of open space, starting anywhere
// against the eight-cell blocks: blocks of walls only are taken at once.
TEST(ChamferTest, RowScanOverStretchesOfWalls) {
  std::mt19937 rng(13);
  for (int pw = 3; pw <= 90; ++pw) {
    for (int trial = 0; trial < 20; ++trial) {
      std::vector<std::uint16_t> t(static_cast<std::size_t>(pw), 0);
      std::uint16_t value = 0;
      for (int c = 1; c < pw - 1; ++c) {
        if (rng() % 12 == 0) value = rng() % 2 ? 0 : static_cast<std::uint16_t>(rng() % 0xffff);
        t[c] = value;
      }
      for (const bool forward : {true, false}) {
        std::vector<std::uint16_t> row(t.size(), 7);
        ChamferScanRow(t.data(), row.data(), pw, forward);
        std::vector<std::uint16_t> expected = ReferenceScan(t, pw, forward);
        expected[0] = expected[pw - 1] = 7;  // the frame cells are not written
        EXPECT_EQ(row, expected) << "width " << pw << (forward ? " >" : " <");
      }
    }
  }
}

// Grids with rooms inside thick walls and unknown space (whole blocks of
// walls in both passes) against the plain two-pass transform.
TEST(ChamferTest, TransformOverBlocksOfWalls) {
  std::mt19937 rng(17);
  for (int trial = 0; trial < 30; ++trial) {
    const int pw = 3 + static_cast<int>(rng() % 60), ph = 3 + static_cast<int>(rng() % 40);
    std::vector<std::uint16_t> dist(static_cast<std::size_t>(pw) * ph, 0);
    for (int k = 0; k < 3; ++k) {
      const int c0 = 1 + static_cast<int>(rng() % (pw - 2)),
                r0 = 1 + static_cast<int>(rng() % (ph - 2));
      const int c1 = std::min(pw - 1, c0 + 1 + static_cast<int>(rng() % 30));
      const int r1 = std::min(ph - 1, r0 + 1 + static_cast<int>(rng() % 20));
      for (int r = r0; r < r1; ++r) {
        for (int c = c0; c < c1; ++c) dist[static_cast<std::size_t>(r) * pw + c] = kChamferFar;
      }
    }
    std::vector<std::uint16_t> expected = dist;
    for (int pass = 0; pass < 2; ++pass) {
      for (int k = 1; k < ph - 1; ++k) {
        const int r = pass == 0 ? k : ph - 1 - k;
        for (int j = 1; j < pw - 1; ++j) {
          const int c = pass == 0 ? j : pw - 1 - j;
          std::uint16_t& d = expected[static_cast<std::size_t>(r) * pw + c];
          if (d == 0) continue;
          const int dr = pass == 0 ? -1 : 1, dc = pass == 0 ? -1 : 1;
          int best = d;
          const auto at = [&](int cc, int rr) {
            return expected[static_cast<std::size_t>(rr) * pw + cc];
          };
          best = std::min(best, at(c + dc, r) + kChamferSide);
          best = std::min(best, at(c, r + dr) + kChamferSide);
          best = std::min(best, at(c - 1, r + dr) + kChamferDiagonal);
          best = std::min(best, at(c + 1, r + dr) + kChamferDiagonal);
          d = static_cast<std::uint16_t>(std::min(best, 0xfffe));
        }
      }
    }
    ChamferInPlace(&dist, pw, ph);
    EXPECT_EQ(dist, expected) << "trial " << trial;
  }
}

// A row of open space longer than 0xfffe / 3 cells (a map some 22,000 cells
// wide, within the default limit of 2^30 cells): the distance from the frame
// passes 0xfffe and stays there, where a running value that wrapped around
// would start again from 1.
TEST(ChamferTest, RowScanSaturatesOnLongOpenRows) {
  const int pw = 22000;
  const std::vector<std::uint16_t> t(static_cast<std::size_t>(pw), 0xfffe);
  for (const bool forward : {true, false}) {
    std::vector<std::uint16_t> row(t.size(), 0), serial(t.size(), 0);
    ChamferScanRow(t.data(), row.data(), pw, forward);
    ChamferScanRowSerial(t.data(), serial.data(), pw, forward);
    for (int c = 1; c < pw - 1; ++c) {
      const long from_frame = 3L * (forward ? c : pw - 1 - c);
      const auto expected = static_cast<std::uint16_t>(std::min(from_frame, 0xfffeL));
      ASSERT_EQ(row[c], expected) << "cell " << c << (forward ? " >" : " <");
      ASSERT_EQ(serial[c], expected) << "serial, cell " << c << (forward ? " >" : " <");
    }
  }
}

// The 3-4 chamfer distance between two cells: 4 per diagonal step, 3 per
// straight step of the rest.
int ChamferDistance(int dc, int dr) {
  const int a = std::abs(dc), b = std::abs(dr);
  return 4 * std::min(a, b) + 3 * (std::max(a, b) - std::min(a, b));
}

TEST(ChamferTest, TransformIsTheDistanceToTheNearestWall) {
  std::mt19937 rng(11);
  for (int trial = 0; trial < 30; ++trial) {
    const int pw = 3 + static_cast<int>(rng() % 40), ph = 3 + static_cast<int>(rng() % 30);
    std::vector<std::uint16_t> dist(static_cast<std::size_t>(pw) * ph, 0);
    for (int r = 1; r < ph - 1; ++r) {
      for (int c = 1; c < pw - 1; ++c) {
        if (rng() % 10 != 0) dist[static_cast<std::size_t>(r) * pw + c] = kChamferFar;
      }
    }
    std::vector<std::uint16_t> expected = dist;
    for (int r = 0; r < ph; ++r) {
      for (int c = 0; c < pw; ++c) {
        if (dist[static_cast<std::size_t>(r) * pw + c] == 0) continue;
        int best = 0xfffe;
        for (int r2 = 0; r2 < ph; ++r2) {
          for (int c2 = 0; c2 < pw; ++c2) {
            if (dist[static_cast<std::size_t>(r2) * pw + c2] == 0) {
              best = std::min(best, ChamferDistance(c - c2, r - r2));
            }
          }
        }
        expected[static_cast<std::size_t>(r) * pw + c] = static_cast<std::uint16_t>(best);
      }
    }
    ChamferInPlace(&dist, pw, ph);
    EXPECT_EQ(dist, expected) << pw << " x " << ph;
  }
}

}  // namespace
}  // namespace linemap::segment_internal
