#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <set>
#include <utility>
#include <vector>

#include "linemap/plan.h"

namespace linemap {
namespace {

TEST(MoveTemplateTest, RaysCoverTheDisk) {
  const MoveTemplate moves = MoveTemplate::Build(10.0);
  EXPECT_EQ(moves.rays.size() % 8, 0u);
  EXPECT_GE(moves.rays.size(), 63u);  // angular step <= 1 / D_max
  const std::vector<CellOffset> east = {{1, 0}, {2, 0}, {3, 0}, {4, 0}, {5, 0},
                                        {6, 0}, {7, 0}, {8, 0}, {9, 0}, {10, 0}};
  EXPECT_EQ(moves.rays[0].cells, east);
  std::set<std::pair<int, int>> seen;
  for (const TemplateRay& ray : moves.rays) {
    for (std::size_t k = 0; k < ray.cells.size(); ++k) {
      seen.insert({ray.cells[k].dx, ray.cells[k].dy});
      EXPECT_LE(std::hypot(ray.cells[k].dx, ray.cells[k].dy), 10.0 + 1e-9);
      if (k > 0) {  // consecutive cells are 8-adjacent
        EXPECT_LE(std::abs(ray.cells[k].dx - ray.cells[k - 1].dx), 1);
        EXPECT_LE(std::abs(ray.cells[k].dy - ray.cells[k - 1].dy), 1);
      }
    }
  }
  for (int dy = -10; dy <= 10; ++dy) {
    for (int dx = -10; dx <= 10; ++dx) {
      if ((dx || dy) && dx * dx + dy * dy <= 100) {
        EXPECT_TRUE(seen.count({dx, dy})) << dx << "," << dy;
      }
    }
  }
}

}  // namespace
}  // namespace linemap
