// Total-least-squares line fitting over cell centres, shared by RM-Line and
// linemap's extractor. RM-Line's Eq. (3)-(4) (Liu & Zhang 2022, section 2.3)
// are the moments of the points and the line through their centroid; see
// line_fit.cc for why Eq. (4) is not used as printed.
#ifndef LINEMAP_CODEC_LINES_LINE_FIT_H_
#define LINEMAP_CODEC_LINES_LINE_FIT_H_

#include <Eigen/Core>
#include <cstddef>

#include "linemap/lines.h"

namespace linemap::lines_internal {

// A line through `centroid` along the unit vector `direction` (cell units).
struct FittedLine {
  Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
  Eigen::Vector2d direction = Eigen::Vector2d::UnitX();
  // Smallest eigenvalue of the covariance: the mean squared distance of the
  // points to the line (cells^2).
  double mean_squared_residual = 0;
};

// The TLS line through `centroid` given the 2x2 covariance of the points.
FittedLine FitFromCovariance(const Eigen::Vector2d& centroid, const Eigen::Matrix2d& covariance);

// The smallest eigenvalue of a 2x2 covariance in closed form: the mean
// squared distance of the points to their TLS line, for quick rejections.
double SmallestEigenvalue(const Eigen::Matrix2d& covariance);

// The first and second moments of a point set, Eq. (3): mu_x, mu_y, mu_xx,
// mu_yy, mu_xy. Sums are taken relative to the first point added so that
// large coordinates do not cancel.
class PointMoments {
 public:
  void Add(double x, double y);
  // Adds every point of `other` (which may use another reference point).
  void Merge(const PointMoments& other);
  std::size_t count() const { return count_; }
  Eigen::Vector2d Mean() const;
  // mu_xx, mu_xy, mu_yy as the 2x2 covariance (divided by N, as Eq. 3).
  Eigen::Matrix2d Covariance() const;
  // The total-least-squares line: the principal axis of Covariance().
  FittedLine Fit() const;

 private:
  bool has_reference_ = false;
  double ref_x_ = 0, ref_y_ = 0;
  std::size_t count_ = 0;
  double sx_ = 0, sy_ = 0, sxx_ = 0, sxy_ = 0, syy_ = 0;
};

// The segment of `line` between the projections of the extreme points of
// `xs`/`ys` (n points) onto it.
LineSegment SegmentFromProjections(const FittedLine& line, const double* xs, const double* ys,
                                   std::size_t n);

// Euclidean distance from point (x, y) to a segment (cell units).
double PointSegmentDistance(double x, double y, const LineSegment& segment);

}  // namespace linemap::lines_internal

#endif  // LINEMAP_CODEC_LINES_LINE_FIT_H_
