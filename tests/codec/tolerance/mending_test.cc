// The mending steps of the tolerance fitting (tolerance_internal.h): which
// cells each gives back when blocks break a guarantee. The fitting is
// correct with any cells given back (simplify_test.cc checks the
// guarantees on its results); these tests hold the steps to giving back
// few: one doorway rather than a plan's whole wall side, one gap rather
// than a split-off piece's whole edge, one cell in three along a
// thickened wall; and the local plan check to finding a closed doorway
// that sampled starts miss, without flagging a wall one cell thicker.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <random>
#include <set>
#include <vector>

#include "codec/tolerance/tolerance_internal.h"
#include "linemap/cells.h"
#include "linemap/grid.h"

namespace linemap::tolerance_internal {
namespace {

std::set<std::size_t> AsSet(const std::vector<std::size_t>& cells) {
  return {cells.begin(), cells.end()};
}

// A 30 x 12 room split by a wall on row 6 with a doorway at column 25, and
// a wall along its bottom row. The decode closes the doorway and thickens
// the bottom wall along row 10 from column 3 to the right edge. That
// changes no plan (the lower half stays orthogonally convex, where every
// plan is as long as its Manhattan distance) but lies on some of the
// shortest plans from the lower half to the doorway (the breadth-first
// search's own plan from (2, 10) runs along it). Giving back the doorway
// alone restores every plan.
TEST(PlanCulpritsTest, GivesBackTheDoorwayNotTheCellsAlongTheWall) {
  Grid original(30, 12, Cell::kFree);
  for (int c = 0; c < 30; ++c) {
    if (c != 25) original.set(c, 6, Cell::kOccupied);
    original.set(c, 11, Cell::kOccupied);
  }
  Grid decoded = original;
  decoded.set(25, 6, Cell::kOccupied);
  for (int c = 3; c < 30; ++c) decoded.set(c, 10, Cell::kOccupied);

  const std::vector<std::size_t> culprits = PlanCulprits(original, decoded);
  ASSERT_FALSE(culprits.empty());
  EXPECT_EQ(AsSet(culprits), std::set<std::size_t>{original.Index(25, 6)});
}

// The same with the roles swapped: the decode opens a second doorway
// (column 4) that makes plans shorter. The culprit is that doorway.
TEST(PlanCulpritsTest, FindsTheShortcutTheDecodeOpened) {
  Grid original(30, 12, Cell::kFree);
  for (int c = 0; c < 30; ++c) {
    if (c != 25) original.set(c, 6, Cell::kOccupied);
  }
  original.set(4, 6, Cell::kUnknown);
  Grid decoded = original;
  decoded.set(4, 6, Cell::kFree);

  EXPECT_EQ(AsSet(PlanCulprits(original, decoded)), std::set<std::size_t>{original.Index(4, 6)});
}

// A 20 x 20 free room whose decode loses rows 9 and 10 across its whole
// width: the lower part splits off. Two cells (one column of the band)
// join it again; every lost cell beside the piece would be 20.
TEST(TopologyFaultsTest, SplitCulpritsAreOneGapThroughTheBand) {
  const Grid original(20, 20, Cell::kFree);
  Grid decoded = original;
  for (int c = 0; c < 20; ++c) {
    decoded.set(c, 9, Cell::kOccupied);
    decoded.set(c, 10, Cell::kOccupied);
  }
  const TopologyFaults faults = FindTopologyFaults(original, decoded, true);
  ASSERT_EQ(faults.splits, 1u);
  ASSERT_EQ(faults.split_culprits.size(), 2u);
  const std::size_t a = faults.split_culprits[0], b = faults.split_culprits[1];
  EXPECT_EQ(a % 20, b % 20) << "one column";
  EXPECT_EQ(std::set<std::size_t>({a / 20, b / 20}), std::set<std::size_t>({9, 10}));

  for (const std::size_t i : faults.split_culprits) decoded.mutable_cells()[i] = Cell::kFree;
  EXPECT_EQ(FindTopologyFaults(original, decoded, false).splits, 0u);
}

// Two rooms joined by a doorway (column 20 of a wall on row 10) and, far
// round, by a corridor down the left edge. The decode closes the doorway:
// every plan still exists, but between the cells on either side of it the
// plan is 40 steps longer. (On this small map the sampled starts find it
// too; on a large one they may all lie in other rooms.)
Grid TwoRoomsWithADoorway() {
  Grid g(40, 21, Cell::kFree);
  for (int c = 2; c < 40; ++c) {
    if (c != 20) g.set(c, 10, Cell::kOccupied);
  }
  return g;
}

TEST(LocalDetourCulpritsTest, FindsADoorwayClosedBetweenTwoRooms) {
  const Grid original = TwoRoomsWithADoorway();
  Grid decoded = original;
  decoded.set(20, 10, Cell::kOccupied);
  EXPECT_EQ(AsSet(LocalDetourCulprits(original, decoded, 8)),
            std::set<std::size_t>{original.Index(20, 10)});
}

// Given the decode it last checked, the check searches only near cells
// that changed since: the closed doorway is found again when the doorway
// changed since (checked against the original), not when nothing did.
TEST(LocalDetourCulpritsTest, SearchesOnlyNearChangesSinceTheLastCheck) {
  const Grid original = TwoRoomsWithADoorway();
  Grid decoded = original;
  decoded.set(20, 10, Cell::kOccupied);
  EXPECT_TRUE(LocalDetourCulprits(original, decoded, 8, &decoded).empty());
  EXPECT_EQ(AsSet(LocalDetourCulprits(original, decoded, 8, &original)),
            std::set<std::size_t>{original.Index(20, 10)});
}

// The same with an unknown cell in the wall that the decode makes free: a
// shortcut, whose culprit is that cell.
TEST(LocalDetourCulpritsTest, FindsAShortcutThroughAWall) {
  Grid original(40, 21, Cell::kFree);
  for (int c = 2; c < 40; ++c) original.set(c, 10, Cell::kOccupied);
  original.set(30, 10, Cell::kUnknown);
  Grid decoded = original;
  decoded.set(30, 10, Cell::kFree);
  EXPECT_EQ(AsSet(LocalDetourCulprits(original, decoded, 8)),
            std::set<std::size_t>{original.Index(30, 10)});
}

// A wall thickened by a cell along its length and at its tip: plans along
// it keep their length, but round the tip they gain 2 steps ((25, 9) to
// (25, 12): 5 steps past (26, 10) and (26, 11), 7 past column 27), more
// than 3 % of such short plans. The culprits are those two cells, the only
// changed ones on the shortest plans round the tip; with them given back
// every plan is as long as before.
TEST(LocalDetourCulpritsTest, AWallGrownAtItsTipGivesTheTipBack) {
  Grid original(40, 21, Cell::kFree);
  for (int c = 0; c <= 25; ++c) original.set(c, 10, Cell::kOccupied);
  Grid decoded = original;
  for (int c = 0; c <= 26; ++c) decoded.set(c, 11, Cell::kOccupied);
  decoded.set(26, 10, Cell::kOccupied);
  EXPECT_EQ(AsSet(LocalDetourCulprits(original, decoded, 8)),
            std::set<std::size_t>({original.Index(26, 10), original.Index(26, 11)}));
  decoded.set(26, 10, Cell::kFree);
  decoded.set(26, 11, Cell::kFree);
  EXPECT_TRUE(LocalDetourCulprits(original, decoded, 8).empty());
}

// The check shares its sources out in runs of a few thousand, each with its
// own searches, on several threads: on a map of 300 walled rooms, each
// holding the grown tip above (some 9,000 sources, three runs), it finds
// every room's two tip cells and nothing else, in the same order on 1 and 3
// threads.
TEST(LocalDetourCulpritsTest, FindsEveryTipAcrossRunsOfSourcesOnAnyThreads) {
  constexpr int kW = 42, kH = 23, kRoomsX = 20, kRoomsY = 15;
  Grid original(kW * kRoomsX, kH * kRoomsY, Cell::kFree);
  Grid decoded = original;
  std::set<std::size_t> expected;
  for (int ry = 0; ry < kRoomsY; ++ry) {
    for (int rx = 0; rx < kRoomsX; ++rx) {
      const int x0 = rx * kW, y0 = ry * kH;
      for (int c = 0; c < kW; ++c) {
        for (Grid* g : {&original, &decoded}) {
          g->set(x0 + c, y0, Cell::kOccupied);
          g->set(x0 + c, y0 + kH - 1, Cell::kOccupied);
        }
      }
      for (int r = 0; r < kH; ++r) {
        for (Grid* g : {&original, &decoded}) {
          g->set(x0, y0 + r, Cell::kOccupied);
          g->set(x0 + kW - 1, y0 + r, Cell::kOccupied);
        }
      }
      // The pattern of AWallGrownAtItsTipGivesTheTipBack, one cell in.
      for (int c = 1; c <= 26; ++c) {
        original.set(x0 + c, y0 + 11, Cell::kOccupied);
        decoded.set(x0 + c, y0 + 11, Cell::kOccupied);
      }
      for (int c = 1; c <= 27; ++c) decoded.set(x0 + c, y0 + 12, Cell::kOccupied);
      decoded.set(x0 + 27, y0 + 11, Cell::kOccupied);
      expected.insert(original.Index(x0 + 27, y0 + 11));
      expected.insert(original.Index(x0 + 27, y0 + 12));
    }
  }
  const std::vector<std::size_t> one = LocalDetourCulprits(original, decoded, 8, nullptr, 1);
  EXPECT_EQ(AsSet(one), expected);
  EXPECT_EQ(LocalDetourCulprits(original, decoded, 8, nullptr, 3), one);
}

// Steps of the shortest 4-connected plan over free cells from `a` to `b`;
// -1 when there is none. The test's own breadth-first search.
int PlanSteps(const Grid& g, CellIndex a, CellIndex b) {
  std::vector<int> steps(g.size(), -1);
  std::vector<std::size_t> queue{g.Index(a.col, a.row)};
  steps[queue[0]] = 0;
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const int c = static_cast<int>(queue[head] % g.width());
    const int r = static_cast<int>(queue[head] / g.width());
    const int dc[4] = {1, -1, 0, 0}, dr[4] = {0, 0, 1, -1};
    for (int k = 0; k < 4; ++k) {
      if (!g.Contains(c + dc[k], r + dr[k]) || g.at(c + dc[k], r + dr[k]) != Cell::kFree) continue;
      const std::size_t n = g.Index(c + dc[k], r + dr[k]);
      if (steps[n] >= 0) continue;
      steps[n] = steps[queue[head]] + 1;
      queue.push_back(n);
    }
  }
  return steps[g.Index(b.col, b.row)];
}

// A corridor `width` cells long and `height` wide along a wall on row 0.
Grid CorridorAlongAWall(int width, int height) {
  Grid g(width, height, Cell::kFree);
  for (int c = 0; c < width; ++c) g.set(c, 0, Cell::kOccupied);
  return g;
}

// The decode grows the wall by `rows` rows (rows 1 to `rows`) over columns
// [first, last]. A plan along row 1 past the whole stretch walks round it:
// 2 `rows` steps longer.
Grid WallGrownAlong(const Grid& original, int first, int last, int rows) {
  Grid decoded = original;
  for (int c = first; c <= last; ++c) {
    for (int r = 1; r <= rows; ++r) decoded.set(c, r, Cell::kOccupied);
  }
  return decoded;
}

// The plans from beside the stretch (and of at most `max_steps`) that the
// stretch check holds to their length, given back until it finds nothing:
// the rounds the encoder runs, on these cells alone.
Grid MendStretches(const Grid& original, Grid decoded, int max_steps) {
  for (int round = 0; round < 8; ++round) {
    const std::vector<std::size_t> culprits =
        StretchDetourCulprits(original, decoded, 32, max_steps);
    if (culprits.empty()) break;
    for (const std::size_t i : culprits) {
      EXPECT_EQ(original.cells()[i], Cell::kFree);
      EXPECT_NE(decoded.cells()[i], Cell::kFree);
      decoded.mutable_cells()[i] = Cell::kFree;
    }
  }
  return decoded;
}

// A 60-cell stretch grown by 2 rows: the plan from (19, 1) to (80, 1) is 4
// steps longer (61 to 65, 6.6 %), yet every plan of up to 32 steps from
// beside the stretch keeps its length (the corridor stays orthogonally
// convex), so the local check finds nothing. The stretch check gives back
// cells of the stretch only, after which the plan is as long as before and
// neither check finds anything.
TEST(StretchDetourCulpritsTest, FindsAWallGrownAlongALongStretch) {
  const Grid original = CorridorAlongAWall(100, 12);
  const Grid decoded = WallGrownAlong(original, 20, 79, 2);
  ASSERT_EQ(PlanSteps(decoded, {19, 1}, {80, 1}), 65);
  EXPECT_TRUE(LocalDetourCulprits(original, decoded, 32).empty());
  const std::vector<std::size_t> culprits = StretchDetourCulprits(original, decoded, 32, 69);
  ASSERT_FALSE(culprits.empty());
  EXPECT_EQ(AsSet(culprits).size(), culprits.size()) << "each cell once";
  for (const std::size_t i : culprits) {
    EXPECT_TRUE(i / 100 == 1 || i / 100 == 2) << "row " << i / 100;
    EXPECT_GE(i % 100, 20u);
    EXPECT_LE(i % 100, 79u);
  }
  const Grid mended = MendStretches(original, decoded, 69);
  EXPECT_EQ(PlanSteps(mended, {19, 1}, {80, 1}), 61);
  EXPECT_TRUE(LocalDetourCulprits(original, mended, 32).empty());
}

// The same with a pocket in the wall (50, 0) that the decode fills, so that
// the stretch's cells are no longer in one row: the plan past its ends is
// still found (it was missed when the sources were every k-th cell beside
// the stretch rather than all of them).
TEST(StretchDetourCulpritsTest, FindsItWithAPocketInTheWall) {
  Grid original = CorridorAlongAWall(100, 12);
  original.set(50, 0, Cell::kFree);
  Grid decoded = WallGrownAlong(original, 20, 79, 2);
  decoded.set(50, 0, Cell::kOccupied);
  ASSERT_EQ(PlanSteps(decoded, {19, 1}, {80, 1}), 65);
  EXPECT_FALSE(StretchDetourCulprits(original, decoded, 32, 69).empty());
  EXPECT_EQ(PlanSteps(MendStretches(original, decoded, 69), {19, 1}, {80, 1}), 61);
}

// A stretch down a column, and one grown by 4 cells (T = 4) over 258
// columns: its end-to-end plan, 259 steps, is 8 steps (3.09 %) longer,
// which a check of up to 200 T / 3 + 2 = 269 steps sees.
TEST(StretchDetourCulpritsTest, FindsVerticalAndLongStretches) {
  Grid tall(12, 100, Cell::kFree);
  for (int r = 0; r < 100; ++r) tall.set(0, r, Cell::kOccupied);
  Grid tall_decoded = tall;
  for (int r = 20; r <= 79; ++r) {
    tall_decoded.set(1, r, Cell::kOccupied);
    tall_decoded.set(2, r, Cell::kOccupied);
  }
  EXPECT_EQ(PlanSteps(MendStretches(tall, tall_decoded, 69), {1, 19}, {1, 80}), 61);

  const Grid wide = CorridorAlongAWall(300, 14);
  const Grid wide_decoded = WallGrownAlong(wide, 20, 277, 4);
  ASSERT_EQ(PlanSteps(wide_decoded, {19, 1}, {278, 1}), 267);
  EXPECT_EQ(PlanSteps(MendStretches(wide, wide_decoded, 269), {19, 1}, {278, 1}), 259);
}

// A stretch the local check spans (20 columns, within its 32 steps) is left
// to it: the local check finds its detour, the stretch check does not look.
TEST(StretchDetourCulpritsTest, LeavesShortStretchesToTheLocalCheck) {
  const Grid original = CorridorAlongAWall(100, 12);
  const Grid decoded = WallGrownAlong(original, 40, 59, 2);
  EXPECT_FALSE(LocalDetourCulprits(original, decoded, 32).empty());
  EXPECT_TRUE(StretchDetourCulprits(original, decoded, 32, 69).empty());
}

// A wall grown along the whole corridor changes no plan (no plan can enter
// the stretch from an end; its ends are the map's edges): the stretch check
// gives nothing back.
TEST(StretchDetourCulpritsTest, GivesNothingBackWhereNoPlanIsLonger) {
  const Grid original = CorridorAlongAWall(100, 12);
  const Grid decoded = WallGrownAlong(original, 0, 99, 2);
  EXPECT_TRUE(StretchDetourCulprits(original, decoded, 32, 69).empty());
}

// Lost cells cost what they are, not how far they lie: below a band of
// lost rows (5-7) the decode splits the room's lower part into A (columns
// 0-9) and B (12-19, and (11, 18)) by lost columns 10 and 11, and leaves a
// way from the main piece to A through one lost cell, (2, 7). B is nearest
// the main piece straight up through the band (3 lost cells); through A it
// is 2 (with (10, 18), where the columns are one cell thick). A search by
// lost cells gives back those 2; one by steps would give back 4.
TEST(TopologyFaultsTest, SplitCulpritsCountLostCellsNotSteps) {
  const Grid original(20, 20, Cell::kFree);
  Grid decoded = original;
  for (int c = 0; c < 20; ++c) {
    for (int r = 5; r <= 7; ++r) decoded.set(c, r, Cell::kOccupied);
  }
  decoded.set(2, 5, Cell::kFree);
  decoded.set(2, 6, Cell::kFree);
  for (int r = 8; r < 20; ++r) {
    decoded.set(10, r, Cell::kOccupied);
    if (r != 18) decoded.set(11, r, Cell::kOccupied);
  }

  const TopologyFaults faults = FindTopologyFaults(original, decoded, true);
  ASSERT_EQ(faults.splits, 1u);
  EXPECT_EQ(AsSet(faults.split_culprits),
            std::set<std::size_t>({original.Index(2, 7), original.Index(10, 18)}));
  for (const std::size_t i : faults.split_culprits) decoded.mutable_cells()[i] = Cell::kFree;
  EXPECT_EQ(FindTopologyFaults(original, decoded, false).splits, 0u);
}

// Whether `grid` or `extra` has a free cell within Chebyshev t of cell i
// (window scan).
bool ServedWithin(const Grid& grid, const std::set<std::size_t>& extra, std::size_t i, int t) {
  const int c = static_cast<int>(i % grid.width()), r = static_cast<int>(i / grid.width());
  for (int y = r - t; y <= r + t; ++y) {
    for (int x = c - t; x <= c + t; ++x) {
      if (!grid.Contains(x, y)) continue;
      if (grid.at(x, y) == Cell::kFree || extra.count(grid.Index(x, y))) return true;
    }
  }
  return false;
}

// Lost cells (free in `original`, more than t from every free cell of
// `decoded`), by window scans.
std::vector<std::size_t> LostFree(const Grid& original, const Grid& decoded, int t) {
  std::vector<std::size_t> lost;
  for (std::size_t i = 0; i < original.size(); ++i) {
    if (original.cells()[i] == Cell::kFree && !ServedWithin(decoded, {}, i, t)) lost.push_back(i);
  }
  return lost;
}

// The decode thickens a wall to rows 4-6 across a 10 x 11 free map: the
// ten cells of row 5 lie 2 from free space. At t = 1 a cell given back on
// row 4 serves three columns of row 5 and touches row 3's free space:
// ceil(10 / 3) = 4 cells, where giving back every lost cell would be 10.
TEST(FreeCoverTest, OneCellServesItsNeighboursAlongAThickenedWall) {
  Grid original(10, 11, Cell::kFree);
  Grid decoded = original;
  for (int c = 0; c < 10; ++c) {
    for (int r = 4; r <= 6; ++r) decoded.set(c, r, Cell::kOccupied);
  }
  const std::vector<std::size_t> lost = LostFree(original, decoded, 1);
  ASSERT_EQ(lost.size(), 10u) << "row 5 only: rows 4 and 6 are within 1 of rows 3 and 7";

  const std::vector<std::size_t> cover = FreeCover(original, decoded, lost, 1);
  const std::set<std::size_t> given(cover.begin(), cover.end());
  for (const std::size_t i : lost) EXPECT_TRUE(ServedWithin(decoded, given, i, 1)) << i;
  EXPECT_EQ(cover.size(), 4u);
}

// On random grids and their random decodes every lost cell is served, and
// only cells free in the original and not in the decode are given back.
// The decode's free share falls as 0.15 / t^2, so that about a third of
// the (2t + 1)^2 windows hold no free cell at every t and each t has lost
// cells to serve.
TEST(FreeCoverTest, ServesEveryLostCellOnRandomGrids) {
  std::mt19937 rng(20261127);
  int trials_with_lost[5] = {};
  for (int trial = 0; trial < 60; ++trial) {
    const int w = 8 + static_cast<int>(rng() % 30), h = 8 + static_cast<int>(rng() % 30);
    const int t = 1 + static_cast<int>(rng() % 4);
    const unsigned free_per_mille = 150u / static_cast<unsigned>(t * t);
    Grid original(w, h, Cell::kFree), decoded(w, h, Cell::kFree);
    for (std::size_t i = 0; i < original.size(); ++i) {
      const unsigned v = rng() % 10;
      original.mutable_cells()[i] = v < 6 ? Cell::kFree : v < 8 ? Cell::kOccupied : Cell::kUnknown;
      decoded.mutable_cells()[i] = rng() % 1000 < free_per_mille ? Cell::kFree : Cell::kOccupied;
    }
    const std::vector<std::size_t> lost = LostFree(original, decoded, t);
    trials_with_lost[t] += lost.empty() ? 0 : 1;
    const std::vector<std::size_t> cover = FreeCover(original, decoded, lost, t);
    const std::set<std::size_t> given(cover.begin(), cover.end());
    for (const std::size_t i : given) {
      EXPECT_EQ(original.cells()[i], Cell::kFree);
      EXPECT_NE(decoded.cells()[i], Cell::kFree);
    }
    for (const std::size_t i : lost) EXPECT_TRUE(ServedWithin(decoded, given, i, t)) << i;
    EXPECT_LE(cover.size(), lost.size());
  }
  for (int t = 1; t <= 4; ++t) EXPECT_GE(trials_with_lost[t], 5) << "t = " << t;
}

}  // namespace
}  // namespace linemap::tolerance_internal
