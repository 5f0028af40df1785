// Stage 4 of the trajectory planner: the neighbourhood template of straight
// moves (Kosteley et al., section 3.2 D; Table 1 stage 9 "neighbourhood
// template"), built once per robot: rays from the node, each the distinct
// cells it meets up to D_max.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

#include "codec/plan/turn_and_move_internal.h"
#include "linemap/plan.h"

namespace linemap {
namespace {

using plan_internal::Length;

// Largest D_max in cells the template accepts (memory ~ 2 pi D^2 offsets).
constexpr double kMaxTemplateRadius = 500.0;

// One ray of the first octant (0..45 degrees): the distinct rounded cells
// at steps of half a cell (each coordinate moves by at most 0.5 per step,
// so consecutive cells are 8-adjacent), up to the radius.
TemplateRay OctantRay(double angle_rad, double radius) {
  TemplateRay ray;
  ray.angle_rad = angle_rad;
  const double cx = std::cos(angle_rad), cy = std::sin(angle_rad);
  const double limit = radius * radius + 1e-6;
  const int steps = static_cast<int>(2.0 * radius) + 1;
  ray.cells.reserve(steps);
  ray.lengths.reserve(steps);
  for (int k = 1; k <= steps; ++k) {
    const double t = 0.5 * k;
    const int dx = static_cast<int>(std::lround(t * cx));
    const int dy = static_cast<int>(std::lround(t * cy));
    if ((dx == 0 && dy == 0) ||
        static_cast<double>(dx) * dx + static_cast<double>(dy) * dy > limit) {
      continue;
    }
    if (!ray.cells.empty() && ray.cells.back() == CellOffset{dx, dy}) continue;
    ray.cells.push_back({dx, dy});
    ray.lengths.push_back(static_cast<float>(Length(dx, dy)));
  }
  return ray;
}

// The octant's symmetry that maps first-octant offsets to octant `octant`
// (counter-clockwise from +x); odd octants mirror the angle within it.
CellOffset ToOctant(CellOffset o, int octant) {
  switch (octant) {
    case 0:
      return {o.dx, o.dy};
    case 1:
      return {o.dy, o.dx};
    case 2:
      return {-o.dy, o.dx};
    case 3:
      return {-o.dx, o.dy};
    case 4:
      return {-o.dx, -o.dy};
    case 5:
      return {-o.dy, -o.dx};
    case 6:
      return {o.dy, -o.dx};
    default:
      return {o.dx, -o.dy};
  }
}

}  // namespace

MoveTemplate MoveTemplate::Build(double d_max_cells) {
  MoveTemplate moves;
  moves.d_max_cells = std::clamp(d_max_cells, 1.0, kMaxTemplateRadius);
  const double radius = moves.d_max_cells;
  // Angular step <= 1 / D_max: neighbouring rays are <= 1 cell apart at D_max.
  const int per_octant =
      std::max(1, static_cast<int>(std::ceil(2.0 * std::numbers::pi * radius / 8.0)));
  const int ray_count = 8 * per_octant;
  const double step = 2.0 * std::numbers::pi / ray_count;
  // Rays of the first octant, 0..45 degrees inclusive; the others are its
  // mirror images, which keeps the template exactly symmetric and is 8 times
  // cheaper than rounding every ray.
  std::vector<TemplateRay> base;
  for (int j = 0; j <= per_octant; ++j) base.push_back(OctantRay(step * j, radius));
  moves.rays.reserve(ray_count);
  for (int i = 0; i < ray_count; ++i) {
    const int octant = i / per_octant, j = i % per_octant;
    const TemplateRay& from = base[octant % 2 == 0 ? j : per_octant - j];
    TemplateRay ray;
    ray.angle_rad = step * i;
    ray.lengths = from.lengths;
    ray.cells.reserve(from.cells.size());
    for (const CellOffset& o : from.cells) ray.cells.push_back(ToOctant(o, octant));
    moves.cell_count += ray.cells.size();
    moves.rays.push_back(std::move(ray));
  }
  return moves;
}

}  // namespace linemap
