#include "codec/lines/line_fit.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

namespace linemap::lines_internal {
namespace {

TEST(LineFitTest, VerticalPointsGiveAVerticalLine) {
  // Eq. (4) as printed divides 0 by 0 here (mu_xx = mu_xy = 0).
  PointMoments moments;
  for (int row = 0; row < 5; ++row) moments.Add(7, row);
  const FittedLine line = moments.Fit();
  EXPECT_NEAR(line.centroid.x(), 7, 1e-12);
  EXPECT_NEAR(line.centroid.y(), 2, 1e-12);
  EXPECT_NEAR(line.direction.x(), 0, 1e-12);
  EXPECT_NEAR(line.direction.y(), 1, 1e-12);
  EXPECT_NEAR(line.mean_squared_residual, 0, 1e-12);
}

TEST(LineFitTest, TotalNotOrdinaryLeastSquares) {
  // (0,0), (1,1), (2,2) plus the mirror pair (0,1), (1,0): the set is
  // symmetric about y = x, so the TLS line is y = x exactly, while ordinary
  // y-on-x regression gives slope 0.7.
  PointMoments moments;
  moments.Add(0, 0);
  moments.Add(1, 1);
  moments.Add(2, 2);
  moments.Add(0, 1);
  moments.Add(1, 0);
  const FittedLine line = moments.Fit();
  EXPECT_NEAR(line.direction.x(), std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(line.direction.y(), std::sqrt(0.5), 1e-12);
}

TEST(LineFitTest, MergeEqualsAddingEveryPoint) {
  PointMoments a, b, all;
  const double xs[] = {1000.5, 1003, 1007, 1002, 1009, 1011};
  const double ys[] = {-3, 2, 4.5, 8, 1, 0};
  for (int i = 0; i < 6; ++i) {
    (i < 3 ? a : b).Add(xs[i], ys[i]);
    all.Add(xs[i], ys[i]);
  }
  a.Merge(b);
  EXPECT_EQ(a.count(), 6u);
  EXPECT_TRUE(a.Mean().isApprox(all.Mean(), 1e-12));
  EXPECT_TRUE(a.Covariance().isApprox(all.Covariance(), 1e-9));
}

TEST(LineFitTest, SegmentEndsAreProjectionsOfTheExtremePoints) {
  // (0,1), (3,1), (6,1), (9,1): the line y = 1, cut at x = 0 and x = 9.
  PointMoments moments;
  const double xs[] = {0, 3, 6, 9};
  const double ys[] = {1, 1, 1, 1};
  for (int i = 0; i < 4; ++i) moments.Add(xs[i], ys[i]);
  const LineSegment s = SegmentFromProjections(moments.Fit(), xs, ys, 4);
  EXPECT_NEAR(s.x1, 0, 1e-12);
  EXPECT_NEAR(s.y1, 1, 1e-12);
  EXPECT_NEAR(s.x2, 9, 1e-12);
  EXPECT_NEAR(s.y2, 1, 1e-12);
}

TEST(LineFitTest, PointSegmentDistance) {
  const LineSegment s{0, 0, 4, 0};
  EXPECT_DOUBLE_EQ(PointSegmentDistance(2, 3, s), 3);
  EXPECT_DOUBLE_EQ(PointSegmentDistance(7, 4, s), 5);    // beyond the end: to (4,0)
  EXPECT_DOUBLE_EQ(PointSegmentDistance(-3, -4, s), 5);  // before the start: to (0,0)
  EXPECT_DOUBLE_EQ(PointSegmentDistance(1, 1, LineSegment{2, 2, 2, 2}), std::sqrt(2.0));
}

// FitFromCovariance repeats the closed-form solver's operations: the same
// bits as the solver itself, on covariances of cell sets (as the extractor
// fits them) and on the degenerate ones (points, axis-parallel and
// diagonal lines, equal spreads, tiny or huge magnitudes).
void ExpectSameBits(const Eigen::Matrix2d& cov) {
  const Eigen::Vector2d centroid(3.25, -7.5);
  const FittedLine fast = FitFromCovariance(centroid, cov);
  const FittedLine reference = FitFromCovarianceReference(centroid, cov);
  const auto bits = [](double x) { return std::bit_cast<std::uint64_t>(x); };
  SCOPED_TRACE(::testing::Message()
               << "covariance " << cov(0, 0) << " " << cov(0, 1) << " " << cov(1, 1));
  EXPECT_EQ(bits(fast.direction.x()), bits(reference.direction.x()));
  EXPECT_EQ(bits(fast.direction.y()), bits(reference.direction.y()));
  EXPECT_EQ(bits(fast.mean_squared_residual), bits(reference.mean_squared_residual));
  EXPECT_EQ(fast.centroid, reference.centroid);
}

Eigen::Matrix2d Symmetric(double xx, double xy, double yy) {
  Eigen::Matrix2d cov;
  cov << xx, xy, xy, yy;
  return cov;
}

TEST(LineFitTest, FitFromCovarianceMatchesEigensSolver) {
  const double values[] = {0, 1e-300, 1e-12, 0.25, 0.5, 1, 2, 3.75, 1e6, 1e12};
  for (const double xx : values) {
    for (const double yy : values) {
      for (const double xy : values) {
        ExpectSameBits(Symmetric(xx, xy, yy));
        ExpectSameBits(Symmetric(xx, -xy, yy));
      }
    }
  }
  std::mt19937 rng(19);
  std::uniform_int_distribution<int> coordinate(-40, 40);
  std::uniform_int_distribution<int> count(1, 60);
  std::uniform_real_distribution<double> slope(-3, 3);
  for (int trial = 0; trial < 20000; ++trial) {
    // Cells along a random line, a cell or two off it now and then.
    PointMoments moments;
    const int n = count(rng);
    const double m = slope(rng);
    const bool steep = trial % 2 == 1;
    const int x0 = coordinate(rng), y0 = coordinate(rng);
    for (int k = 0; k < n; ++k) {
      const int off = coordinate(rng) % 3 == 0 ? coordinate(rng) % 2 : 0;
      const int along = x0 + k, across = y0 + static_cast<int>(std::lround(m * k)) + off;
      steep ? moments.Add(across, along) : moments.Add(along, across);
    }
    ExpectSameBits(moments.Covariance());
    std::uniform_real_distribution<double> any(-1e3, 1e3);
    const double xx = std::abs(any(rng)), yy = std::abs(any(rng));
    ExpectSameBits(Symmetric(xx, any(rng) * 1e-3 * std::sqrt(xx * yy), yy));
  }
}

}  // namespace
}  // namespace linemap::lines_internal
