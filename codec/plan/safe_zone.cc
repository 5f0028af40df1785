// Stage 1 of the trajectory planner: the safe zone (Kosteley et al., section
// 3.2 D, Eq. 1 and Eq. 2; Table 1 stages 5 "safe zone template" and 6 "safe
// zone layout").
//
// Choice: the paper's template ("impassable area mask"), not a distance
// transform. The mask is built once per robot; per call, it is stamped only
// around obstacle cells that have a non-obstacle 4-neighbour. That is exact:
// if c is the obstacle cell nearest to a free cell p, the 4-neighbour of c
// one step towards p is nearer to p, so it is not an obstacle. The work per
// call is (boundary obstacle cells) x (mask cells), a few ms on the paper's
// 193x175 map even for large robots.
//
// Parameter: the mask radius is d_save / resolution in cells (Eq. 1, see
// SafeDistanceMetres); a free cell at a centre-to-centre distance <= d_save
// from an obstacle is unsafe ("within this circle"), farther is safe.
#include <algorithm>
#include <cmath>

#include "linemap/plan.h"

namespace linemap {
namespace {

// Float slack so that a radius of 0.15 m / 0.05 m = 2.9999999999999996
// cells still covers the cells at exactly 3 cells.
constexpr double kRadiusSlack = 1e-6;

bool IsObstacle(Cell cell) { return cell != Cell::kFree; }

bool TouchesNonObstacle(const Grid& grid, int col, int row) {
  static constexpr int kDx[4] = {1, -1, 0, 0};
  static constexpr int kDy[4] = {0, 0, 1, -1};
  for (int k = 0; k < 4; ++k) {
    const int c = col + kDx[k], r = row + kDy[k];
    if (grid.Contains(c, r) && !IsObstacle(grid.at(c, r))) return true;
  }
  return false;
}

// Clears the mask's disk around (col, row), one row span at a time.
void Stamp(const ImpassableAreaMask& mask, int col, int row, SafeZone* zone) {
  const int r0 = std::max(0, row - mask.reach), r1 = std::min(zone->height - 1, row + mask.reach);
  for (int r = r0; r <= r1; ++r) {
    const int half = mask.half_widths[r - row + mask.reach];
    const int c0 = std::max(0, col - half), c1 = std::min(zone->width - 1, col + half);
    if (c0 > c1) continue;
    std::uint8_t* line = zone->safe.data() + static_cast<std::size_t>(r) * zone->width;
    std::fill(line + c0, line + c1 + 1, std::uint8_t{0});
  }
}

// Cells within the radius of the virtual obstacle ring just outside the map
// (column -1, column width, row -1, row height).
void MarkBorder(double radius_cells, SafeZone* zone) {
  const int band = static_cast<int>(std::floor(radius_cells + kRadiusSlack));  // distance k+1 <= r
  for (int row = 0; row < zone->height; ++row) {
    for (int col = 0; col < zone->width; ++col) {
      const int edge = std::min({col, row, zone->width - 1 - col, zone->height - 1 - row});
      if (edge + 1 <= band) zone->safe[static_cast<std::size_t>(row) * zone->width + col] = 0;
    }
  }
}

}  // namespace

double SafeDistanceMetres(const RobotFootprint& robot) {
  return std::max(robot.width_m / 2.0, robot.length_m / 2.0) + robot.margin_m;
}

ImpassableAreaMask ImpassableAreaMask::Build(double radius_cells) {
  ImpassableAreaMask mask;
  mask.radius_cells = std::max(0.0, radius_cells);
  const double limit = mask.radius_cells * mask.radius_cells + kRadiusSlack;
  const int reach = static_cast<int>(std::floor(mask.radius_cells + kRadiusSlack));
  mask.reach = reach;
  mask.half_widths.assign(2 * reach + 1, 0);
  for (int dy = -reach; dy <= reach; ++dy) {
    for (int dx = -reach; dx <= reach; ++dx) {
      if (dx * dx + dy * dy <= limit) {
        mask.offsets.push_back({dx, dy});
        mask.half_widths[dy + reach] = std::max(mask.half_widths[dy + reach], dx);
      }
    }
  }
  return mask;
}

SafeZone ComputeSafeZone(const Grid& grid, const ImpassableAreaMask& mask) {
  SafeZone zone;
  zone.width = grid.width();
  zone.height = grid.height();
  zone.safe.resize(grid.size());
  for (std::size_t i = 0; i < grid.size(); ++i) zone.safe[i] = IsObstacle(grid.cells()[i]) ? 0 : 1;
  for (int row = 0; row < grid.height(); ++row) {
    for (int col = 0; col < grid.width(); ++col) {
      if (IsObstacle(grid.at(col, row)) && TouchesNonObstacle(grid, col, row)) {
        Stamp(mask, col, row, &zone);
      }
    }
  }
  MarkBorder(mask.radius_cells, &zone);
  return zone;
}

}  // namespace linemap
