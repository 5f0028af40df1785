// Steps 7 and 8 of linemap's extractor: L1 polish of each line, corners.
#include "codec/lines/polish_and_corners.h"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>
#include <utility>
#include <vector>

#include "codec/lines/line_fit.h"

namespace linemap::lines_internal {

void PolishGroupL1(Group* group, double epsilon, PolishScratch* scratch) {
  const std::size_t n = group->cells.size();
  if (n < 3) return;
  std::vector<double>& xs = scratch->xs;
  std::vector<double>& ys = scratch->ys;
  std::vector<double>& w = scratch->w;
  xs.resize(n);
  ys.resize(n);
  w.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const CellXY& c = group->cells[i];
    xs[i] = c.col;
    ys[i] = c.row;
  }
  auto evaluate = [&](const FittedLine& line, double* sum, double* worst) {
    *sum = 0;
    *worst = 0;
    const double nx = -line.direction.y(), ny = line.direction.x();
    for (std::size_t i = 0; i < n; ++i) {
      const double d =
          std::abs((xs[i] - line.centroid.x()) * nx + (ys[i] - line.centroid.y()) * ny);
      *sum += d;
      *worst = std::max(*worst, d);
    }
  };
  FittedLine best = group->line;
  double best_sum = 0, worst = 0;
  evaluate(best, &best_sum, &worst);
  if (worst > epsilon + kRoundingSlack) return;  // cells handed over off the line's end
  for (int iteration = 0; iteration < 8; ++iteration) {
    const double nx = -best.direction.y(), ny = best.direction.x();
    double sw = 0, sx = 0, sy = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const double d =
          std::abs((xs[i] - best.centroid.x()) * nx + (ys[i] - best.centroid.y()) * ny);
      w[i] = 1.0 / std::max(d, 0.1);
      sw += w[i];
      sx += w[i] * xs[i];
      sy += w[i] * ys[i];
    }
    const Eigen::Vector2d mean(sx / sw, sy / sw);
    Eigen::Matrix2d cov = Eigen::Matrix2d::Zero();
    for (std::size_t i = 0; i < n; ++i) {
      const double dx = xs[i] - mean.x(), dy = ys[i] - mean.y();
      cov(0, 0) += w[i] * dx * dx;
      cov(0, 1) += w[i] * dx * dy;
      cov(1, 1) += w[i] * dy * dy;
    }
    cov(1, 0) = cov(0, 1);
    const FittedLine candidate = FitFromCovariance(mean, cov / sw);
    double sum = 0;
    evaluate(candidate, &sum, &worst);
    if (worst > epsilon + kRoundingSlack || sum >= best_sum - 1e-9) break;
    best = candidate;
    best_sum = sum;
  }
  group->line = best;
  group->cost = best_sum;
  group->segment = SegmentFromProjections(best, xs.data(), ys.data(), n);
}

void JoinCorners(std::vector<LineSegment>* segments, int width, int height, double reach) {
  constexpr int kTile = 8;
  const int tiles_x = std::max(1, (width + kTile - 1) / kTile);
  const int tiles_y = std::max(1, (height + kTile - 1) / kTile);
  auto tile_of = [&](double x, double y) {
    const int tx = std::clamp(static_cast<int>(std::floor((x + 0.5) / kTile)), 0, tiles_x - 1);
    const int ty = std::clamp(static_cast<int>(std::floor((y + 0.5) / kTile)), 0, tiles_y - 1);
    return std::pair<int, int>(tx, ty);
  };
  // Ends: 2 * id + (0 for (x1, y1), 1 for (x2, y2)), bucketed by tile in
  // increasing order (a counting sort: tile t's ends are
  // ends[tile_begin[t], tile_begin[t + 1])).
  auto end_point = [&](std::uint32_t end) {
    const LineSegment& s = (*segments)[end / 2];
    return (end % 2 == 0) ? Eigen::Vector2d(s.x1, s.y1) : Eigen::Vector2d(s.x2, s.y2);
  };
  const std::uint32_t end_count = static_cast<std::uint32_t>(2 * segments->size());
  std::vector<std::uint32_t> tile_of_end(end_count);
  std::vector<std::uint32_t> tile_begin(static_cast<std::size_t>(tiles_x) * tiles_y + 1, 0);
  for (std::uint32_t end = 0; end < end_count; ++end) {
    const Eigen::Vector2d p = end_point(end);
    const auto [tx, ty] = tile_of(p.x(), p.y());
    tile_of_end[end] = static_cast<std::uint32_t>(ty) * tiles_x + tx;
    ++tile_begin[tile_of_end[end] + 1];
  }
  for (std::size_t t = 1; t < tile_begin.size(); ++t) tile_begin[t] += tile_begin[t - 1];
  std::vector<std::uint32_t> ends(end_count);
  {
    std::vector<std::uint32_t> fill(tile_begin.begin(), tile_begin.end() - 1);
    for (std::uint32_t end = 0; end < end_count; ++end) ends[fill[tile_of_end[end]]++] = end;
  }
  std::vector<std::uint8_t> joined(2 * segments->size(), 0);
  const double min_sine = std::sin(20.0 * std::numbers::pi / 180.0);
  for (std::uint32_t end = 0; end < 2 * segments->size(); ++end) {
    if (joined[end]) continue;
    const Eigen::Vector2d p = end_point(end);
    const auto [tx0, ty0] = tile_of(p.x() - reach, p.y() - reach);
    const auto [tx1, ty1] = tile_of(p.x() + reach, p.y() + reach);
    for (int ty = ty0; ty <= ty1 && !joined[end]; ++ty) {
      for (int tx = tx0; tx <= tx1 && !joined[end]; ++tx) {
        const std::size_t tile = static_cast<std::size_t>(ty) * tiles_x + tx;
        for (std::uint32_t k = tile_begin[tile]; k < tile_begin[tile + 1]; ++k) {
          const std::uint32_t other = ends[k];
          if (other / 2 == end / 2 || joined[other]) continue;
          const Eigen::Vector2d q = end_point(other);
          if ((p - q).norm() > reach) continue;
          // Directions pointing outwards from each end.
          const Eigen::Vector2d u = p - end_point(end ^ 1u);
          const Eigen::Vector2d v = q - end_point(other ^ 1u);
          if (u.norm() <= 0 || v.norm() <= 0) continue;
          const Eigen::Vector2d du = u.normalized(), dv = v.normalized();
          const double cross = du.x() * dv.y() - du.y() * dv.x();
          if (std::abs(cross) < min_sine) continue;
          // p + a * du = q + b * dv.
          const Eigen::Vector2d w = q - p;
          const double a = (w.x() * dv.y() - w.y() * dv.x()) / cross;
          const double b = (w.x() * du.y() - w.y() * du.x()) / cross;
          if (a < 0 || b < 0 || a > reach || b > reach) continue;
          const Eigen::Vector2d corner = p + a * du;
          for (std::uint32_t e : {end, other}) {
            LineSegment& s = (*segments)[e / 2];
            (e % 2 == 0 ? s.x1 : s.x2) = corner.x();
            (e % 2 == 0 ? s.y1 : s.y2) = corner.y();
            joined[e] = 1;
          }
          break;
        }
      }
    }
  }
}

}  // namespace linemap::lines_internal
