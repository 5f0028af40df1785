#include "linemap/labeling.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <map>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace linemap {
namespace {

BinaryMask RandomMask(std::mt19937* rng, int w, int h, double density) {
  BinaryMask mask(w, h);
  std::bernoulli_distribution on(density);
  for (auto& b : mask.bits) b = on(*rng);
  return mask;
}

// Plain flood fill: component ids in raster order of first cells.
std::vector<int> FloodFill(const BinaryMask& mask, bool eight) {
  std::vector<int> ids(mask.bits.size(), 0);
  int next = 0;
  for (int r = 0; r < mask.height; ++r) {
    for (int c = 0; c < mask.width; ++c) {
      if (!mask.at(c, r) || ids[mask.Index(c, r)]) continue;
      ++next;
      std::vector<CellIndex> stack{{c, r}};
      ids[mask.Index(c, r)] = next;
      while (!stack.empty()) {
        const CellIndex cur = stack.back();
        stack.pop_back();
        for (int dr = -1; dr <= 1; ++dr) {
          for (int dc = -1; dc <= 1; ++dc) {
            if ((!dr && !dc) || (!eight && dr && dc)) continue;
            const int nc = cur.col + dc, nr = cur.row + dr;
            if (!mask.get(nc, nr) || ids[mask.Index(nc, nr)]) continue;
            ids[mask.Index(nc, nr)] = next;
            stack.push_back({nc, nr});
          }
        }
      }
    }
  }
  return ids;
}

TEST(LabelingTest, HandExample) {
  // Row 0 is the first line below: a U, a lone cell, and a cell that only
  // touches the U diagonally.
  const char* rows[] = {"#.#..", "#.#.#", "###..", "...#."};
  BinaryMask mask(5, 4);
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 5; ++c) mask.set(c, r, rows[r][c] == '#');
  }
  const Labeling four = LabelComponents(mask, Connectivity::kFour);
  ASSERT_EQ(four.components.size(), 3u);
  EXPECT_EQ(four.components[0].cell_count, 7u);
  EXPECT_EQ(four.components[0].first_cell, (CellIndex{0, 0}));
  EXPECT_EQ(four.components[0].box, (BoundingBox{0, 0, 2, 2}));
  EXPECT_EQ(four.components[1].first_cell, (CellIndex{4, 1}));
  EXPECT_EQ(four.components[2].first_cell, (CellIndex{3, 3}));
  const Labeling eight = LabelComponents(mask, Connectivity::kEight);
  ASSERT_EQ(eight.components.size(), 2u);
  EXPECT_EQ(eight.components[0].cell_count, 8u);
  EXPECT_EQ(eight.components[0].box, (BoundingBox{0, 0, 3, 3}));
  EXPECT_EQ(eight.components[1].cell_count, 1u);
}

// Labels, cell counts, first cells and boxes as the plain flood fill gives
// them.
void ExpectMatchesFloodFill(const BinaryMask& mask, bool eight, const std::string& what) {
  const Labeling got = LabelComponents(mask, eight ? Connectivity::kEight : Connectivity::kFour);
  const std::vector<int> want = FloodFill(mask, eight);
  ASSERT_EQ(got.labels.size(), want.size()) << what;
  std::map<int, ComponentStats> stats;
  for (int r = 0; r < mask.height; ++r) {
    for (int c = 0; c < mask.width; ++c) {
      const int id = want[mask.Index(c, r)];
      ASSERT_EQ(got.at(c, r), id) << what << " eight " << eight << " at " << c << "," << r;
      if (!id) continue;
      ComponentStats& s = stats[id];
      if (s.cell_count == 0) s = {0, {c, r}, {c, r, c, r}};
      ++s.cell_count;
      s.box.min_col = std::min(s.box.min_col, c);
      s.box.max_col = std::max(s.box.max_col, c);
      s.box.min_row = std::min(s.box.min_row, r);
      s.box.max_row = std::max(s.box.max_row, r);
    }
  }
  ASSERT_EQ(got.components.size(), stats.size()) << what;
  for (const auto& [id, s] : stats) {
    EXPECT_EQ(got.components[id - 1].cell_count, s.cell_count) << what;
    EXPECT_EQ(got.components[id - 1].first_cell, s.first_cell) << what;
    EXPECT_EQ(got.components[id - 1].box, s.box) << what;
  }
}

TEST(LabelingTest, MatchesFloodFillOnRandomGrids) {
  std::mt19937 rng(777);
  for (int trial = 0; trial < 80; ++trial) {
    const int w = 1 + (trial * 13) % 90, h = 1 + (trial * 7) % 29;
    const double density = trial % 6 == 5 ? 0.03 : 0.3 + 0.1 * (trial % 5);  // some sparse
    const BinaryMask mask = RandomMask(&rng, w, h, density);
    for (bool eight : {false, true}) {
      ExpectMatchesFloodFill(mask, eight, "trial " + std::to_string(trial));
    }
  }
}

// Dense masks are where provisional labels merge most: free space of a
// map is mostly one component with holes, and one long run at the bottom
// joins every tooth of a comb above it only on the last row.
TEST(LabelingTest, MatchesFloodFillOnDenseGridsAndLateMerges) {
  std::mt19937 rng(4242);
  for (const double density : {0.8, 0.9, 0.97, 1.0}) {
    for (const auto& [w, h] : {std::pair{257, 131}, std::pair{64, 300}, std::pair{1, 97}}) {
      const BinaryMask mask = RandomMask(&rng, w, h, density);
      for (bool eight : {false, true}) {
        ExpectMatchesFloodFill(mask, eight,
                               "density " + std::to_string(density) + " " + std::to_string(w));
      }
    }
  }
  // A comb: teeth on every other column, joined only by the last row; and
  // the same upside down; and diagonal staircases, which only 8-connectivity
  // joins.
  BinaryMask comb(101, 60), flipped(101, 60), stairs(80, 80);
  for (int c = 0; c < comb.width; ++c) {
    for (int r = 0; r < comb.height; ++r) {
      const bool on = c % 2 == 0 || r == comb.height - 1;
      comb.bits[comb.Index(c, r)] = on;
      flipped.bits[flipped.Index(c, comb.height - 1 - r)] = on;
    }
  }
  for (int r = 0; r < stairs.height; ++r) {
    for (int c = 0; c < stairs.width; ++c) {
      stairs.bits[stairs.Index(c, r)] = (c + r) % 7 == 0 ? 0xFF : 0;  // any non-zero byte is set
    }
  }
  for (bool eight : {false, true}) {
    ExpectMatchesFloodFill(comb, eight, "comb");
    ExpectMatchesFloodFill(flipped, eight, "flipped comb");
    ExpectMatchesFloodFill(stairs, eight, "stairs");
  }
}

// A map of no columns (or no rows) has no components; its rows must not
// be indexed (a 0 x 5 map saved within a tolerance labels its free space).
TEST(LabelingTest, MasksWithoutCellsHaveNoComponents) {
  for (const auto& [w, h] : {std::pair{0, 5}, std::pair{5, 0}, std::pair{0, 0}}) {
    for (const Connectivity c : {Connectivity::kFour, Connectivity::kEight}) {
      const Labeling l = LabelComponents(BinaryMask(w, h), c);
      EXPECT_EQ(l.width, w);
      EXPECT_EQ(l.height, h);
      EXPECT_TRUE(l.labels.empty());
      EXPECT_TRUE(l.components.empty());
    }
  }
}

// Component cells 4-adjacent to the background region that reaches the
// mask's edge (4-connected background, the dual of 8-connected objects).
std::vector<CellIndex> OuterBoundaryCells(const BinaryMask& mask, const Labeling& labels,
                                          std::int32_t label) {
  const int w = mask.width + 2, h = mask.height + 2;  // padded
  std::vector<std::uint8_t> outside(static_cast<std::size_t>(w) * h, 0);
  auto is_object = [&](int c, int r) { return labels.get(c - 1, r - 1) == label; };
  std::vector<CellIndex> stack{{0, 0}};
  outside[0] = 1;
  while (!stack.empty()) {
    const CellIndex cur = stack.back();
    stack.pop_back();
    const int dc[4] = {1, -1, 0, 0}, dr[4] = {0, 0, 1, -1};
    for (int k = 0; k < 4; ++k) {
      const int c = cur.col + dc[k], r = cur.row + dr[k];
      if (c < 0 || r < 0 || c >= w || r >= h || is_object(c, r)) continue;
      if (outside[static_cast<std::size_t>(r) * w + c]) continue;
      outside[static_cast<std::size_t>(r) * w + c] = 1;
      stack.push_back({c, r});
    }
  }
  std::vector<CellIndex> cells;
  for (int r = 0; r < mask.height; ++r) {
    for (int c = 0; c < mask.width; ++c) {
      if (labels.at(c, r) != label) continue;
      const int dc[4] = {1, -1, 0, 0}, dr[4] = {0, 0, 1, -1};
      for (int k = 0; k < 4; ++k) {
        if (outside[static_cast<std::size_t>(r + 1 + dr[k]) * w + c + 1 + dc[k]]) {
          cells.push_back({c, r});
          break;
        }
      }
    }
  }
  return cells;
}

TEST(LabelingTest, OuterContourIsClosedAndCoversTheOuterBoundary) {
  std::mt19937 rng(99);
  for (int trial = 0; trial < 40; ++trial) {
    const BinaryMask mask = RandomMask(&rng, 3 + trial % 20, 3 + trial % 13, 0.55);
    const Labeling labels = LabelComponents(mask, Connectivity::kEight);
    for (std::size_t k = 0; k < labels.components.size(); ++k) {
      const std::int32_t label = static_cast<std::int32_t>(k + 1);
      const std::vector<CellIndex> chain = TraceOuterContour(labels, label);
      ASSERT_FALSE(chain.empty());
      EXPECT_EQ(chain.front(), labels.components[k].first_cell);
      for (std::size_t i = 0; i < chain.size(); ++i) {
        ASSERT_EQ(labels.get(chain[i].col, chain[i].row), label);
        if (chain.size() == 1) break;
        const CellIndex& a = chain[i];
        const CellIndex& b = chain[(i + 1) % chain.size()];
        ASSERT_EQ(std::max(std::abs(a.col - b.col), std::abs(a.row - b.row)), 1)
            << "trial " << trial << " label " << label << " at " << i;
      }
      for (const CellIndex& cell : OuterBoundaryCells(mask, labels, label)) {
        EXPECT_NE(std::find(chain.begin(), chain.end(), cell), chain.end())
            << "trial " << trial << " misses " << cell.col << "," << cell.row;
      }
    }
  }
}

}  // namespace
}  // namespace linemap
