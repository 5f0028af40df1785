// The room flood's raster pass over the levels above a door's clearance
// (merge_tree.cc, JoinPlateaus) against the flood that visits every level
// cell by cell: rooms, peaks and doors must come out the same on generated
// floor plans, the bundled maps and random grids.
#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "codec/segment/segment_internal.h"
#include "linemap/map_io.h"
#include "tests/testing/floor_plan.h"
#include "tests/testing/test_support.h"

namespace linemap {
namespace {

using segment_internal::FloodRooms;
using segment_internal::RoomFlood;

void ExpectSameFlood(const Grid& grid, const SegmentationOptions& options,
                     const std::string& name) {
  SegmentationTimings timings;
  const RoomFlood fast = FloodRooms(grid, options, &timings, /*join_plateaus=*/true);
  const RoomFlood slow = FloodRooms(grid, options, &timings, /*join_plateaus=*/false);
  EXPECT_EQ(fast.room_count, slow.room_count) << name;
  EXPECT_EQ(fast.room_of_cell, slow.room_of_cell) << name;
  EXPECT_EQ(fast.peak, slow.peak) << name;
  ASSERT_EQ(fast.doors.size(), slow.doors.size()) << name;
  for (std::size_t k = 0; k < fast.doors.size(); ++k) {
    EXPECT_EQ(fast.doors[k].room_a, slow.doors[k].room_a) << name << " door " << k;
    EXPECT_EQ(fast.doors[k].room_b, slow.doors[k].room_b) << name << " door " << k;
    EXPECT_EQ(fast.doors[k].cell, slow.doors[k].cell) << name << " door " << k;
    EXPECT_EQ(fast.doors[k].width_m, slow.doors[k].width_m) << name << " door " << k;
  }
}

TEST(RoomFloodTest, RasterPassFloodsLikeEveryLevelOnFloorPlans) {
  int rooms = 0;
  for (int kind = 0; kind < testing::kFloorPlanKinds; ++kind) {
    for (std::uint32_t seed = 1; seed <= 2; ++seed) {
      const testing::FloorPlan plan =
          testing::GenerateFloorPlan(testing::FloorPlanKind(kind, seed));
      ExpectSameFlood(plan.grid, {}, plan.name);
      rooms += plan.room_count;
    }
  }
  EXPECT_GT(rooms, 16);  // the plans have rooms and doors to keep apart
}

TEST(RoomFloodTest, RasterPassFloodsLikeEveryLevelOnBundledMaps) {
  const std::vector<std::string> maps = testing::FindYamlFiles(testing::BundledMapsDir());
  ASSERT_FALSE(maps.empty());
  for (const std::string& path : maps) {
    StatusOr<Grid> grid = LoadRosMap(path);
    ASSERT_TRUE(grid.ok()) << path << ": " << grid.status().message();
    ExpectSameFlood(*grid, {}, path);
    // Narrower doors: more of the free space lies above a door's clearance.
    SegmentationOptions narrow;
    narrow.min_door_width_m = 0.3;
    narrow.max_door_width_m = 0.6;
    ExpectSameFlood(*grid, narrow, path + " (doors 0.3-0.6 m)");
  }
}

// Open rectangles joined and split by random walls: plateaus that meet at
// several places, ties between equally high peaks, plateaus touching the
// map's edge.
TEST(RoomFloodTest, RasterPassFloodsLikeEveryLevelOnRandomGrids) {
  std::mt19937 rng(20261127);
  for (int trial = 0; trial < 40; ++trial) {
    const int w = 40 + static_cast<int>(rng() % 160), h = 40 + static_cast<int>(rng() % 160);
    Grid grid(w, h, Cell::kFree);
    grid.meta.resolution = trial % 2 ? 0.05 : 0.02;
    const int walls = static_cast<int>(rng() % 30);
    for (int k = 0; k < walls; ++k) {
      const int c = static_cast<int>(rng() % w), r = static_cast<int>(rng() % h);
      const int len = 5 + static_cast<int>(rng() % 80);
      const bool across = rng() % 2 == 0;
      const Cell value = rng() % 5 == 0 ? Cell::kUnknown : Cell::kOccupied;
      for (int i = 0; i < len; ++i) {
        const int cc = across ? c + i : c, rr = across ? r : r + i;
        if (cc < w && rr < h) grid.set(cc, rr, value);
      }
    }
    ExpectSameFlood(grid, {}, "random grid " + std::to_string(trial));
  }
}

}  // namespace
}  // namespace linemap
