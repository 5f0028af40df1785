// CoveringSegments checked by brute force: every edge cell left out by the
// walls ends within one cell of a new segment, and every new segment lies on
// the obstacles.
#include "codec/layers/wall_cover.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "codec/layers/raster.h"

namespace linemap {
namespace {

// Euclidean distance from cell p to segment ab, written out here.
double Distance(CellIndex p, const LatticeSegment& s) {
  const double ax = s.a.col, ay = s.a.row, bx = s.b.col, by = s.b.row;
  const double dx = bx - ax, dy = by - ay, len2 = dx * dx + dy * dy;
  double t = len2 > 0 ? ((p.col - ax) * dx + (p.row - ay) * dy) / len2 : 0;
  t = t < 0 ? 0 : t > 1 ? 1 : t;
  return std::hypot(p.col - (ax + t * dx), p.row - (ay + t * dy));
}

double Nearest(CellIndex p, const std::vector<LatticeSegment>& segments) {
  double best = INFINITY;
  for (const LatticeSegment& s : segments) best = std::min(best, Distance(p, s));
  return best;
}

bool IsEdge(const Grid& g, int c, int r) {
  if (g.at(c, r) != Cell::kOccupied) return false;
  const int dc[4] = {1, -1, 0, 0}, dr[4] = {0, 0, 1, -1};
  for (int k = 0; k < 4; ++k) {
    if (g.Contains(c + dc[k], r + dr[k]) && g.at(c + dc[k], r + dr[k]) == Cell::kFree) return true;
  }
  return false;
}

// Free space with walls of random length and specks and clutter.
Grid ClutteredRoom(std::mt19937* rng, int w, int h) {
  Grid g(w, h, Cell::kFree);
  for (int c = 0; c < w; ++c) {
    g.set(c, 0, Cell::kOccupied);
    g.set(c, h - 1, Cell::kOccupied);
  }
  for (int k = 0; k < w * h / 40; ++k) {
    const int c = static_cast<int>((*rng)() % w), r = static_cast<int>((*rng)() % h);
    g.set(c, r, (*rng)() % 5 == 0 ? Cell::kUnknown : Cell::kOccupied);
    if ((*rng)() % 3 == 0 && c + 1 < w) g.set(c + 1, r, Cell::kOccupied);
    if ((*rng)() % 4 == 0 && r + 1 < h) g.set(c, r + 1, Cell::kOccupied);
  }
  return g;
}

void ExpectCovers(const Grid& g, const std::vector<LatticeSegment>& walls,
                  const std::vector<std::uint8_t>* covered) {
  const std::vector<LatticeSegment> cover = CoveringSegments(g, walls, covered);
  std::vector<LatticeSegment> all = walls;
  all.insert(all.end(), cover.begin(), cover.end());
  for (int r = 0; r < g.height(); ++r) {
    for (int c = 0; c < g.width(); ++c) {
      if (!IsEdge(g, c, r) || (covered && (*covered)[g.Index(c, r)])) continue;
      EXPECT_LE(Nearest({c, r}, all), 1.0) << "edge cell " << c << "," << r;
    }
  }
  for (const LatticeSegment& s : cover) {
    EXPECT_FALSE(s.a == s.b);
    EXPECT_TRUE(g.Contains(s.a.col, s.a.row) && g.Contains(s.b.col, s.b.row));
    RasterizeSegment(s.a, s.b, [&](int c, int r) {
      bool near = false;
      for (int dr = -1; dr <= 1; ++dr) {
        for (int dc = -1; dc <= 1; ++dc) {
          near = near || (g.Contains(c + dc, r + dr) && g.at(c + dc, r + dr) == Cell::kOccupied);
        }
      }
      EXPECT_TRUE(near) << "segment cell " << c << "," << r << " off the obstacles";
    });
  }
  EXPECT_EQ(CoveringSegments(g, walls, covered), cover);  // deterministic
}

TEST(WallCoverTest, EveryLeftOutEdgeCellEndsNearASegmentOnTheObstacles) {
  std::mt19937 rng(21);
  for (int trial = 0; trial < 20; ++trial) {
    const Grid g =
        ClutteredRoom(&rng, 20 + static_cast<int>(rng() % 60), 10 + static_cast<int>(rng() % 40));
    // The two long walls as the extractor would give them, or none.
    std::vector<LatticeSegment> walls;
    if (trial % 2 == 0) {
      walls = {{{0, 0}, {g.width() - 1, 0}},
               {{0, g.height() - 1}, {g.width() - 1, g.height() - 1}}};
    }
    ExpectCovers(g, walls, nullptr);
  }
}

TEST(WallCoverTest, CellsMarkedCoveredAndCellsNearWallsGetNothing) {
  Grid g(30, 20, Cell::kFree);
  for (int c = 5; c < 25; ++c) g.set(c, 10, Cell::kOccupied);
  // Already within one cell of this wall.
  EXPECT_TRUE(CoveringSegments(g, {{{5, 10}, {24, 10}}}, nullptr).empty());
  // A speck, marked as furniture: nothing either.
  g.set(2, 2, Cell::kOccupied);
  std::vector<std::uint8_t> furniture(g.size(), 0);
  furniture[g.Index(2, 2)] = 1;
  EXPECT_TRUE(CoveringSegments(g, {{{5, 10}, {24, 10}}}, &furniture).empty());
  // Unmarked, it gets a one-cell stub through it.
  const auto stub = CoveringSegments(g, {{{5, 10}, {24, 10}}}, nullptr);
  ASSERT_EQ(stub.size(), 1u);
  EXPECT_TRUE(stub[0].a == (CellIndex{2, 2}) || stub[0].b == (CellIndex{2, 2}));
}

// The layer extractor passes the edge cells it has already found; marked
// by this test's own definition (any non-zero byte), they give the same
// segments as the overload that finds them, with and without furniture.
TEST(WallCoverTest, EdgeCellsGivenByTheCallerGiveTheSameSegments) {
  std::mt19937 rng(58);
  for (int trial = 0; trial < 12; ++trial) {
    const Grid g =
        ClutteredRoom(&rng, 20 + static_cast<int>(rng() % 70), 10 + static_cast<int>(rng() % 50));
    std::vector<std::uint8_t> edge(g.size(), 0), furniture(g.size(), 0);
    for (int r = 0; r < g.height(); ++r) {
      for (int c = 0; c < g.width(); ++c) {
        if (IsEdge(g, c, r)) edge[g.Index(c, r)] = 0x5A;
        if (IsEdge(g, c, r) && rng() % 4 == 0) furniture[g.Index(c, r)] = 1;
      }
    }
    const std::vector<LatticeSegment> walls = {{{0, 0}, {g.width() - 1, 0}}};
    for (const std::vector<std::uint8_t>* covered :
         {static_cast<decltype(&furniture)>(nullptr), &furniture}) {
      const auto given = CoveringSegments(g, walls, covered, edge.data());
      EXPECT_EQ(given, CoveringSegments(g, walls, covered)) << "trial " << trial;
      EXPECT_FALSE(given.empty()) << "trial " << trial;  // the clutter is left out
    }
  }
}

TEST(WallCoverTest, AnLShapedClusterIsSplitRatherThanCrossedDiagonally) {
  Grid g(30, 30, Cell::kFree);
  for (int c = 5; c <= 20; ++c) g.set(c, 5, Cell::kOccupied);
  for (int r = 5; r <= 20; ++r) g.set(5, r, Cell::kOccupied);
  const auto cover = CoveringSegments(g, {}, nullptr);
  EXPECT_GE(cover.size(), 2u);
  ExpectCovers(g, {}, nullptr);
}

}  // namespace
}  // namespace linemap
