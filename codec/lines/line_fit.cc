// Total-least-squares fit for RM-Line (Liu & Zhang 2022, section 2.3,
// Eq. 3-4) and linemap's extractor.
//
// Eq. (3) gives the centroid (mu_x, mu_y) and the second moments mu_xx, mu_yy,
// mu_xy. Eq. (4) as printed is inconsistent: a = mu_xy / sqrt(mu_xx^2 +
// mu_yy^2) and b = -mu_xx / sqrt(mu_xx^2 + mu_xy^2) divide by two different
// norms, so (a, b) is not a unit normal, and the direction it implies,
// (mu_xx, mu_xy), is one power-iteration step from the x axis rather than the
// principal axis (for a vertical wall mu_xx = mu_xy = 0 and the line is
// undefined). We use what the equations evidently intend: the total-least-
// squares line through the centroid along the eigenvector of the largest
// eigenvalue of the 2x2 covariance [[mu_xx, mu_xy], [mu_xy, mu_yy]] (Eigen's
// closed-form self-adjoint solver), which minimises the sum of squared
// perpendicular distances.
#include "codec/lines/line_fit.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>

namespace linemap::lines_internal {

void PointMoments::Add(double x, double y) {
  if (!has_reference_) {
    has_reference_ = true;
    ref_x_ = x;
    ref_y_ = y;
  }
  const double dx = x - ref_x_;
  const double dy = y - ref_y_;
  ++count_;
  sx_ += dx;
  sy_ += dy;
  sxx_ += dx * dx;
  sxy_ += dx * dy;
  syy_ += dy * dy;
}

FittedLine PointMoments::Fit() const { return FitFromCovariance(Mean(), Covariance()); }

namespace {

// A canonical orientation (towards +x, or +y when vertical) makes results
// independent of the eigen solver's sign choice.
Eigen::Vector2d Canonical(const Eigen::Vector2d& direction) {
  if (direction.x() < -1e-12 || (std::abs(direction.x()) <= 1e-12 && direction.y() < 0)) {
    return -direction;
  }
  return direction;
}

}  // namespace

// The operations of Eigen's closed-form 2x2 solver
// (SelfAdjointEigenSolver::computeDirect, Eigen 3.4: shift by the mean
// eigenvalue, scale to [-1, 1], roots, then the principal axis from the
// shifted rows), in the same order, so the same bits as
// FitFromCovarianceReference; without the second axis and eigenvalue,
// which the fit never reads (the merge search fits a line per merge it
// tries, the chain split one per range it tests).
FittedLine FitFromCovariance(const Eigen::Vector2d& centroid, const Eigen::Matrix2d& covariance) {
  const double shift = (covariance(0, 0) + covariance(1, 1)) / 2.0;
  double a = covariance(0, 0) - shift;
  double b = covariance(1, 0);
  double c = covariance(1, 1) - shift;
  const double scale = std::max({std::abs(a), std::abs(b), std::abs(c)});
  if (scale > 0) {
    a /= scale;
    b /= scale;
    c /= scale;
  }
  const double t0 = 0.5 * std::sqrt((a - c) * (a - c) + 4.0 * (b * b));
  const double t1 = 0.5 * (a + c);
  const double low = t1 - t0, high = t1 + t0;
  Eigen::Vector2d axis(0, 1);
  if (high - low > std::abs(high) * std::numeric_limits<double>::epsilon()) {
    const double a_high = a - high, c_high = c - high;
    const double a2 = a_high * a_high, c2 = c_high * c_high, b2 = b * b;
    if (a2 > c2) {
      const double norm = std::sqrt(a2 + b2);
      axis = {-b / norm, a_high / norm};
    } else {
      const double norm = std::sqrt(c2 + b2);
      axis = {-c_high / norm, b / norm};
    }
  }
  FittedLine line;
  line.centroid = centroid;
  // Eigen's normalized(): divided by the norm when it is positive.
  const double norm_sq = axis.x() * axis.x() + axis.y() * axis.y();
  if (norm_sq > 0) axis /= std::sqrt(norm_sq);
  line.direction = Canonical(axis);
  line.mean_squared_residual = std::max(0.0, low * scale + shift);
  return line;
}

FittedLine FitFromCovarianceReference(const Eigen::Vector2d& centroid,
                                      const Eigen::Matrix2d& covariance) {
  FittedLine line;
  line.centroid = centroid;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> solver;
  solver.computeDirect(covariance);
  // Eigenvalues come in increasing order: column 1 is the principal axis.
  line.direction = Canonical(solver.eigenvectors().col(1).normalized());
  line.mean_squared_residual = std::max(0.0, solver.eigenvalues()(0));
  return line;
}

LineSegment SegmentFromProjections(const FittedLine& line, const double* xs, const double* ys,
                                   std::size_t n) {
  double t_min = std::numeric_limits<double>::infinity();
  double t_max = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < n; ++i) {
    const double t = (xs[i] - line.centroid.x()) * line.direction.x() +
                     (ys[i] - line.centroid.y()) * line.direction.y();
    t_min = std::min(t_min, t);
    t_max = std::max(t_max, t);
  }
  if (n == 0) t_min = t_max = 0;
  const Eigen::Vector2d a = line.centroid + t_min * line.direction;
  const Eigen::Vector2d b = line.centroid + t_max * line.direction;
  return {a.x(), a.y(), b.x(), b.y()};
}

}  // namespace linemap::lines_internal
