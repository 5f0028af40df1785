// SegmentMap() with the default method: rooms split at doorways, checked
// against generated floor plans with known rooms and doors
// (tests/testing/floor_plan.h) and against hand-built grids, with plain
// reference code (flood fills, neighbour checks) written here.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "linemap/map_io.h"
#include "linemap/segmentation.h"
#include "tests/testing/floor_plan.h"
#include "tests/testing/reference_components.h"
#include "tests/testing/reference_geometry.h"
#include "tests/testing/test_support.h"

namespace linemap {
namespace {

void Fill(Grid* grid, int c0, int r0, int c1, int r1, Cell value) {
  for (int r = r0; r <= r1; ++r) {
    for (int c = c0; c <= c1; ++c) grid->set(c, r, value);
  }
}

// Sizes of the 4-connected components of free cells, per cell (0 for cells
// that are not free), by a plain flood fill.
std::vector<std::size_t> FreeComponentSizes(const Grid& grid) {
  const testing::FreeComponents components = testing::FreeComponentsByFloodFill(grid);
  const std::vector<int>& id = components.id;
  const std::vector<std::size_t>& sizes = components.sizes;
  std::vector<std::size_t> out(grid.size(), 0);
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = sizes[id[i]];
  return out;
}

// The structural promises of the rooms method, on any grid:
//  - every chain closed, 8-connected, inside the grid, on its own room's
//    cells, and no cell on two chains;
//  - every cell of a room enclosed by its chain (spec/format.md 8.2, by the
//    plain crossing count of tests/testing/reference_geometry.h);
//  - every free cell in a room unless its free component is smaller than
//    the minimum room area;
//  - free-standing furniture: its cells in its room, none on or 8-adjacent
//    to a chain; furniture against a wall: its cells in no room and off
//    every chain (the room's chain runs around it).
void ExpectRoomInvariants(const Grid& grid, const Segmentation& seg,
                          const SegmentationOptions& options, const std::string& what) {
  ASSERT_EQ(seg.room_of_cell.size(), grid.size()) << what;
  std::vector<int> chain_of(grid.size(), 0);
  for (std::size_t k = 0; k < seg.rooms.size(); ++k) {
    const RoomBorder& room = seg.rooms[k];
    ASSERT_EQ(room.id, static_cast<int>(k + 1)) << what;
    ASSERT_FALSE(room.chain.empty()) << what;
    for (std::size_t i = 0; i < room.chain.size(); ++i) {
      const CellIndex& a = room.chain[i];
      const CellIndex& b = room.chain[(i + 1) % room.chain.size()];
      ASSERT_TRUE(grid.Contains(a.col, a.row)) << what;
      if (room.chain.size() > 1) {
        ASSERT_EQ(std::max(std::abs(a.col - b.col), std::abs(a.row - b.row)), 1)
            << what << ": room " << room.id << " chain cells " << i << " and next not 8-adjacent";
      }
      const std::size_t at = grid.Index(a.col, a.row);
      ASSERT_EQ(seg.room_of_cell[at], room.id) << what << ": chain off its room";
      ASSERT_TRUE(chain_of[at] == 0 || chain_of[at] == room.id)
          << what << ": chains of rooms " << chain_of[at] << " and " << room.id << " share a cell";
      chain_of[at] = room.id;
    }
  }
  std::vector<testing::ReferenceChainInterior> interiors;
  for (const RoomBorder& room : seg.rooms) interiors.emplace_back(room.chain);
  for (int r = 0; r < grid.height(); ++r) {
    for (int c = 0; c < grid.width(); ++c) {
      const std::int32_t id = seg.room_of_cell[grid.Index(c, r)];
      if (id <= 0) continue;
      ASSERT_TRUE(interiors[id - 1].Encloses(c, r))
          << what << ": cell " << c << "," << r << " of room " << id << " outside its chain";
    }
  }
  const std::size_t min_cells = static_cast<std::size_t>(
      options.min_room_area_m2 / (grid.meta.resolution * grid.meta.resolution));
  const std::vector<std::size_t> component = FreeComponentSizes(grid);
  std::size_t left_out = 0;
  for (std::size_t i = 0; i < grid.size(); ++i) {
    if (grid.cells()[i] != Cell::kFree || seg.room_of_cell[i]) continue;
    ++left_out;
    ASSERT_LT(component[i], min_cells) << what << ": free cell " << i << " in no room";
  }
  for (const FurnitureBlob& blob : seg.blobs) {
    ASSERT_GT(blob.room, 0) << what;
    ASSERT_EQ(blob.cells.size(), blob.cell_count) << what;
    for (const CellIndex& cell : blob.cells) {
      ASSERT_EQ(grid.at(cell.col, cell.row), Cell::kOccupied) << what;
      ASSERT_GE(cell.col, blob.box.min_col);
      ASSERT_LE(cell.col, blob.box.max_col);
      ASSERT_GE(cell.row, blob.box.min_row);
      ASSERT_LE(cell.row, blob.box.max_row);
      if (blob.against_wall) {
        ASSERT_EQ(seg.room_of_cell[grid.Index(cell.col, cell.row)], 0) << what;
        ASSERT_EQ(chain_of[grid.Index(cell.col, cell.row)], 0) << what;
        continue;
      }
      ASSERT_EQ(seg.room_of_cell[grid.Index(cell.col, cell.row)], blob.room) << what;
      for (int dr = -1; dr <= 1; ++dr) {
        for (int dc = -1; dc <= 1; ++dc) {
          if (!grid.Contains(cell.col + dc, cell.row + dr)) continue;
          ASSERT_EQ(chain_of[grid.Index(cell.col + dc, cell.row + dr)], 0)
              << what << ": furniture at " << cell.col << "," << cell.row << " touches a chain";
        }
      }
    }
  }
}

// For each true room, the segment holding most of its cells, and the share.
std::map<int, std::pair<int, double>> BestSegments(const testing::FloorPlan& plan,
                                                   const std::vector<std::int32_t>& segment_of) {
  std::map<std::pair<int, int>, std::size_t> overlap;
  std::map<int, std::size_t> size;
  for (std::size_t i = 0; i < plan.room_of_cell.size(); ++i) {
    // A cabinet against a wall is no room space (the room's chain runs
    // around it).
    if (!plan.room_of_cell[i] || plan.furniture[i] == testing::FloorPlan::kAgainstWall) continue;
    ++size[plan.room_of_cell[i]];
    if (segment_of[i]) ++overlap[{plan.room_of_cell[i], segment_of[i]}];
  }
  std::map<int, std::pair<int, double>> best;
  for (const auto& [key, n] : overlap) {
    const double share = static_cast<double>(n) / size[key.first];
    if (share > best[key.first].second) best[key.first] = {key.second, share};
  }
  return best;
}

TEST(RoomsTest, GeneratedPlansEveryDoorFoundNoSplitWithoutDoor) {
  const SegmentationOptions options;
  int plans = 0;
  for (std::uint32_t seed = 1; seed <= 3; ++seed) {
    for (int kind = 0; kind < testing::kFloorPlanKinds; ++kind) {
      const testing::FloorPlan plan =
          testing::GenerateFloorPlan(testing::FloorPlanKind(kind, seed));
      StatusOr<Segmentation> seg = SegmentMap(plan.grid, options);
      ASSERT_TRUE(seg.ok()) << plan.name << ": " << seg.status().message();
      ExpectRoomInvariants(plan.grid, *seg, options, plan.name);
      // No split without a door: one segment per true room, each holding
      // nearly all of its room space.
      EXPECT_EQ(seg->rooms.size(), static_cast<std::size_t>(plan.room_count)) << plan.name;
      const auto best = BestSegments(plan, seg->room_of_cell);
      std::set<int> used;
      for (int id = 1; id <= plan.room_count; ++id) {
        ASSERT_TRUE(best.count(id)) << plan.name << ": room " << id << " not covered";
        EXPECT_GE(best.at(id).second, 0.95) << plan.name << ": room " << id << " split";
        used.insert(best.at(id).first);
      }
      // Every door found: its two rooms fall in different segments.
      for (const testing::FloorPlanDoor& door : plan.doors) {
        EXPECT_NE(best.at(door.room_a).first, best.at(door.room_b).first)
            << plan.name << ": door at " << door.centre.col << "," << door.centre.row << " ("
            << door.width_m << " m) missed";
      }
      EXPECT_EQ(used.size(), static_cast<std::size_t>(plan.room_count)) << plan.name;
      // The corridor (at least 15 m long, 1.4 to 2.4 m wide) is a corridor,
      // the rooms (2.5 to 5 m by 3 to 5 m, alone or joined by wide openings) are
      // rooms.
      for (int id = 1; id <= plan.room_count; ++id) {
        const RoomKind kind = seg->rooms[best.at(id).first - 1].kind;
        EXPECT_EQ(kind, id == plan.corridor ? RoomKind::kCorridor : RoomKind::kRoom)
            << plan.name << ": room " << id;
      }
      // One doorway listed per pair of true rooms with a door between them
      // (rooms joined by a wide opening have two doors to the corridor).
      std::set<std::pair<int, int>> pairs;
      for (const testing::FloorPlanDoor& door : plan.doors) {
        pairs.insert(std::minmax(door.room_a, door.room_b));
      }
      EXPECT_EQ(seg->doors.size(), pairs.size()) << plan.name;
      ++plans;
    }
  }
  EXPECT_EQ(plans, 24);
}

// Two 4 x 3 m rooms side by side, a 0.1 m wall between them with an opening
// `gap_cells` wide (0.05 m cells), unknown outside.
Grid TwoRooms(int gap_cells) {
  Grid grid(180, 80, Cell::kUnknown);
  Fill(&grid, 4, 4, 175, 75, Cell::kOccupied);
  Fill(&grid, 5, 5, 84, 64, Cell::kFree);    // room A: 80 x 60 cells
  Fill(&grid, 87, 5, 166, 64, Cell::kFree);  // room B
  Fill(&grid, 85, 30, 86, 30 + gap_cells - 1, Cell::kFree);
  return grid;
}

TEST(RoomsTest, SplitsOnlyAtDoorWidths) {
  for (const int gap : {6, 10, 16, 20, 24}) {  // 0.3 .. 1.2 m
    StatusOr<Segmentation> seg = SegmentMap(TwoRooms(gap));
    ASSERT_TRUE(seg.ok());
    const std::size_t expected = gap >= 10 ? 2 : 1;  // 0.5 m and up is a door
    EXPECT_EQ(seg->rooms.size(), expected) << "opening of " << gap << " cells";
    ExpectRoomInvariants(TwoRooms(gap), *seg, {}, "two rooms");
    if (expected == 2) {
      ASSERT_EQ(seg->doors.size(), 1u);
      EXPECT_NEAR(seg->doors[0].width_m, gap * 0.05, 0.1);
      EXPECT_EQ(seg->rooms[0].area_m2 > 0, true);
      // Room A holds the first cell in raster order: id 1.
      EXPECT_EQ(seg->room_of_cell[TwoRooms(gap).Index(5, 5)], 1);
      EXPECT_EQ(seg->room_of_cell[TwoRooms(gap).Index(166, 64)], 2);
    }
  }
  // An opening of 2 m is no door.
  StatusOr<Segmentation> wide = SegmentMap(TwoRooms(40));
  ASSERT_TRUE(wide.ok());
  EXPECT_EQ(wide->rooms.size(), 1u);
  EXPECT_TRUE(wide->doors.empty());
}

// Which openings the default range 0.5..1.2 m takes, and the width a door
// reports. The rule goes by the clearance c = ceil(n / 2) cells at the
// middle of an opening of n cells (segmentation.h): 3 c within
// [round(1.5 * 0.5 / res), round(1.5 * (1.2 / res + 2))], which is [15, 39]
// at 0.05 m/cell, so c in 5..13 and n in 9..26 (0.45..1.30 m), and [8, 21]
// at 0.1 m/cell, so c in 3..7 and n in 5..14 (0.5..1.4 m), worked out by
// hand here. The door's width_m is n cells: a 1.40 m opening of 0.1 m cells
// used to read 1.3 (2 c - 1 cells), a 0.50 m one of 0.05 m cells 0.45.
TEST(RoomsTest, DoorsAreTheOpeningsTheDocumentedSlackTakesAtTheirOwnWidth) {
  for (const auto& [res, first, last] : {std::tuple{0.05, 9, 26}, std::tuple{0.1, 5, 14}}) {
    for (int gap = first - 3; gap <= last + 3; ++gap) {
      SCOPED_TRACE(std::to_string(res) + " m/cell, opening of " + std::to_string(gap) + " cells");
      Grid grid = TwoRooms(gap);
      grid.meta.resolution = res;
      StatusOr<Segmentation> seg = SegmentMap(grid);
      ASSERT_TRUE(seg.ok()) << seg.status().message();
      const bool door = gap >= first && gap <= last;
      EXPECT_EQ(seg->rooms.size(), door ? 2u : 1u);
      ASSERT_EQ(seg->doors.size(), door ? 1u : 0u);
      if (door) {
        EXPECT_NEAR(seg->doors[0].width_m, gap * res, 1e-12);
      }
    }
  }
}

TEST(RoomsTest, DoorRangeIsAnOption) {
  SegmentationOptions options;
  options.max_door_width_m = 0.8;
  StatusOr<Segmentation> seg = SegmentMap(TwoRooms(20), options);  // 1.0 m
  ASSERT_TRUE(seg.ok());
  EXPECT_EQ(seg->rooms.size(), 1u);
  options.min_door_width_m = 0.2;
  options.max_door_width_m = 1.2;
  seg = SegmentMap(TwoRooms(6), options);  // 0.3 m
  ASSERT_TRUE(seg.ok());
  EXPECT_EQ(seg->rooms.size(), 2u);
  options.min_door_width_m = 0.7;
  seg = SegmentMap(TwoRooms(10), options);  // 0.5 m
  ASSERT_TRUE(seg.ok());
  EXPECT_EQ(seg->rooms.size(), 1u);
}

// Two 10 x 10 m halls joined by a 3 m opening are one room unless
// max_room_area_m2 is smaller than the two together.
TEST(RoomsTest, MaxRoomAreaSplitsHallsAtWideOpenings) {
  Grid grid(420, 210, Cell::kUnknown);
  Fill(&grid, 4, 4, 415, 205, Cell::kOccupied);
  Fill(&grid, 5, 5, 204, 204, Cell::kFree);     // hall A, 200 x 200 cells
  Fill(&grid, 209, 5, 408, 204, Cell::kFree);   // hall B, wall of 4 cells between
  Fill(&grid, 205, 70, 208, 129, Cell::kFree);  // opening, 60 cells = 3 m
  StatusOr<Segmentation> one = SegmentMap(grid);
  ASSERT_TRUE(one.ok());
  EXPECT_EQ(one->rooms.size(), 1u);
  SegmentationOptions options;
  options.max_room_area_m2 = 150;
  StatusOr<Segmentation> two = SegmentMap(grid, options);
  ASSERT_TRUE(two.ok());
  ASSERT_EQ(two->rooms.size(), 2u);
  ExpectRoomInvariants(grid, *two, options, "halls");
  EXPECT_NE(two->room_of_cell[grid.Index(10, 100)], two->room_of_cell[grid.Index(400, 100)]);
  ASSERT_EQ(two->doors.size(), 1u);
  EXPECT_GT(two->doors[0].width_m, 2.5);
}

// A 1.0 m corridor 12 m long with ragged walls (cells bitten out on both
// sides) and a 3 x 3 m room at its end through a 0.8 m door: the corridor
// stays one room, however the wall noise narrows it.
TEST(RoomsTest, RaggedCorridorStaysWhole) {
  Grid grid(320, 100, Cell::kUnknown);
  Fill(&grid, 4, 4, 315, 95, Cell::kOccupied);
  Fill(&grid, 5, 40, 244, 59, Cell::kFree);    // corridor, 20 cells wide
  Fill(&grid, 250, 20, 309, 79, Cell::kFree);  // room, 60 x 60
  Fill(&grid, 245, 42, 249, 57, Cell::kFree);  // door, 16 cells
  for (int c = 10; c < 240; c += 7) {
    grid.set(c, 40, Cell::kOccupied);
    grid.set(c + 3, 59, Cell::kOccupied);
  }
  StatusOr<Segmentation> seg = SegmentMap(grid);
  ASSERT_TRUE(seg.ok());
  ASSERT_EQ(seg->rooms.size(), 2u);
  ExpectRoomInvariants(grid, *seg, {}, "corridor");
  // The room's first cell (row 20) comes before the corridor's (row 40).
  EXPECT_EQ(seg->rooms[0].kind, RoomKind::kRoom);
  EXPECT_EQ(seg->rooms[1].kind, RoomKind::kCorridor);
  EXPECT_EQ(seg->room_of_cell[grid.Index(300, 70)], 1);
  EXPECT_EQ(seg->room_of_cell[grid.Index(6, 41)], 2);
  EXPECT_EQ(seg->room_of_cell[grid.Index(240, 50)], 2);
}

// Table legs in the middle of a room are one blob; a leg in a doorway or
// within a cell of a wall is none; a specks is none.
TEST(RoomsTest, FurnitureStandsInsideRooms) {
  Grid grid = TwoRooms(20);
  for (const auto& [c, r] :
       std::vector<std::pair<int, int>>{{30, 30}, {45, 30}, {30, 45}, {45, 45}}) {
    Fill(&grid, c, r, c + 1, r + 1, Cell::kOccupied);  // 2 x 2 legs, 0.75 m apart
  }
  Fill(&grid, 6, 50, 7, 51, Cell::kOccupied);  // one cell off the wall
  grid.set(120, 20, Cell::kOccupied);          // a speck
  StatusOr<Segmentation> seg = SegmentMap(grid);
  ASSERT_TRUE(seg.ok());
  ExpectRoomInvariants(grid, *seg, {}, "furnished");
  ASSERT_EQ(seg->rooms.size(), 2u);
  ASSERT_EQ(seg->blobs.size(), 1u);
  EXPECT_EQ(seg->blobs[0].cell_count, 16u);
  EXPECT_EQ(seg->blobs[0].room, 1);
  EXPECT_EQ(seg->blobs[0].box, (BoundingBox{30, 30, 46, 46}));
}

TEST(RoomsTest, RejectsBadOptionsAndResolution) {
  SegmentationOptions options;
  options.min_door_width_m = 1.5;  // above max_door_width_m
  EXPECT_FALSE(SegmentMap(TwoRooms(20), options).ok());
  options = {};
  options.min_room_area_m2 = -1;
  EXPECT_FALSE(SegmentMap(TwoRooms(20), options).ok());
  options = {};
  options.max_room_area_m2 = std::nan("");
  EXPECT_FALSE(SegmentMap(TwoRooms(20), options).ok());
  Grid grid = TwoRooms(20);
  grid.meta.resolution = 0;
  EXPECT_FALSE(SegmentMap(grid).ok());
  StatusOr<Segmentation> empty = SegmentMap(Grid());
  ASSERT_TRUE(empty.ok());
  EXPECT_TRUE(empty->rooms.empty());
}

// Shared maps with rooms labelled by hand (tests/data/rooms/*.truth): the
// issue's goal, area-weighted recall and precision of at least 0.9.
TEST(RoomsTest, HandLabelledSharedMaps) {
  const std::string dir = testing::SharedMapsDir();
  if (dir.empty()) GTEST_SKIP() << "../shared/maps is absent";
  int checked = 0;
  const std::string truths = testing::SourceDir() + "/tests/data/rooms";
  for (const std::string& name : testing::ListDir(truths)) {
    if (name.size() < 6 || name.substr(name.size() - 6) != ".truth") continue;
    const std::string path = truths + "/" + name;
    StatusOr<testing::HandTruth> truth = testing::LoadHandTruth(path, dir);
    ASSERT_TRUE(truth.ok()) << path << ": " << truth.status().message();
    ASSERT_GT(truth->rooms, 1) << path;
    StatusOr<Segmentation> seg = SegmentMap(truth->grid);
    ASSERT_TRUE(seg.ok()) << path;
    const testing::RoomScores scores = testing::ScoreRooms(truth->room_of_cell, seg->room_of_cell);
    std::printf("[ hand truth] %s: recall %.3f precision %.3f\n", path.c_str(), scores.recall,
                scores.precision);
    EXPECT_GE(scores.recall, 0.9) << path;
    EXPECT_GE(scores.precision, 0.9) << path;
    ++checked;
  }
  EXPECT_EQ(checked, 2);
}

TEST(RoomsTest, InvariantsOnSharedMaps) {
  const std::string dir = testing::SharedMapsDir();
  if (dir.empty()) GTEST_SKIP() << "../shared/maps is absent";
  std::vector<std::string> maps = testing::FindYamlFiles(dir);
  for (const std::string& image : testing::FindBareImages(dir)) maps.push_back(image);
  int checked = 0;
  for (const std::string& path : maps) {
    StatusOr<Grid> grid = LoadRosMap(path);
    if (!grid.ok()) continue;
    StatusOr<Segmentation> seg = SegmentMap(*grid);
    ASSERT_TRUE(seg.ok()) << path << ": " << seg.status().message();
    ExpectRoomInvariants(*grid, *seg, {}, path);
    ++checked;
  }
  EXPECT_GT(checked, 0);
}

}  // namespace
}  // namespace linemap
