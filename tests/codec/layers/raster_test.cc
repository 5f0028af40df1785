// The decoder's rasterisation against an independent, straightforward
// version written from the spec's words (spec/format.md "Rasterisation").
#include "codec/layers/raster.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "tests/testing/reference_geometry.h"

namespace linemap {
namespace {

using Cells = std::vector<std::pair<int, int>>;

Cells Rasterize(CellIndex a, CellIndex b) {
  Cells out;
  RasterizeSegment(a, b, [&](int c, int r) { out.emplace_back(c, r); });
  return out;
}

// Spec: step i of n = max(|dx|,|dy|) covers, on each axis, the cell whose
// centre is nearest to a + i/n * (b - a), halves going to the larger value.
// Found here by searching candidate cells and comparing exact rationals.
int NearestUp(int start, int delta, int i, int n) {
  // Exact point: start + i * delta / n. Compare |2 n (x - start) - 2 i delta|.
  int best = 0;
  long long best_err = -1;
  for (int x = start - std::abs(delta) - 1; x <= start + std::abs(delta) + 1; ++x) {
    const long long err = std::llabs(2LL * n * (x - start) - 2LL * i * delta);
    if (best_err < 0 || err < best_err || (err == best_err && x > best)) {
      best = x;
      best_err = err;
    }
  }
  return best;
}

Cells SlowRasterize(CellIndex a, CellIndex b) {
  const int dx = b.col - a.col;
  const int dy = b.row - a.row;
  const int n = std::max(std::abs(dx), std::abs(dy));
  if (n == 0) return {{a.col, a.row}};
  Cells out;
  for (int i = 0; i <= n; ++i) {
    out.emplace_back(NearestUp(a.col, dx, i, n), NearestUp(a.row, dy, i, n));
  }
  return out;
}

TEST(RasterizeSegmentTest, KnownAnswers) {
  EXPECT_EQ(Rasterize({2, 3}, {2, 3}), (Cells{{2, 3}}));
  EXPECT_EQ(Rasterize({0, 0}, {3, 0}), (Cells{{0, 0}, {1, 0}, {2, 0}, {3, 0}}));
  EXPECT_EQ(Rasterize({0, 0}, {2, 2}), (Cells{{0, 0}, {1, 1}, {2, 2}}));
  // Slope 1/2: the half-way rows round up.
  EXPECT_EQ(Rasterize({0, 0}, {4, 2}), (Cells{{0, 0}, {1, 1}, {2, 1}, {3, 2}, {4, 2}}));
  // Going left and down: -0.5 rounds up to 0.
  EXPECT_EQ(Rasterize({4, 2}, {0, 0}), (Cells{{4, 2}, {3, 2}, {2, 1}, {1, 1}, {0, 0}}));
  EXPECT_EQ(Rasterize({0, 0}, {1, 3}), (Cells{{0, 0}, {0, 1}, {1, 2}, {1, 3}}));
}

TEST(RasterizeSegmentTest, AgreesWithSlowVersionOnRandomSegments) {
  std::mt19937 rng(11);
  for (int trial = 0; trial < 20000; ++trial) {
    const int span = trial < 10000 ? 8 : 300;
    const CellIndex a{static_cast<int>(rng() % span), static_cast<int>(rng() % span)};
    const CellIndex b{static_cast<int>(rng() % span), static_cast<int>(rng() % span)};
    ASSERT_EQ(Rasterize(a, b), SlowRasterize(a, b))
        << "(" << a.col << "," << a.row << ") -> (" << b.col << "," << b.row << ")";
  }
}

// The spec's formula as written, a division per step: the rasteriser
// carries its quotients instead, which must give the same cells anywhere
// on the lattice (negative coordinates, far from the origin, long steps).
Cells DividingRasterize(CellIndex a, CellIndex b) {
  const std::int64_t dx = std::int64_t{b.col} - a.col, dy = std::int64_t{b.row} - a.row;
  const std::int64_t n = std::max(std::llabs(dx), std::llabs(dy));
  if (n == 0) return {{a.col, a.row}};
  Cells out;
  for (std::int64_t i = 0; i <= n; ++i) {
    out.emplace_back(static_cast<int>(a.col + FloorDiv(2 * i * dx + n, 2 * n)),
                     static_cast<int>(a.row + FloorDiv(2 * i * dy + n, 2 * n)));
  }
  return out;
}

TEST(RasterizeSegmentTest, AgreesWithTheDivisionFormulaAnywhere) {
  std::mt19937 rng(12);
  std::uniform_int_distribution<int> origin(-1000000000, 1000000000);
  std::uniform_int_distribution<int> step(-5000, 5000);
  for (int trial = 0; trial < 20000; ++trial) {
    const CellIndex a{origin(rng), origin(rng)};
    const CellIndex b{a.col + step(rng), a.row + step(rng) / (trial % 7 + 1)};
    ASSERT_EQ(Rasterize(a, b), DividingRasterize(a, b))
        << "(" << a.col << "," << a.row << ") -> (" << b.col << "," << b.row << ")";
  }
}

TEST(RasterizeSegmentTest, CellsAreEightConnectedAndEndAtTheEndpoints) {
  std::mt19937 rng(3);
  for (int trial = 0; trial < 2000; ++trial) {
    const CellIndex a{static_cast<int>(rng() % 100), static_cast<int>(rng() % 100)};
    const CellIndex b{static_cast<int>(rng() % 100), static_cast<int>(rng() % 100)};
    const Cells cells = Rasterize(a, b);
    EXPECT_EQ(cells.front(), std::make_pair(a.col, a.row));
    EXPECT_EQ(cells.back(), std::make_pair(b.col, b.row));
    for (std::size_t i = 1; i < cells.size(); ++i) {
      EXPECT_LE(std::abs(cells[i].first - cells[i - 1].first), 1);
      EXPECT_LE(std::abs(cells[i].second - cells[i - 1].second), 1);
    }
  }
}

std::set<std::pair<int, int>> Fill(const std::vector<CellIndex>& chain) {
  std::set<std::pair<int, int>> out;
  FillChain(chain, [&](int c, int r) { out.emplace(c, r); });
  return out;
}

// The cells of `chain`'s box and one cell around it that `encloses`.
template <typename Encloses>
std::set<std::pair<int, int>> CellsAround(const std::vector<CellIndex>& chain, Encloses encloses) {
  int min_c = chain[0].col, max_c = chain[0].col, min_r = chain[0].row, max_r = chain[0].row;
  for (const CellIndex& p : chain) {
    min_c = std::min(min_c, p.col);
    max_c = std::max(max_c, p.col);
    min_r = std::min(min_r, p.row);
    max_r = std::max(max_r, p.row);
  }
  std::set<std::pair<int, int>> out;
  for (int r = min_r - 1; r <= max_r + 1; ++r) {
    for (int c = min_c - 1; c <= max_c + 1; ++c) {
      if (encloses(c, r)) out.emplace(c, r);
    }
  }
  return out;
}

// The spec's rule cell by cell (ReferenceChainEncloses).
std::set<std::pair<int, int>> SlowFill(const std::vector<CellIndex>& chain) {
  return CellsAround(chain,
                     [&](int c, int r) { return testing::ReferenceChainEncloses(chain, c, r); });
}

TEST(FillChainTest, KnownAnswerSquareRing) {
  // The 8-cell ring around (1, 1) encloses it.
  const std::vector<CellIndex> ring = {{0, 0}, {1, 0}, {2, 0}, {2, 1},
                                       {2, 2}, {1, 2}, {0, 2}, {0, 1}};
  std::set<std::pair<int, int>> all;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) all.emplace(c, r);
  }
  EXPECT_EQ(Fill(ring), all);
}

TEST(FillChainTest, KnownAnswerDiamond) {
  // A diamond through (2,0), (4,2), (2,4), (0,2): its inside is the 13 cells
  // with |c - 2| + |r - 2| <= 2.
  const std::vector<CellIndex> diamond = {{2, 0}, {3, 1}, {4, 2}, {3, 3},
                                          {2, 4}, {1, 3}, {0, 2}, {1, 1}};
  std::set<std::pair<int, int>> expected;
  for (int r = 0; r <= 4; ++r) {
    for (int c = 0; c <= 4; ++c) {
      if (std::abs(c - 2) + std::abs(r - 2) <= 2) expected.emplace(c, r);
    }
  }
  EXPECT_EQ(Fill(diamond), expected);
}

// A random closed 8-connected walk: out and back by different random paths.
std::vector<CellIndex> RandomChain(std::mt19937& rng) {
  const int steps = 2 + static_cast<int>(rng() % 60);
  std::vector<CellIndex> chain = {{30, 30}};
  for (int i = 0; i < steps; ++i) {
    CellIndex next = chain.back();
    do {
      next = chain.back();
      next.col += static_cast<int>(rng() % 3) - 1;
      next.row += static_cast<int>(rng() % 3) - 1;
    } while (next == chain.back());
    chain.push_back(next);
  }
  // Walk back to the start, one 8-step at a time.
  while (std::abs(chain.back().col - 30) > 1 || std::abs(chain.back().row - 30) > 1) {
    CellIndex next = chain.back();
    next.col += next.col < 30 ? 1 : next.col > 30 ? -1 : 0;
    next.row += next.row < 30 ? 1 : next.row > 30 ? -1 : 0;
    if (rng() % 4 == 0 && next.col != 30) next.row = chain.back().row;  // wander a little
    if (next == chain.back()) next.row += next.row < 30 ? 1 : -1;
    chain.push_back(next);
  }
  if (chain.back() == chain.front()) chain.pop_back();
  return chain;
}

TEST(FillChainTest, AgreesWithSlowVersionOnRandomChains) {
  std::mt19937 rng(5);
  for (int trial = 0; trial < 3000; ++trial) {
    const std::vector<CellIndex> chain = RandomChain(rng);
    ASSERT_GE(chain.size(), 1u);
    ASSERT_EQ(Fill(chain), SlowFill(chain)) << "trial " << trial;
  }
}

// ChainEncloses tests one cell: the cells it accepts around each random
// chain are exactly the spec's.
TEST(ChainEnclosesTest, AgreesWithSlowVersionOnRandomChains) {
  std::mt19937 rng(6);
  for (int trial = 0; trial < 1000; ++trial) {
    const std::vector<CellIndex> chain = RandomChain(rng);
    const std::set<std::pair<int, int>> want = SlowFill(chain);
    const std::set<std::pair<int, int>> got = CellsAround(chain, [&](int c, int r) {
      return ChainEncloses(chain, {c, r});
    });
    ASSERT_EQ(got, want) << "trial " << trial;
  }
}

}  // namespace
}  // namespace linemap
