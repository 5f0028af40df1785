#include "linemap/segmentation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <set>
#include <utility>

#include "linemap/map_io.h"
#include "tests/testing/reference_components.h"
#include "tests/testing/test_support.h"

namespace linemap {
namespace {

void Fill(Grid* grid, int c0, int r0, int c1, int r1, Cell value) {
  for (int r = r0; r <= r1; ++r) {
    for (int c = c0; c <= c1; ++c) grid->set(c, r, value);
  }
}

// A 50 x 30 room (cols 5..54, rows 5..34) walled in, inside unknown space,
// with a table (6 x 4 = 24 cells), a shelf (2 x 9 = 18 cells), a hollow
// pillar (5 x 5 ring = 16 cells, unknown inside) and a surge: a 2-cell wide
// streak of free cells leaking out through a gap in the top wall up to row 46.
Grid SyntheticRoom() {
  Grid grid(60, 52, Cell::kUnknown);
  Fill(&grid, 4, 4, 55, 35, Cell::kOccupied);
  Fill(&grid, 5, 5, 54, 34, Cell::kFree);
  Fill(&grid, 28, 35, 29, 46, Cell::kFree);      // the surge
  Fill(&grid, 12, 10, 17, 13, Cell::kOccupied);  // table
  Fill(&grid, 40, 18, 41, 26, Cell::kOccupied);  // shelf
  Fill(&grid, 25, 15, 29, 19, Cell::kOccupied);  // pillar
  Fill(&grid, 26, 16, 28, 18, Cell::kUnknown);
  return grid;
}

// These tests cover the paper's method; the default (rooms split at
// doorways) is tested in rooms_test.cc.
SegmentationOptions Paper() {
  SegmentationOptions options;
  options.method = SegmentationMethod::kPaperBorder;
  return options;
}

void ExpectClosedChain(const std::vector<CellIndex>& chain, const std::string& what) {
  ASSERT_GE(chain.size(), 1u) << what;
  for (std::size_t i = 0; i < chain.size() && chain.size() > 1; ++i) {
    const CellIndex& a = chain[i];
    const CellIndex& b = chain[(i + 1) % chain.size()];
    ASSERT_EQ(std::max(std::abs(a.col - b.col), std::abs(a.row - b.row)), 1)
        << what << ": cells " << i << " and " << (i + 1) % chain.size() << " not 8-adjacent";
  }
}

// Independent even-odd test, counting crossings of a ray towards +col.
bool InsideByRay(const std::vector<CellIndex>& chain, double col, double row) {
  int crossings = 0;
  for (std::size_t i = 0; i < chain.size(); ++i) {
    const CellIndex& a = chain[i];
    const CellIndex& b = chain[(i + 1) % chain.size()];
    const bool a_above = a.row > row, b_above = b.row > row;
    if (a_above == b_above) continue;
    const double t = (row - a.row) / static_cast<double>(b.row - a.row);
    if (a.col + t * (b.col - a.col) > col) ++crossings;
  }
  return crossings % 2 == 1;
}

TEST(FillChainPolygonTest, MatchesRayTestOnHandShapes) {
  // A square ring (2,2)-(6,6) and an L shape, listed cell by cell.
  std::vector<CellIndex> square;
  for (int c = 2; c <= 6; ++c) square.push_back({c, 2});
  for (int r = 3; r <= 6; ++r) square.push_back({6, r});
  for (int c = 5; c >= 2; --c) square.push_back({c, 6});
  for (int r = 5; r >= 3; --r) square.push_back({2, r});
  const BinaryMask fill = FillChainPolygon(square, 10, 10);
  EXPECT_EQ(fill.Count(), 25u);
  EXPECT_TRUE(fill.at(4, 4));
  EXPECT_FALSE(fill.at(7, 4));
  const std::vector<CellIndex> ell = {{0, 0}, {1, 0}, {2, 0}, {3, 0}, {4, 0}, {4, 1}, {3, 2},
                                      {2, 3}, {1, 4}, {0, 4}, {0, 3}, {0, 2}, {0, 1}};
  const BinaryMask ell_fill = FillChainPolygon(ell, 6, 6);
  std::set<std::pair<int, int>> on_chain;
  for (const CellIndex& c : ell) on_chain.insert({c.col, c.row});
  for (int r = 0; r < 6; ++r) {
    for (int c = 0; c < 6; ++c) {
      // Off-grid-line sample points avoid the ray test's vertex ambiguity;
      // a cell centre strictly inside has all four nearby samples inside.
      const bool want = on_chain.count({c, r}) || (InsideByRay(ell, c + 0.01, r + 0.01) &&
                                                   InsideByRay(ell, c - 0.01, r - 0.01));
      EXPECT_EQ(ell_fill.at(c, r), want) << c << "," << r;
    }
  }
}

TEST(SegmentationTest, SyntheticRoomWithFurniturePillarAndSurge) {
  const Grid grid = SyntheticRoom();
  StatusOr<Segmentation> seg = SegmentMap(grid, Paper());
  ASSERT_TRUE(seg.ok()) << seg.status().message();
  ASSERT_EQ(seg->rooms.size(), 1u);
  const RoomBorder& room = seg->rooms[0];
  ExpectClosedChain(room.chain, "room");
  EXPECT_TRUE(room.closed_by_lee);
  // The pillar and the furniture are inside M_H, so the heavy border is one
  // ring, and the paper's mid-line rule calls it a room border.
  EXPECT_EQ(room.border_components, 1);
  EXPECT_EQ(room.ring_components, 1);
  EXPECT_EQ(room.free_cells, 50u * 30u - 24u - 18u - 25u + 2u * 12u);
  // The surge is cut off: the chain stays near the top wall (row 35) and the
  // far part of the streak (rows 40..46) is outside the polygon.
  for (const CellIndex& cell : room.chain) {
    EXPECT_LE(cell.row, 38) << cell.col << "," << cell.row;
    EXPECT_TRUE(grid.Contains(cell.col, cell.row));
  }
  for (int r = 40; r <= 46; ++r) {
    EXPECT_FALSE(InsideByRay(room.chain, 28.01, r + 0.01)) << "surge row " << r;
  }
  // The room itself and its furniture are inside.
  for (const auto& [c, r] :
       std::vector<std::pair<int, int>>{{5, 5}, {54, 34}, {14, 11}, {27, 17}}) {
    EXPECT_TRUE(InsideByRay(room.chain, c + 0.01, r + 0.01)) << c << "," << r;
  }
  // Three blobs with their exact cells.
  ASSERT_EQ(seg->blobs.size(), 3u);
  std::vector<std::size_t> counts;
  for (const FurnitureBlob& blob : seg->blobs) {
    counts.push_back(blob.cell_count);
    EXPECT_EQ(blob.cells.size(), blob.cell_count);
    EXPECT_EQ(blob.first_cell, blob.cells.front());
    ExpectClosedChain(blob.outline, "blob outline");
    for (const CellIndex& cell : blob.cells) {
      EXPECT_EQ(grid.at(cell.col, cell.row), Cell::kOccupied);
    }
  }
  std::sort(counts.begin(), counts.end());
  EXPECT_EQ(counts, (std::vector<std::size_t>{16, 18, 24}));
  // The blobs come in the raster order of their first cells.
  EXPECT_EQ(seg->blobs[0].first_cell, (CellIndex{12, 10}));
  EXPECT_EQ(seg->blobs[0].box, (BoundingBox{12, 10, 17, 13}));
  EXPECT_EQ(seg->blobs[1].first_cell, (CellIndex{25, 15}));
  EXPECT_EQ(seg->blobs[2].first_cell, (CellIndex{40, 18}));
}

TEST(SegmentationTest, PaperBorderAlsoCutsTheSurge) {
  SegmentationOptions options = Paper();
  options.protect_room_interior = false;
  options.robot = CellPoint{30, 20};
  StatusOr<Segmentation> seg = SegmentMap(SyntheticRoom(), options);
  ASSERT_TRUE(seg.ok());
  ASSERT_EQ(seg->rooms.size(), 1u);
  ExpectClosedChain(seg->rooms[0].chain, "room");
  EXPECT_TRUE(seg->rooms[0].closed_by_lee);
  for (const CellIndex& cell : seg->rooms[0].chain) EXPECT_LE(cell.row, 38);
  EXPECT_EQ(seg->blobs.size(), 3u);
}

TEST(SegmentationTest, RobotPicksItsRoom) {
  Grid grid(70, 30, Cell::kUnknown);
  Fill(&grid, 2, 2, 30, 27, Cell::kOccupied);
  Fill(&grid, 3, 3, 29, 26, Cell::kFree);
  Fill(&grid, 38, 2, 67, 27, Cell::kOccupied);
  Fill(&grid, 39, 3, 66, 26, Cell::kFree);
  StatusOr<Segmentation> both = SegmentMap(grid, Paper());
  ASSERT_TRUE(both.ok());
  EXPECT_EQ(both->rooms.size(), 2u);
  SegmentationOptions options = Paper();
  options.robot = CellPoint{50.2, 10.0};
  StatusOr<Segmentation> one = SegmentMap(grid, options);
  ASSERT_TRUE(one.ok());
  ASSERT_EQ(one->rooms.size(), 1u);
  EXPECT_EQ(one->rooms[0].free_cells, 28u * 24u);
  ExpectClosedChain(one->rooms[0].chain, "room");
  for (const CellIndex& cell : one->rooms[0].chain) EXPECT_GE(cell.col, 34);
  options.robot = CellPoint{34, 15};  // in the unknown gap, > 3 cells from free
  EXPECT_FALSE(SegmentMap(grid, options).ok());
  options.robot = CellPoint{-5, 15};
  EXPECT_FALSE(SegmentMap(grid, options).ok());
  options.robot = CellPoint{std::nan(""), 15};
  EXPECT_FALSE(SegmentMap(grid, options).ok());
  options.robot = CellPoint{1e300, 15};
  EXPECT_FALSE(SegmentMap(grid, options).ok());
}

// A robot exactly on the map's lower edge (cell units -0.5) is in cell 0, as
// the edge map and the line extractor have it; the error for a robot off the
// map gives the position in metres.
TEST(SegmentationTest, RobotOnTheLowerEdgeIsOnTheMap) {
  Grid grid(30, 20, Cell::kFree);
  grid.meta.resolution = 0.1;
  grid.meta.origin = {2.0, -1.0, 0.0};
  SegmentationOptions options = Paper();
  options.robot = CellPoint{-0.5, -0.5};
  StatusOr<Segmentation> seg = SegmentMap(grid, options);
  ASSERT_TRUE(seg.ok()) << seg.status().message();
  EXPECT_EQ(seg->rooms.size(), 1u);
  options.robot = CellPoint{29.5, 10};  // the upper edge is the next cell's
  StatusOr<Segmentation> off = SegmentMap(grid, options);
  ASSERT_FALSE(off.ok());
  EXPECT_NE(off.status().message().find("robot position 5.000,0.050 m is outside the map"),
            std::string::npos)
      << off.status().message();
}

TEST(SegmentationTest, EmptyAndUnknownGridsHaveNoRooms) {
  for (const Grid& grid : {Grid(), Grid(20, 10, Cell::kUnknown), Grid(20, 10, Cell::kOccupied)}) {
    StatusOr<Segmentation> seg = SegmentMap(grid, Paper());
    ASSERT_TRUE(seg.ok());
    EXPECT_TRUE(seg->rooms.empty());
    EXPECT_TRUE(seg->blobs.empty());
  }
}

TEST(SegmentationTest, RoomFillingTheWholeMapFollowsTheMapEdge) {
  Grid grid(40, 30, Cell::kFree);
  Fill(&grid, 10, 10, 12, 12, Cell::kOccupied);  // one 3 x 3 blob
  StatusOr<Segmentation> seg = SegmentMap(grid, Paper());
  ASSERT_TRUE(seg.ok());
  ASSERT_EQ(seg->rooms.size(), 1u);
  const RoomBorder& room = seg->rooms[0];
  ExpectClosedChain(room.chain, "room");
  // The 8-connected shortest path steps diagonally past the four corner
  // cells; everything else is enclosed.
  EXPECT_EQ(room.free_cells, 40u * 30u - 9u);
  EXPECT_EQ(room.enclosed_free_cells, room.free_cells - 4u);
  EXPECT_EQ(room.chain.size(), 2u * (40u + 30u) - 8u);
  for (const CellIndex& cell : room.chain) {
    EXPECT_TRUE(cell.col == 0 || cell.row == 0 || cell.col == 39 || cell.row == 29)
        << cell.col << "," << cell.row;
  }
  ASSERT_EQ(seg->blobs.size(), 1u);
  EXPECT_EQ(seg->blobs[0].cell_count, 9u);
  EXPECT_EQ(seg->blobs[0].outline.size(), 8u);  // the ring around the centre cell
}

TEST(SegmentationTest, BorderWithoutInsideFallsBackToTheOuterContour) {
  // A lone streak of free cells in unknown space: the heavy border covers it
  // completely, no cut row switches into room space, so the chain is the
  // outer contour of D (here rows 7..13 around the streak on row 10).
  Grid grid(40, 21, Cell::kUnknown);
  Fill(&grid, 10, 10, 29, 10, Cell::kFree);
  StatusOr<Segmentation> seg = SegmentMap(grid, Paper());
  ASSERT_TRUE(seg.ok());
  ASSERT_EQ(seg->rooms.size(), 1u);
  const RoomBorder& room = seg->rooms[0];
  EXPECT_FALSE(room.closed_by_lee);
  ExpectClosedChain(room.chain, "fallback");
  EXPECT_EQ(room.enclosed_free_cells, 20u);
  int min_row = 99, max_row = -1;
  for (const CellIndex& cell : room.chain) {
    min_row = std::min(min_row, cell.row);
    max_row = std::max(max_row, cell.row);
  }
  EXPECT_EQ(min_row, 7);
  EXPECT_EQ(max_row, 13);
}

TEST(SegmentationTest, RejectsEvenStructuringElements) {
  SegmentationOptions options = Paper();
  StructuringElement even;
  even.width = 2;
  even.height = 2;
  even.on = {1, 1, 1, 1};
  options.border_erode = {even};
  EXPECT_FALSE(SegmentMap(SyntheticRoom(), options).ok());
}

// Largest 4-connected free component, by a plain flood fill.
std::vector<std::uint8_t> LargestFreeComponent(const Grid& grid) {
  const testing::FreeComponents components = testing::FreeComponentsByFloodFill(grid);
  const std::vector<int>& id = components.id;
  const std::vector<std::size_t>& sizes = components.sizes;
  const int best = static_cast<int>(std::max_element(sizes.begin(), sizes.end()) - sizes.begin());
  std::vector<std::uint8_t> mask(grid.size(), 0);
  for (std::size_t i = 0; i < mask.size(); ++i) mask[i] = best > 0 && id[i] == best;
  return mask;
}

TEST(SegmentationTest, EveryRoomChainClosedOnSharedMaps) {
  const std::string dir = testing::SharedMapsDir();
  if (dir.empty()) GTEST_SKIP() << "../shared/maps is absent";
  std::vector<std::string> maps = testing::FindYamlFiles(dir);
  for (const std::string& image : testing::FindBareImages(dir)) maps.push_back(image);
  int checked = 0;
  for (const std::string& path : maps) {
    StatusOr<Grid> grid = LoadRosMap(path);
    if (!grid.ok()) continue;  // e.g. a YAML naming an image that is not there
    StatusOr<Segmentation> seg = SegmentMap(*grid, Paper());
    ASSERT_TRUE(seg.ok()) << path << ": " << seg.status().message();
    ASSERT_FALSE(seg->rooms.empty()) << path;
    for (const RoomBorder& room : seg->rooms) {
      ExpectClosedChain(room.chain, path);
      EXPECT_TRUE(room.closed_by_lee) << path << ": fell back to the outer contour";
      for (const CellIndex& cell : room.chain) {
        ASSERT_TRUE(grid->Contains(cell.col, cell.row)) << path;
      }
    }
    std::vector<std::uint8_t> taken(grid->size(), 0);
    for (const FurnitureBlob& blob : seg->blobs) {
      ExpectClosedChain(blob.outline, path);
      ASSERT_EQ(blob.cells.size(), blob.cell_count) << path;
      for (const CellIndex& cell : blob.cells) {
        ASSERT_EQ(grid->at(cell.col, cell.row), Cell::kOccupied) << path;
        ASSERT_FALSE(taken[grid->Index(cell.col, cell.row)]) << path << ": blobs overlap";
        taken[grid->Index(cell.col, cell.row)] = 1;
      }
    }
    const std::vector<std::uint8_t> largest = LargestFreeComponent(*grid);
    const BinaryMask fill = FillChainPolygon(seg->rooms[0].chain, grid->width(), grid->height());
    std::size_t total = 0, enclosed = 0;
    for (std::size_t i = 0; i < largest.size(); ++i) {
      total += largest[i];
      enclosed += largest[i] && fill.bits[i];
    }
    const double share = total ? static_cast<double>(enclosed) / total : 1.0;
    std::printf("[ enclosure] %-60s %6.2f%% of %zu cells%s\n", path.c_str() + dir.size(),
                100.0 * share, total, seg->rooms[0].closed_by_lee ? "" : " (fallback contour)");
    EXPECT_GE(share, 0.95) << path;
    ++checked;
  }
  EXPECT_GT(checked, 0);
}

}  // namespace
}  // namespace linemap
