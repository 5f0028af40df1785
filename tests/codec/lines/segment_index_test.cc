// SegmentIndex (codec/lines/segment_index.h) against a brute force over
// every segment, written here: the nearest distance, and whether any
// segment lies within a radius.
#include "codec/lines/segment_index.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "tests/testing/reference_geometry.h"

namespace linemap::lines_internal {
namespace {

std::vector<LineSegment> RandomSegments(std::mt19937* rng, int n, int w, int h) {
  std::uniform_real_distribution<double> x(-20.0, w + 20.0), y(-20.0, h + 20.0);
  std::uniform_real_distribution<double> step(-30.0, 30.0);
  std::vector<LineSegment> segments;
  for (int k = 0; k < n; ++k) {
    LineSegment s;
    s.x1 = std::round(x(*rng));
    s.y1 = std::round(y(*rng));
    // Mostly short walls, some points, a few long ones across the map.
    const int kind = static_cast<int>((*rng)() % 8);
    const double scale = kind == 0 ? 0.0 : kind == 1 ? 8.0 : 1.0;
    s.x2 = s.x1 + std::round(step(*rng) * scale);
    s.y2 = s.y1 + std::round(step(*rng) * scale);
    segments.push_back(s);
  }
  return segments;
}

TEST(SegmentIndexTest, NearestDistanceAndAnyWithinMatchTheBruteForce) {
  std::mt19937 rng(5);
  for (int trial = 0; trial < 20; ++trial) {
    const int w = 20 + static_cast<int>(rng() % 200), h = 20 + static_cast<int>(rng() % 200);
    const std::vector<LineSegment> segments =
        RandomSegments(&rng, 1 + static_cast<int>(rng() % 60), w, h);
    SegmentIndex index(&segments, w, h);
    for (int q = 0; q < 400; ++q) {
      // Cell centres, off-lattice points, and points beyond the map.
      const double x =
          static_cast<double>(static_cast<int>(rng() % (w + 20)) - 10) + (q % 3 == 0 ? 0.37 : 0.0);
      const double y = static_cast<double>(static_cast<int>(rng() % (h + 20)) - 10);
      double best = std::numeric_limits<double>::infinity();
      for (const LineSegment& s : segments)
        best = std::min(best, testing::ReferencePointSegmentDistance(x, y, s));
      EXPECT_NEAR(index.NearestDistance(x, y), best, 1e-9) << x << ", " << y;
      for (const double radius : {0.0, 0.5, 1.0, 1.5, 3.0, 17.0}) {
        // Away from the boundary, where rounding could tip either way.
        if (std::abs(best - radius) < 1e-9) continue;
        EXPECT_EQ(index.AnyWithin(x, y, radius), best <= radius)
            << x << ", " << y << " radius " << radius << " nearest " << best;
      }
    }
  }
}

TEST(SegmentIndexTest, AnyWithinAgreesWithNearestDistanceExactly) {
  // On cell centres and integer segments the two compare the same computed
  // distance, so they agree even at the boundary.
  std::mt19937 rng(9);
  const int w = 64, h = 48;
  const std::vector<LineSegment> segments = RandomSegments(&rng, 40, w, h);
  SegmentIndex index(&segments, w, h);
  int within = 0;
  for (int r = -3; r < h + 3; ++r) {
    for (int c = -3; c < w + 3; ++c) {
      const bool near = index.NearestDistance(c, r) <= 1.0;
      EXPECT_EQ(index.AnyWithin(c, r, 1.0), near) << c << ", " << r;
      within += near;
    }
  }
  EXPECT_GT(within, 100);
}

}  // namespace
}  // namespace linemap::lines_internal
