#include <gtest/gtest.h>

#include "linemap/grid.h"
#include "linemap/lines.h"
#include "tests/codec/lines/test_maps.h"

namespace linemap {
namespace {

using testing::FillBox;
using testing::IsEdgeCell;

TEST(EdgeMapTest, MarksObstacleCellsFourAdjacentToFreeCells) {
  // 5 x 5, row 0 at the bottom:
  //   row 4: U U U U U
  //   row 3: U # # # U
  //   row 2: U # . # U
  //   row 1: U # # # U
  //   row 0: # U U U U
  Grid grid(5, 5, Cell::kUnknown);
  FillBox(&grid, 1, 1, 3, 3, Cell::kOccupied);
  grid.set(2, 2, Cell::kFree);
  grid.set(0, 0, Cell::kOccupied);
  const EdgeMap edges = ComputeEdgeMap(grid);
  // Only the four 4-neighbours of the single free cell are edge points: the
  // corners of the ring touch it diagonally only, and (0, 0) touches no free cell.
  EXPECT_EQ(edges.edge_count, 4u);
  EXPECT_TRUE(IsEdgeCell(edges, 1, 2));
  EXPECT_TRUE(IsEdgeCell(edges, 3, 2));
  EXPECT_TRUE(IsEdgeCell(edges, 2, 1));
  EXPECT_TRUE(IsEdgeCell(edges, 2, 3));
  EXPECT_FALSE(IsEdgeCell(edges, 1, 1));
  EXPECT_FALSE(IsEdgeCell(edges, 0, 0));
  EXPECT_FALSE(IsEdgeCell(edges, 2, 2));
}

TEST(EdgeMapTest, RobotPositionFloodsOnlyItsComponent) {
  // Two rooms side by side separated by a wall at col 5; the robot is in the left.
  Grid grid(11, 5, Cell::kOccupied);
  FillBox(&grid, 1, 1, 3, 3, Cell::kFree);
  FillBox(&grid, 7, 1, 9, 3, Cell::kFree);
  const EdgeMap left = ComputeEdgeMap(grid, CellPoint{2, 2});
  const EdgeMap all = ComputeEdgeMap(grid);
  // Each room's 3x3 interior has 12 obstacle cells 4-adjacent to it.
  EXPECT_EQ(left.edge_count, 12u);
  EXPECT_EQ(all.edge_count, 24u);
  EXPECT_TRUE(IsEdgeCell(left, 4, 2));
  EXPECT_FALSE(IsEdgeCell(left, 6, 2));
  EXPECT_TRUE(IsEdgeCell(all, 6, 2));
}

TEST(EdgeMapTest, RobotOnAnObstacleOrOffTheMapFloodsNothing) {
  Grid grid(4, 4, Cell::kFree);
  grid.set(0, 0, Cell::kOccupied);
  EXPECT_EQ(ComputeEdgeMap(grid, CellPoint{0, 0}).edge_count, 0u);
  EXPECT_EQ(ComputeEdgeMap(grid, CellPoint{-3, 1}).edge_count, 0u);
  EXPECT_EQ(ComputeEdgeMap(grid, CellPoint{1, 1}).edge_count, 1u);
}

TEST(EdgeMapTest, HugeSingleDomainNeedsNoRecursion) {
  // 4000 x 4000 free cells inside a one-cell obstacle frame: a recursive
  // flood would need a 16-million-deep stack.
  const int n = 4000;
  Grid grid(n, n, Cell::kOccupied);
  FillBox(&grid, 1, 1, n - 2, n - 2, Cell::kFree);
  const EdgeMap edges = ComputeEdgeMap(grid, CellPoint{n / 2.0, n / 2.0});
  // The frame minus its four corners.
  EXPECT_EQ(edges.edge_count, static_cast<std::size_t>(4 * (n - 2)));
}

TEST(EdgeMapTest, FloodingEveryComponentEqualsFloodingFromEachRobotCell) {
  // Without a robot position every free component is flooded; the union of
  // the floods from one free cell of each component must be the same map.
  Grid grid(12, 9, Cell::kUnknown);
  FillBox(&grid, 0, 0, 5, 8, Cell::kOccupied);
  FillBox(&grid, 1, 1, 4, 4, Cell::kFree);   // component A
  FillBox(&grid, 2, 6, 3, 7, Cell::kFree);   // component B
  FillBox(&grid, 7, 2, 10, 6, Cell::kFree);  // component C, unknown around
  grid.set(9, 4, Cell::kOccupied);
  const EdgeMap all = ComputeEdgeMap(grid);
  std::vector<std::uint8_t> united(grid.size(), 0);
  for (const CellPoint robot : {CellPoint{1, 1}, CellPoint{2, 6}, CellPoint{7, 2}}) {
    const EdgeMap one = ComputeEdgeMap(grid, robot);
    for (std::size_t i = 0; i < united.size(); ++i) united[i] |= one.is_edge[i];
  }
  EXPECT_EQ(all.is_edge, united);
  // By hand: A's ring 4 * 4 = 16; B adds cols 1 and 4 of rows 6-7 and row 8
  // cols 2-3 (its row 5 is A's top): 6; C's inner obstacle (9,4): 1.
  EXPECT_EQ(all.edge_count, 23u);
}

}  // namespace
}  // namespace linemap
