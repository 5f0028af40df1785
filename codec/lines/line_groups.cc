// Fitting a group's line and segment to its cells (steps 3 and 4 of
// linemap's extractor).
#include "codec/lines/line_groups.h"

#include <cmath>
#include <limits>
#include <vector>

namespace linemap::lines_internal {

bool SweepCells(const FittedLine& line, const std::vector<CellXY>& cells, double epsilon,
                double max_cost, LineSweep* sweep) {
  const Eigen::Vector2d& c = line.centroid;
  const Eigen::Vector2d& u = line.direction;
  for (const CellXY& cell : cells) {
    const double dx = cell.col - c.x(), dy = cell.row - c.y();
    const double d = std::abs(-u.y() * dx + u.x() * dy);
    sweep->cost += d;
    if (d > epsilon + kRoundingSlack || sweep->cost > max_cost) return false;
    sweep->worst = MaxOf(sweep->worst, d);
    const double t = u.x() * dx + u.y() * dy;
    sweep->t_min = sweep->any ? MinOf(sweep->t_min, t) : t;
    sweep->t_max = sweep->any ? MaxOf(sweep->t_max, t) : t;
    sweep->any = true;
  }
  return true;
}

void SetLine(Group* group, const FittedLine& line, const LineSweep& sweep) {
  const Eigen::Vector2d& c = line.centroid;
  const Eigen::Vector2d& u = line.direction;
  group->line = line;
  group->max_residual = sweep.worst;
  group->cost = sweep.cost;
  group->segment = {c.x() + sweep.t_min * u.x(), c.y() + sweep.t_min * u.y(),
                    c.x() + sweep.t_max * u.x(), c.y() + sweep.t_max * u.y()};
}

bool RefitGroup(Group* group, double epsilon) {
  const FittedLine line = group->moments.Fit();
  if (line.mean_squared_residual > epsilon * epsilon + kRoundingSlack) return false;
  LineSweep sweep;
  if (!SweepCells(line, group->cells, epsilon, std::numeric_limits<double>::infinity(), &sweep)) {
    return false;
  }
  SetLine(group, line, sweep);
  return true;
}

}  // namespace linemap::lines_internal
