#include "codec/lines/line_fit.h"

#include <gtest/gtest.h>

#include <cmath>

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

}  // namespace
}  // namespace linemap::lines_internal
