// PlanCulprits against a plain re-implementation, cell for cell and in
// order: its contract (tolerance_internal.h) and the rules
// tolerance_plans.cc fixes besides (the sampled sources' sequence, ties to
// the first neighbour in the order +col, -col, +row, -row, the goals in
// raster order, a walk stopping at a cell walked for the same source and
// side). The fitting gives the culprits back in the order they come (two
// culprits in one block can unfill it either way), so the order is part of
// the result. The reference keeps everything a search finds (whole-map
// arrays per source and side), the plain way the library avoids for memory.
#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <random>
#include <vector>

#include "codec/tolerance/tolerance_internal.h"
#include "linemap/cells.h"
#include "linemap/grid.h"
#include "linemap/tolerance.h"

namespace linemap::tolerance_internal {
namespace {

constexpr std::int32_t kUnreached = -1;
constexpr std::size_t kNoCell = SIZE_MAX;

// The sampled sources, as the contract fixes them: cells free in both maps,
// drawn by the linear congruential sequence of tolerance_plans.cc, at most
// 16 of 1024 draws.
std::vector<std::size_t> Sources(const Grid& a, const Grid& b) {
  std::vector<std::size_t> out;
  std::uint64_t state = 0x9E3779B97F4A7C15ull;
  for (int draw = 0; draw < 16 * 64 && out.size() < 16; ++draw) {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    const std::size_t i = static_cast<std::size_t>((state >> 17) % a.size());
    if (a.cells()[i] == Cell::kFree && b.cells()[i] == Cell::kFree) out.push_back(i);
  }
  return out;
}

// The 4-neighbours of i in the order +col, -col, +row, -row.
std::vector<std::size_t> Neighbours(const Grid& g, std::size_t i) {
  const std::size_t w = static_cast<std::size_t>(g.width());
  std::vector<std::size_t> out;
  if (i % w + 1 < w) out.push_back(i + 1);
  if (i % w > 0) out.push_back(i - 1);
  if (i + w < g.size()) out.push_back(i + w);
  if (i >= w) out.push_back(i - w);
  return out;
}

// Steps over free cells from `source`, with the cells in the order reached.
std::vector<std::int32_t> Steps(const Grid& g, std::size_t source,
                                std::vector<std::size_t>* order) {
  std::vector<std::int32_t> steps(g.size(), kUnreached);
  order->assign(1, source);
  steps[source] = 0;
  for (std::size_t head = 0; head < order->size(); ++head) {
    const std::size_t i = (*order)[head];
    for (const std::size_t j : Neighbours(g, i)) {
      if (steps[j] == kUnreached && g.cells()[j] == Cell::kFree) {
        steps[j] = steps[i] + 1;
        order->push_back(j);
      }
    }
  }
  return steps;
}

// For every cell reached, the cell before it on the shortest plan crossing
// the fewest cells not free in `other` (ties to the first neighbour in
// Neighbours' order); kNoCell at the source.
std::vector<std::size_t> FewestChangesBefore(const Grid& g, const Grid& other,
                                             const std::vector<std::int32_t>& steps,
                                             const std::vector<std::size_t>& order) {
  std::vector<std::int64_t> changes(g.size(), 0);
  std::vector<std::size_t> before(g.size(), kNoCell);
  for (const std::size_t i : order) {  // by steps: the nearer cells come first
    const std::int64_t own = other.cells()[i] != Cell::kFree ? 1 : 0;
    std::int64_t best = 0;
    for (const std::size_t j : Neighbours(g, i)) {
      if (steps[i] > 0 && steps[j] == steps[i] - 1 && (before[i] == kNoCell || changes[j] < best)) {
        best = changes[j];
        before[i] = j;
      }
    }
    changes[i] = own + best;
  }
  return before;
}

bool Agree(std::int32_t a, std::int32_t b) {
  if ((a < 0) != (b < 0)) return false;
  return a < 0 || std::abs(b - a) <= kPlanLengthTolerance * a;
}

// What the reference's walks met, so that the test can tell that the
// trials reach every case.
struct WalkCases {
  std::size_t on_original = 0;    // walks of the original's plans
  std::size_t on_decoded = 0;     // walks of the decode's plans
  std::size_t both_sides = 0;     // sources with walks on both sides
  std::size_t gone = 0;           // goals reached on the original only
  std::size_t new_plans = 0;      // goals reached on the decode only
  std::size_t stopped_early = 0;  // walks stopped at a cell walked before
};

std::vector<std::size_t> ReferenceCulprits(const Grid& original, const Grid& decoded,
                                           WalkCases* cases) {
  std::vector<std::size_t> out;
  for (const std::size_t source : Sources(original, decoded)) {
    std::vector<std::size_t> order_a, order_b;
    const std::vector<std::int32_t> a = Steps(original, source, &order_a);
    const std::vector<std::int32_t> b = Steps(decoded, source, &order_b);
    const std::vector<std::size_t> before_a = FewestChangesBefore(original, decoded, a, order_a);
    const std::vector<std::size_t> before_b = FewestChangesBefore(decoded, original, b, order_b);
    std::vector<bool> walked_a(original.size(), false), walked_b(original.size(), false);
    bool walked_on_original = false, walked_on_decoded = false;
    for (std::size_t g = 0; g < original.size(); ++g) {
      if (g == source || original.cells()[g] != Cell::kFree || decoded.cells()[g] != Cell::kFree ||
          Agree(a[g], b[g])) {
        continue;
      }
      // Longer or gone on the decode: the original's plan; else the decode's.
      const bool on_original = a[g] >= 0 && (b[g] < 0 || b[g] > a[g]);
      (on_original ? walked_on_original : walked_on_decoded) = true;
      ++(on_original ? cases->on_original : cases->on_decoded);
      cases->gone += a[g] >= 0 && b[g] < 0 ? 1 : 0;
      cases->new_plans += a[g] < 0 && b[g] >= 0 ? 1 : 0;
      const std::vector<std::size_t>& before = on_original ? before_a : before_b;
      std::vector<bool>& walked = on_original ? walked_a : walked_b;
      const Grid& other = on_original ? decoded : original;
      std::size_t i = g;
      for (; i != kNoCell && !walked[i]; i = before[i]) {
        walked[i] = true;
        if (other.cells()[i] != Cell::kFree) out.push_back(i);
      }
      cases->stopped_early += i != kNoCell ? 1 : 0;
    }
    cases->both_sides += walked_on_original && walked_on_decoded ? 1 : 0;
  }
  return out;
}

// A random floor plan: walls along some rows and columns with doorways,
// unknown outside a border, scattered obstacles.
Grid RandomPlan(int w, int h, std::mt19937* rng) {
  Grid g(w, h, Cell::kFree);
  std::uniform_int_distribution<int> col(0, w - 1), row(0, h - 1), percent(0, 99);
  for (int k = 0; k < 3; ++k) {
    const int r = row(*rng), door = col(*rng);
    for (int c = 0; c < w; ++c) {
      if (std::abs(c - door) > 1) g.set(c, r, Cell::kOccupied);
    }
    const int c = col(*rng), door_row = row(*rng);
    for (int rr = 0; rr < h; ++rr) {
      if (std::abs(rr - door_row) > 1) g.set(c, rr, Cell::kOccupied);
    }
  }
  for (std::size_t i = 0; i < g.size(); ++i) {
    if (percent(*rng) < 4) g.mutable_cells()[i] = Cell::kOccupied;
  }
  for (int c = 0; c < w; ++c) g.set(c, 0, Cell::kUnknown);
  return g;
}

// The decode of a fitting round: blocks of cells turned occupied (closing
// doorways, thickening walls) or free (opening shortcuts).
Grid RandomDecode(const Grid& original, std::mt19937* rng) {
  Grid d = original;
  std::uniform_int_distribution<int> col(0, original.width() - 3), row(0, original.height() - 3);
  std::uniform_int_distribution<int> coin(0, 1);
  for (int k = 0; k < 12; ++k) {
    const int c0 = col(*rng), r0 = row(*rng);
    const Cell value = coin(*rng) ? Cell::kOccupied : Cell::kFree;
    for (int r = r0; r < r0 + 3; ++r) {
      for (int c = c0; c < c0 + 3; ++c) d.set(c, r, value);
    }
  }
  return d;
}

TEST(PlanCulpritsTest, EqualsTheReferenceCellForCellAndInOrder) {
  std::mt19937 rng(20261129);
  WalkCases cases;
  for (int trial = 0; trial < 60; ++trial) {
    const int w = 12 + trial % 29, h = 10 + (trial * 7) % 23;
    const Grid original = RandomPlan(w, h, &rng);
    const Grid decoded = RandomDecode(original, &rng);
    const std::vector<std::size_t> expected = ReferenceCulprits(original, decoded, &cases);
    EXPECT_EQ(PlanCulprits(original, decoded), expected) << "trial " << trial;
    // A start's two searches side by side change nothing.
    EXPECT_EQ(PlanCulprits(original, decoded, 2), expected) << "trial " << trial;
  }
  // The trials must reach every kind of walk, not only agree on nothing:
  // both sides, both within one source (the merge of the two), plans gone
  // and new, and walks that stop where an earlier one passed.
  EXPECT_GT(cases.on_original, 0u);
  EXPECT_GT(cases.on_decoded, 0u);
  EXPECT_GT(cases.both_sides, 0u);
  EXPECT_GT(cases.gone, 0u);
  EXPECT_GT(cases.new_plans, 0u);
  EXPECT_GT(cases.stopped_early, 0u);
}

}  // namespace
}  // namespace linemap::tolerance_internal
