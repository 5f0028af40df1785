// Total-least-squares line fitting over cell centres, shared by RM-Line and
// linemap's extractor. RM-Line's Eq. (3)-(4) (Liu & Zhang 2022, section 2.3)
// are the moments of the points and the line through their centroid; see
// line_fit.cc for why Eq. (4) is not used as printed.
#ifndef LINEMAP_CODEC_LINES_LINE_FIT_H_
#define LINEMAP_CODEC_LINES_LINE_FIT_H_

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
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
// The same through Eigen's solver (SelfAdjointEigenSolver::computeDirect),
// for tests: FitFromCovariance must give the same bits.
FittedLine FitFromCovarianceReference(const Eigen::Vector2d& centroid,
                                      const Eigen::Matrix2d& covariance);

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

// Inline: the extractor's merge search calls these for every candidate pair.
inline void PointMoments::Merge(const PointMoments& other) {
  if (other.count_ == 0) return;
  if (!has_reference_) {
    *this = other;
    return;
  }
  // Shift other's sums from its reference point to ours.
  const double ox = other.ref_x_ - ref_x_;
  const double oy = other.ref_y_ - ref_y_;
  const double n = static_cast<double>(other.count_);
  sxx_ += other.sxx_ + 2 * ox * other.sx_ + n * ox * ox;
  syy_ += other.syy_ + 2 * oy * other.sy_ + n * oy * oy;
  sxy_ += other.sxy_ + ox * other.sy_ + oy * other.sx_ + n * ox * oy;
  sx_ += other.sx_ + n * ox;
  sy_ += other.sy_ + n * oy;
  count_ += other.count_;
}

inline Eigen::Vector2d PointMoments::Mean() const {
  if (count_ == 0) return Eigen::Vector2d::Zero();
  const double n = static_cast<double>(count_);
  return {ref_x_ + sx_ / n, ref_y_ + sy_ / n};
}

inline Eigen::Matrix2d PointMoments::Covariance() const {
  Eigen::Matrix2d cov = Eigen::Matrix2d::Zero();
  if (count_ == 0) return cov;
  const double n = static_cast<double>(count_);
  const double mx = sx_ / n;
  const double my = sy_ / n;
  cov(0, 0) = std::max(0.0, sxx_ / n - mx * mx);  // mu_xx
  cov(1, 1) = std::max(0.0, syy_ / n - my * my);  // mu_yy
  cov(0, 1) = cov(1, 0) = sxy_ / n - mx * my;     // mu_xy
  return cov;
}

inline double SmallestEigenvalue(const Eigen::Matrix2d& cov) {
  const double half_trace = 0.5 * (cov(0, 0) + cov(1, 1));
  const double half_diff = 0.5 * (cov(0, 0) - cov(1, 1));
  return std::max(0.0, half_trace - std::sqrt(half_diff * half_diff + cov(0, 1) * cov(0, 1)));
}

// The segment of `line` between the projections of the extreme points of
// `xs`/`ys` (n points) onto it.
LineSegment SegmentFromProjections(const FittedLine& line, const double* xs, const double* ys,
                                   std::size_t n);

// Euclidean distance from point (x, y) to a segment (cell units). Inline:
// nearest-segment queries call it for every candidate segment.
inline double PointSegmentDistance(double x, double y, const LineSegment& s) {
  const double dx = s.x2 - s.x1;
  const double dy = s.y2 - s.y1;
  const double length_sq = dx * dx + dy * dy;
  double t = 0;
  if (length_sq > 0) t = std::clamp(((x - s.x1) * dx + (y - s.y1) * dy) / length_sq, 0.0, 1.0);
  const double ex = x - (s.x1 + t * dx), ey = y - (s.y1 + t * dy);
  return std::sqrt(ex * ex + ey * ey);
}

}  // namespace linemap::lines_internal

#endif  // LINEMAP_CODEC_LINES_LINE_FIT_H_
