// Furniture of SegmentMap() (method kRooms): cabinets against walls cut
// from the wall along its face, free-standing pieces grouped without the
// scan specks around them. Checked against the ground truth of generated
// floor plans (tests/testing/floor_plan.h: every cabinet's cells are known)
// and against hand-built rooms, with plain reference code written here (an
// even-odd ray test for "crosses a chain", neighbour checks for "stands
// against a wall").
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "linemap/map_io.h"
#include "linemap/segmentation.h"
#include "tests/testing/floor_plan.h"
#include "tests/testing/reference_geometry.h"
#include "tests/testing/test_support.h"

namespace linemap {
namespace {

void Fill(Grid* grid, int c0, int r0, int c1, int r1, Cell value) {
  for (int r = r0; r <= r1; ++r) {
    for (int c = c0; c <= c1; ++c) grid->set(c, r, value);
  }
}

// Even-odd test of the cell centre (col, row) against the polygon through
// the chain's cell centres, by a ray towards +col; half-open on rows.
bool InsideChain(const std::vector<CellIndex>& chain, int col, int row) {
  bool inside = false;
  for (std::size_t i = 0, j = chain.size() - 1; i < chain.size(); j = i++) {
    const CellIndex& a = chain[i];
    const CellIndex& b = chain[j];
    if ((a.row > row) == (b.row > row)) continue;
    const double x = a.col + static_cast<double>(row - a.row) * (b.col - a.col) / (b.row - a.row);
    if (x > col) inside = !inside;
  }
  return inside;
}

// The furniture promises, on any grid:
//  - blob cells are occupied in the input, none on a room chain;
//  - no blob crosses a chain: all its cells are on one side of each chain;
//  - free-standing: cells in the blob's room, none 8-adjacent to a chain;
//  - against a wall: cells in no room, 4-adjacent to a blocked cell in no
//    room and no blob (the wall), 4-adjacent to a cell of its room.
void ExpectFurnitureInvariants(const Grid& grid, const Segmentation& seg, const std::string& what) {
  std::vector<int> chain_of(grid.size(), 0);
  std::vector<BoundingBox> chain_box;
  for (const RoomBorder& room : seg.rooms) {
    BoundingBox box{grid.width(), grid.height(), -1, -1};
    for (const CellIndex& cell : room.chain) {
      chain_of[grid.Index(cell.col, cell.row)] = room.id;
      box.min_col = std::min(box.min_col, cell.col);
      box.max_col = std::max(box.max_col, cell.col);
      box.min_row = std::min(box.min_row, cell.row);
      box.max_row = std::max(box.max_row, cell.row);
    }
    chain_box.push_back(box);
  }
  std::vector<std::uint8_t> in_blob(grid.size(), 0);
  for (const FurnitureBlob& blob : seg.blobs) {
    for (const CellIndex& cell : blob.cells) in_blob[grid.Index(cell.col, cell.row)] = 1;
  }
  for (const FurnitureBlob& blob : seg.blobs) {
    ASSERT_GT(blob.room, 0) << what;
    ASSERT_FALSE(blob.cells.empty()) << what;
    for (const CellIndex& cell : blob.cells) {
      const std::size_t i = grid.Index(cell.col, cell.row);
      ASSERT_EQ(grid.cells()[i], Cell::kOccupied) << what;
      ASSERT_EQ(chain_of[i], 0) << what << ": furniture on a chain at " << cell.col << ","
                                << cell.row;
      ASSERT_EQ(seg.room_of_cell[i], blob.against_wall ? 0 : blob.room) << what;
    }
    // The outline: closed, 8-connected, holding every cell of the blob.
    ASSERT_FALSE(blob.outline.empty()) << what;
    for (std::size_t i = 0; i < blob.outline.size(); ++i) {
      const CellIndex& a = blob.outline[i];
      const CellIndex& b = blob.outline[(i + 1) % blob.outline.size()];
      ASSERT_LE(std::max(std::abs(a.col - b.col), std::abs(a.row - b.row)), 1) << what;
    }
    // By the plain crossing count of spec 8.2, not the library's fill.
    const testing::ReferenceChainInterior outline(blob.outline);
    for (const CellIndex& cell : blob.cells) {
      ASSERT_TRUE(outline.Encloses(cell.col, cell.row))
          << what << ": blob at " << blob.first_cell.col << "," << blob.first_cell.row
          << " has cells outside its outline";
    }
    // One side of every chain whose box meets the blob's.
    for (std::size_t k = 0; k < seg.rooms.size(); ++k) {
      const BoundingBox& b = chain_box[k];
      if (b.max_col < blob.box.min_col || b.min_col > blob.box.max_col ||
          b.max_row < blob.box.min_row || b.min_row > blob.box.max_row) {
        continue;
      }
      const bool first = InsideChain(seg.rooms[k].chain, blob.cells[0].col, blob.cells[0].row);
      for (const CellIndex& cell : blob.cells) {
        ASSERT_EQ(InsideChain(seg.rooms[k].chain, cell.col, cell.row), first)
            << what << ": blob at " << blob.first_cell.col << "," << blob.first_cell.row
            << " crosses the chain of room " << seg.rooms[k].id;
      }
    }
    bool wall = false, room_next = false, chain_next = false;
    for (const CellIndex& cell : blob.cells) {
      for (int dr = -1; dr <= 1; ++dr) {
        for (int dc = -1; dc <= 1; ++dc) {
          const int c = cell.col + dc, r = cell.row + dr;
          if ((!dr && !dc) || !grid.Contains(c, r)) continue;
          const std::size_t j = grid.Index(c, r);
          chain_next = chain_next || chain_of[j] != 0;
          room_next = room_next || ((!dr || !dc) && seg.room_of_cell[j] == blob.room);
          if (dr && dc) continue;
          wall =
              wall || (grid.cells()[j] != Cell::kFree && seg.room_of_cell[j] == 0 && !in_blob[j]);
        }
      }
    }
    if (blob.against_wall) {
      EXPECT_TRUE(wall) << what << ": blob against a wall at " << blob.first_cell.col << ","
                        << blob.first_cell.row << " next to no wall";
      EXPECT_TRUE(room_next) << what << ": blob against a wall next to no cell of its room";
    } else {
      EXPECT_FALSE(chain_next) << what << ": free-standing blob at " << blob.first_cell.col << ","
                               << blob.first_cell.row << " touches a chain";
    }
  }
}

// The cabinets of a plan: 4-connected components of its kAgainstWall cells.
std::vector<std::vector<std::size_t>> Cabinets(const testing::FloorPlan& plan) {
  const Grid& grid = plan.grid;
  std::vector<std::uint8_t> seen(grid.size(), 0);
  std::vector<std::vector<std::size_t>> out;
  for (std::size_t seed = 0; seed < grid.size(); ++seed) {
    if (plan.furniture[seed] != testing::FloorPlan::kAgainstWall || seen[seed]) continue;
    std::vector<std::size_t> cells, stack{seed};
    seen[seed] = 1;
    while (!stack.empty()) {
      const std::size_t i = stack.back();
      stack.pop_back();
      cells.push_back(i);
      const int c = static_cast<int>(i % grid.width()), r = static_cast<int>(i / grid.width());
      for (const auto& [dc, dr] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
        if (!grid.Contains(c + dc, r + dr)) continue;
        const std::size_t j = grid.Index(c + dc, r + dr);
        if (seen[j] || plan.furniture[j] != testing::FloorPlan::kAgainstWall) continue;
        seen[j] = 1;
        stack.push_back(j);
      }
    }
    std::sort(cells.begin(), cells.end());
    out.push_back(std::move(cells));
  }
  return out;
}

TEST(FurnitureTest, GeneratedPlansAgainstTruth) {
  std::size_t cabinet_cells = 0, cabinet_found = 0, wall_blob_cells = 0, wall_blob_true = 0;
  std::size_t standalone = 0, standalone_found = 0;
  int cabinets = 0;
  for (std::uint32_t seed = 1; seed <= 3; ++seed) {
    for (int kind = 0; kind < testing::kFloorPlanKinds; ++kind) {
      const testing::FloorPlanOptions options = testing::FloorPlanKind(kind, seed);
      const testing::FloorPlan plan = testing::GenerateFloorPlan(options);
      const Grid& grid = plan.grid;
      StatusOr<Segmentation> seg = SegmentMap(grid);
      ASSERT_TRUE(seg.ok()) << plan.name;
      ExpectFurnitureInvariants(grid, *seg, plan.name);
      std::vector<int> blob_of(grid.size(), -1);
      for (std::size_t k = 0; k < seg->blobs.size(); ++k) {
        for (const CellIndex& cell : seg->blobs[k].cells) {
          blob_of[grid.Index(cell.col, cell.row)] = static_cast<int>(k);
        }
      }
      if (!options.furniture) {
        // Walls, wall ends beside wide openings, pieces of wall between
        // doors and wall noise: none is furniture against a wall.
        for (const FurnitureBlob& blob : seg->blobs) {
          EXPECT_FALSE(blob.against_wall) << plan.name << ": wall at " << blob.first_cell.col << ","
                                          << blob.first_cell.row << " taken for furniture";
        }
        continue;
      }
      ASSERT_GT(plan.furniture_objects, 0) << plan.name;
      const std::vector<std::vector<std::size_t>> truth = Cabinets(plan);
      cabinets += static_cast<int>(truth.size());
      for (const std::vector<std::size_t>& cabinet : truth) {
        cabinet_cells += cabinet.size();
        std::size_t found = 0;
        for (const std::size_t i : cabinet) {
          found += blob_of[i] >= 0 && seg->blobs[blob_of[i]].against_wall;
        }
        cabinet_found += found;
        if (!options.noise) {
          // Without noise, each cabinet is exactly one blob against a wall.
          const int k = blob_of[cabinet[0]];
          ASSERT_GE(k, 0) << plan.name << ": cabinet missed";
          const FurnitureBlob& blob = seg->blobs[k];
          EXPECT_TRUE(blob.against_wall) << plan.name;
          std::vector<std::size_t> cells;
          for (const CellIndex& cell : blob.cells) cells.push_back(grid.Index(cell.col, cell.row));
          std::sort(cells.begin(), cells.end());
          EXPECT_EQ(cells, cabinet) << plan.name << ": cabinet cells";
          EXPECT_EQ(blob.room,
                    seg->room_of_cell[grid.Index(blob.box.min_col, blob.box.max_row + 1)] |
                        seg->room_of_cell[grid.Index(blob.box.min_col, blob.box.min_row - 1)])
              << plan.name;
        }
      }
      for (const FurnitureBlob& blob : seg->blobs) {
        if (!blob.against_wall) continue;
        for (const CellIndex& cell : blob.cells) {
          ++wall_blob_cells;
          wall_blob_true += plan.furniture[grid.Index(cell.col, cell.row)] != 0;
        }
      }
      for (std::size_t i = 0; i < grid.size(); ++i) {
        if (plan.furniture[i] != testing::FloorPlan::kStandAlone) continue;
        ++standalone;
        standalone_found += blob_of[i] >= 0 && !seg->blobs[blob_of[i]].against_wall;
      }
    }
  }
  ASSERT_GT(cabinets, 5);
  const double recall = static_cast<double>(cabinet_found) / cabinet_cells;
  const double precision = static_cast<double>(wall_blob_true) / wall_blob_cells;
  const double standalone_recall = static_cast<double>(standalone_found) / standalone;
  std::printf("[ furniture ] %d cabinets: recall %.3f precision %.3f; stand-alone recall %.3f\n",
              cabinets, recall, precision, standalone_recall);
  EXPECT_GE(recall, 0.9);
  EXPECT_GE(precision, 0.9);
  EXPECT_GE(standalone_recall, 0.95);
}

// A 4 x 3 m room (0.05 m cells) with 0.1 m walls, unknown outside.
Grid Room() {
  Grid grid(100, 80, Cell::kUnknown);
  Fill(&grid, 8, 8, 91, 71, Cell::kOccupied);
  Fill(&grid, 10, 10, 89, 69, Cell::kFree);  // 80 x 60 cells
  return grid;
}

// A cabinet against the bottom wall is one blob, cut along the wall's face;
// the room's chain runs around it. Bumps that are no furniture stay wall.
TEST(FurnitureTest, CabinetAgainstWallAndBumpsThatAreNone) {
  Grid grid = Room();
  Fill(&grid, 30, 10, 45, 17, Cell::kOccupied);  // cabinet 0.8 x 0.4 m
  Fill(&grid, 60, 69, 65, 69, Cell::kOccupied);  // wall noise: one cell deep
  Fill(&grid, 10, 40, 21, 43, Cell::kOccupied);  // a wall's end: 0.2 m wide
  Fill(&grid, 60, 10, 75, 29, Cell::kOccupied);  // 1 m deep: a notch
  Fill(&grid, 80, 60, 89, 69, Cell::kOccupied);  // in the corner: not sought
  StatusOr<Segmentation> seg = SegmentMap(grid);
  ASSERT_TRUE(seg.ok());
  ExpectFurnitureInvariants(grid, *seg, "room");
  ASSERT_EQ(seg->rooms.size(), 1u);
  ASSERT_EQ(seg->blobs.size(), 1u);
  const FurnitureBlob& cabinet = seg->blobs[0];
  EXPECT_TRUE(cabinet.against_wall);
  EXPECT_EQ(cabinet.room, 1);
  EXPECT_EQ(cabinet.cell_count, 16u * 8u);
  EXPECT_EQ(cabinet.box, (BoundingBox{30, 10, 45, 17}));
  EXPECT_EQ(cabinet.first_cell, (CellIndex{30, 10}));
  EXPECT_EQ(cabinet.outline.size(), 2u * (16 + 8) - 4);
  // The chain runs along the cabinet's face (row 18) and sides (columns 29
  // and 46), not behind it.
  std::set<std::pair<int, int>> chain;
  for (const CellIndex& cell : seg->rooms[0].chain) chain.insert({cell.col, cell.row});
  for (int c = 30; c <= 45; ++c) EXPECT_TRUE(chain.count({c, 18})) << c;
  for (int r = 10; r <= 17; ++r) {
    EXPECT_TRUE(chain.count({29, r})) << r;
    EXPECT_TRUE(chain.count({46, r})) << r;
  }
  EXPECT_EQ(seg->room_of_cell[grid.Index(35, 12)], 0);

  // Cut off with either maximum at 0.
  SegmentationOptions options;
  options.wall_furniture_max_depth_m = 0;
  StatusOr<Segmentation> none = SegmentMap(grid, options);
  ASSERT_TRUE(none.ok());
  EXPECT_TRUE(none->blobs.empty());
  options = {};
  options.wall_furniture_max_depth_m = 1.2;  // now the notch is furniture too
  StatusOr<Segmentation> deeper = SegmentMap(grid, options);
  ASSERT_TRUE(deeper.ok());
  EXPECT_EQ(deeper->blobs.size(), 2u);
  options = {};
  options.wall_furniture_min_depth_m = -1;
  EXPECT_FALSE(SegmentMap(grid, options).ok());
}

// The same on the other three walls: the search runs along rows and
// columns alike.
TEST(FurnitureTest, CabinetsOnEveryWall) {
  Grid grid = Room();
  Fill(&grid, 30, 62, 45, 69, Cell::kOccupied);  // top wall
  grid.set(30, 62, Cell::kFree);                 // a chipped corner
  grid.set(31, 62, Cell::kFree);
  Fill(&grid, 10, 30, 17, 45, Cell::kOccupied);  // left wall
  Fill(&grid, 80, 30, 89, 49, Cell::kOccupied);  // right wall, 0.5 x 1 m
  StatusOr<Segmentation> seg = SegmentMap(grid);
  ASSERT_TRUE(seg.ok());
  ExpectFurnitureInvariants(grid, *seg, "three walls");
  ASSERT_EQ(seg->blobs.size(), 3u);
  std::vector<BoundingBox> boxes;
  for (const FurnitureBlob& blob : seg->blobs) {
    EXPECT_TRUE(blob.against_wall);
    boxes.push_back(blob.box);
  }
  EXPECT_EQ(boxes,
            (std::vector<BoundingBox>{{10, 30, 17, 45}, {80, 30, 89, 49}, {30, 62, 45, 69}}));
}

// Speck rule: a chair's four one-cell legs are one blob; a speck near it
// that lines up with no leg stays out, one that lines up joins.
TEST(FurnitureTest, SpecksStayOutOfBlobs) {
  Grid grid = Room();
  for (const auto& [c, r] :
       std::vector<std::pair<int, int>>{{40, 30}, {48, 30}, {40, 38}, {48, 38}}) {
    grid.set(c, r, Cell::kOccupied);  // chair legs 0.4 m apart
  }
  grid.set(55, 45, Cell::kOccupied);  // a speck 0.35 m off, lined up with no leg
  StatusOr<Segmentation> seg = SegmentMap(grid);
  ASSERT_TRUE(seg.ok());
  ExpectFurnitureInvariants(grid, *seg, "chair");
  ASSERT_EQ(seg->blobs.size(), 1u);
  EXPECT_EQ(seg->blobs[0].cell_count, 4u);
  EXPECT_EQ(seg->blobs[0].box, (BoundingBox{40, 30, 48, 38}));
  EXPECT_FALSE(seg->blobs[0].against_wall);
  // Without the rule the speck joins.
  SegmentationOptions options;
  options.speck_max_cells = 0;
  StatusOr<Segmentation> joined = SegmentMap(grid, options);
  ASSERT_TRUE(joined.ok());
  ASSERT_EQ(joined->blobs.size(), 1u);
  EXPECT_EQ(joined->blobs[0].cell_count, 5u);
  // A speck in a leg's column joins: the rule cannot tell it from a leg.
  grid.set(55, 45, Cell::kFree);
  grid.set(48, 45, Cell::kOccupied);
  StatusOr<Segmentation> lined = SegmentMap(grid);
  ASSERT_TRUE(lined.ok());
  ASSERT_EQ(lined->blobs.size(), 1u);
  EXPECT_EQ(lined->blobs[0].cell_count, 5u);
}

// The same promises on the shared maps (real scans: slanted walls, clutter,
// unknown patches); the count of blobs against walls is printed.
TEST(FurnitureTest, InvariantsOnSharedMaps) {
  const std::string dir = testing::SharedMapsDir();
  if (dir.empty()) GTEST_SKIP() << "../shared/maps is absent";
  int checked = 0;
  std::size_t against_wall = 0, blobs = 0;
  for (const std::string& path : testing::FindYamlFiles(dir)) {
    StatusOr<Grid> grid = LoadRosMap(path);
    if (!grid.ok()) continue;
    StatusOr<Segmentation> seg = SegmentMap(*grid);
    ASSERT_TRUE(seg.ok()) << path << ": " << seg.status().message();
    ExpectFurnitureInvariants(*grid, *seg, path);
    for (const FurnitureBlob& blob : seg->blobs) against_wall += blob.against_wall;
    blobs += seg->blobs.size();
    ++checked;
  }
  std::printf("[ furniture ] %d shared maps: %zu blobs, %zu against walls\n", checked, blobs,
              against_wall);
  EXPECT_GT(checked, 0);
}

}  // namespace
}  // namespace linemap
