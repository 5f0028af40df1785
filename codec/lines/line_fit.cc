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

FittedLine FitFromCovariance(const Eigen::Vector2d& centroid, const Eigen::Matrix2d& covariance) {
  FittedLine line;
  line.centroid = centroid;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> solver;
  solver.computeDirect(covariance);
  // Eigenvalues come in increasing order: column 1 is the principal axis.
  line.direction = solver.eigenvectors().col(1).normalized();
  line.mean_squared_residual = std::max(0.0, solver.eigenvalues()(0));
  // A canonical orientation (towards +x, or +y when vertical) makes results
  // independent of the eigen solver's sign choice.
  if (line.direction.x() < -1e-12 ||
      (std::abs(line.direction.x()) <= 1e-12 && line.direction.y() < 0)) {
    line.direction = -line.direction;
  }
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
