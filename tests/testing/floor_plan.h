// Generated floor plans with ground truth, for the room segmentation's tests
// and its bench (tools/bench_rooms): a corridor 1.4 to 2.4 m wide with
// rectangular rooms on both sides (some made L-shaped by a block of wall in
// a back corner), walls thin or thick, one open door of 0.7 to 1.2 m (and at
// least 0.3 m narrower than the corridor) from each room to the corridor,
// doors between some neighbouring rooms and wide openings (over 2 m, which
// make the two one room) between others, optional
// furniture (table and chair legs, bins, cabinets of 0.6 to 1.6 by 0.3 to
// 0.6 m against any wall of a room, off its corners) and
// optional scan noise (specks in the rooms, cells lost along the walls).
// Everything outside the building is unknown.
#ifndef LINEMAP_TESTS_TESTING_FLOOR_PLAN_H_
#define LINEMAP_TESTS_TESTING_FLOOR_PLAN_H_

#include <cstdint>
#include <string>
#include <vector>

#include "linemap/cells.h"
#include "linemap/grid.h"
#include "linemap/status.h"

namespace linemap::testing {

struct FloorPlanOptions {
  std::uint32_t seed = 1;
  double resolution = 0.05;  // metres per cell
  bool thick_walls = false;  // 0.15-0.30 m walls; else 0.05-0.10 m
  bool furniture = false;
  bool noise = false;
  int rooms_per_side = 4;
};

struct FloorPlanDoor {
  int room_a = 0;  // true room ids on both sides
  int room_b = 0;
  CellIndex centre;  // middle cell of the door's opening
  double width_m = 0;
};

struct FloorPlan {
  Grid grid;
  // True room (1..room_count) of every cell of a room or the corridor,
  // furniture included; 0 for walls, door openings and outside.
  std::vector<std::int32_t> room_of_cell;
  int room_count = 0;
  int corridor = 0;  // id of the corridor
  std::vector<FloorPlanDoor> doors;
  // Non-zero where furniture occupies a cell that is free without it:
  // kStandAlone for tables, chairs and bins, kAgainstWall for cabinets.
  static constexpr std::uint8_t kStandAlone = 1;
  static constexpr std::uint8_t kAgainstWall = 2;
  std::vector<std::uint8_t> furniture;
  int furniture_objects = 0;  // tables, chairs, bins and cabinets placed
  std::string name;           // e.g. "seed3-thick-furnished-noisy"
};

FloorPlan GenerateFloorPlan(const FloorPlanOptions& options);

// The development set's eight kinds of plan: `kind` 0..7, bit 0 thick
// walls, bit 1 furniture, bit 2 scan noise; the given seed.
inline constexpr int kFloorPlanKinds = 8;
FloorPlanOptions FloorPlanKind(int kind, std::uint32_t seed);

// The survey's area-weighted figures over cells with a true room: recall =
// sum over true rooms of the largest share one segment covers (in cells) /
// all such cells; precision = sum over segments of their largest overlap
// with one true room / all their cells that have a true room. `segment_of`
// uses 0 for "no segment".
struct RoomScores {
  double recall = 0;
  double precision = 0;
};
RoomScores ScoreRooms(const std::vector<std::int32_t>& truth,
                      const std::vector<std::int32_t>& segment_of);

// A hand-drawn ground truth (tests/data/rooms/*.truth): the map it labels
// (`map PATH`, under `maps_dir`), straight lines drawn by hand across the
// doorways (`cut COL0 ROW0 COL1 ROW1`, image pixels, row 0 at the top) and
// pixels of components that are not scored (`outside COL ROW`). The rooms
// are what a paint bucket gives: the 4-connected components of the free
// cells off the cut lines, those of at least 1 m^2; cut cells, outside
// components and smaller ones have room 0.
struct HandTruth {
  Grid grid;
  std::vector<std::int32_t> room_of_cell;
  int rooms = 0;
};
StatusOr<HandTruth> LoadHandTruth(const std::string& path, const std::string& maps_dir);

}  // namespace linemap::testing

#endif  // LINEMAP_TESTS_TESTING_FLOOR_PLAN_H_
