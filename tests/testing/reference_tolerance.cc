// The references of tests/testing/reference_tolerance.h: window scans,
// flood fills and breadth-first searches, sharing no code with
// codec/tolerance.
#include "tests/testing/reference_tolerance.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <deque>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "linemap/codec.h"
#include "linemap/tolerance.h"
#include "tests/testing/reference_components.h"

namespace linemap::testing {
namespace {

// 4-connected free regions by flood fill; labels from 1, 0 elsewhere.
std::vector<int> FloodFree(const Grid& g, std::vector<int>* sizes) {
  std::vector<int> label(g.size(), 0);
  sizes->assign(1, 0);
  for (int r = 0; r < g.height(); ++r) {
    for (int c = 0; c < g.width(); ++c) {
      if (g.at(c, r) != Cell::kFree || label[g.Index(c, r)]) continue;
      const int id = static_cast<int>(sizes->size());
      sizes->push_back(0);
      std::deque<std::pair<int, int>> queue{{c, r}};
      label[g.Index(c, r)] = id;
      while (!queue.empty()) {
        const auto [x, y] = queue.front();
        queue.pop_front();
        ++(*sizes)[id];
        const int dx[4] = {1, -1, 0, 0}, dy[4] = {0, 0, 1, -1};
        for (int k = 0; k < 4; ++k) {
          const int nx = x + dx[k], ny = y + dy[k];
          if (g.Contains(nx, ny) && g.at(nx, ny) == Cell::kFree && !label[g.Index(nx, ny)]) {
            label[g.Index(nx, ny)] = id;
            queue.emplace_back(nx, ny);
          }
        }
      }
    }
  }
  return label;
}

// Start / goal pairs chosen here (every cell free in both, a fixed stride
// apart), not the module's sample: plans exist on both or neither, and
// lengths agree within 3 %.
void ExpectPlansAgree(const Grid& o, const Grid& s, int sources) {
  std::vector<int> both;
  for (std::size_t i = 0; i < o.size(); ++i) {
    if (o.cells()[i] == Cell::kFree && s.cells()[i] == Cell::kFree)
      both.push_back(static_cast<int>(i));
  }
  // No cell free in both: no plan to compare (the distance checks cover a
  // free space lost whole).
  if (both.empty()) return;
  const std::size_t src_stride = std::max<std::size_t>(1, both.size() / sources);
  const std::size_t goal_stride = std::max<std::size_t>(1, both.size() / 97);
  int disagreements = 0, pairs = 0;
  for (std::size_t a = src_stride / 2; a < both.size(); a += src_stride) {
    const std::vector<int> lo = BfsSteps(o, both[a]);
    const std::vector<int> ls = BfsSteps(s, both[a]);
    for (std::size_t b = 0; b < both.size(); b += goal_stride) {
      const int x = lo[both[b]], y = ls[both[b]];
      ++pairs;
      const bool agree = (x < 0) == (y < 0) && (x < 0 || std::abs(x - y) <= 0.03 * x);
      disagreements += !agree;
    }
  }
  EXPECT_EQ(disagreements, 0) << "of " << pairs << " pairs";
}

// Steps from `from` over free cells up to `depth`, breadth first: the
// cells reached, in order, with their steps in `steps` (a whole-grid array,
// -1 where not reached; the caller resets the cells reached).
std::vector<int> NearSteps(const Grid& g, int from, int depth, std::vector<int>* steps) {
  std::vector<int> reached{from};
  (*steps)[from] = 0;
  for (std::size_t next = 0; next < reached.size(); ++next) {
    const int i = reached[next];
    const int d = (*steps)[i];
    if (d == depth) continue;
    const int c = i % g.width(), r = i / g.width();
    const int dc[4] = {1, -1, 0, 0}, dr[4] = {0, 0, 1, -1};
    for (int k = 0; k < 4; ++k) {
      if (!g.Contains(c + dc[k], r + dr[k]) || g.at(c + dc[k], r + dr[k]) != Cell::kFree) continue;
      const int n = static_cast<int>(g.Index(c + dc[k], r + dr[k]));
      if ((*steps)[n] < 0) {
        (*steps)[n] = d + 1;
        reached.push_back(n);
      }
    }
  }
  return reached;
}

void ExpectLocalPlansAgree(const Grid& o, const Grid& s, int depth) {
  EXPECT_EQ(BruteLocalPlans(o, s, depth).bad, 0u)
      << "plans of up to " << depth << " steps beside a change of different lengths";
}

}  // namespace

std::vector<int> BfsSteps(const Grid& g, int from) {
  std::vector<int> steps(g.size(), -1);
  std::deque<int> queue{from};
  steps[from] = 0;
  while (!queue.empty()) {
    const int i = queue.front();
    queue.pop_front();
    const int c = i % g.width(), r = i / g.width();
    const int dx[4] = {1, -1, 0, 0}, dy[4] = {0, 0, 1, -1};
    for (int k = 0; k < 4; ++k) {
      const int nc = c + dx[k], nr = r + dy[k];
      if (!g.Contains(nc, nr) || g.at(nc, nr) != Cell::kFree) continue;
      const int n = static_cast<int>(g.Index(nc, nr));
      if (steps[n] < 0) {
        steps[n] = steps[i] + 1;
        queue.push_back(n);
      }
    }
  }
  return steps;
}

bool HasWithin(const Grid& grid, int c, int r, Cell value, int t) {
  for (int dr = -t; dr <= t; ++dr) {
    for (int dc = -t; dc <= t; ++dc) {
      if (grid.Contains(c + dc, r + dr) && grid.at(c + dc, r + dr) == value) return true;
    }
  }
  return false;
}

int BruteHausdorff(const Grid& a, const Grid& b) {
  std::vector<std::pair<int, int>> bs;
  for (int r = 0; r < b.height(); ++r) {
    for (int c = 0; c < b.width(); ++c) {
      if (b.at(c, r) == Cell::kOccupied) bs.emplace_back(c, r);
    }
  }
  int worst = 0;
  for (int r = 0; r < a.height(); ++r) {
    for (int c = 0; c < a.width(); ++c) {
      if (a.at(c, r) != Cell::kOccupied) continue;
      if (bs.empty()) return -1;
      int best = INT32_MAX;
      for (const auto& [bc, br] : bs)
        best = std::min(best, std::max(std::abs(bc - c), std::abs(br - r)));
      worst = std::max(worst, best);
    }
  }
  return worst;
}

TopologyCount BruteTopology(const Grid& original, const Grid& decoded) {
  std::vector<int> osize, dsize;
  const std::vector<int> o = FloodFree(original, &osize);
  const std::vector<int> d = FloodFree(decoded, &dsize);
  std::vector<std::set<int>> regions_of_dec(dsize.size());
  std::vector<std::set<int>> pieces_of_orig(osize.size());
  for (std::size_t i = 0; i < o.size(); ++i) {
    if (!o[i] || !d[i] || osize[o[i]] < static_cast<int>(kLeakRegionCells)) continue;
    regions_of_dec[d[i]].insert(o[i]);
    pieces_of_orig[o[i]].insert(d[i]);
  }
  TopologyCount out;
  for (const auto& s : regions_of_dec)
    out.leaks += s.size() > 1 ? static_cast<int>(s.size()) - 1 : 0;
  for (const auto& s : pieces_of_orig) out.splits += s.size() > 1;
  return out;
}

LocalPlanFigures BruteLocalPlans(const Grid& o, const Grid& s, int depth) {
  auto free_in = [](const Grid& g, int i) { return g.cells()[i] == Cell::kFree; };
  LocalPlanFigures out;
  std::vector<int> steps_o(o.size(), -1), steps_s(s.size(), -1);
  for (int r = 0; r < o.height(); ++r) {
    for (int c = 0; c < o.width(); ++c) {
      const int i = static_cast<int>(o.Index(c, r));
      if (!free_in(o, i) || !free_in(s, i)) continue;
      bool beside_change = false;
      const int dc[4] = {1, -1, 0, 0}, dr[4] = {0, 0, 1, -1};
      for (int k = 0; k < 4; ++k) {
        if (!o.Contains(c + dc[k], r + dr[k])) continue;
        const int n = static_cast<int>(o.Index(c + dc[k], r + dr[k]));
        beside_change = beside_change || free_in(o, n) != free_in(s, n);
      }
      if (!beside_change) continue;
      const std::vector<int> in_o = NearSteps(o, i, depth, &steps_o);
      const std::vector<int> in_s = NearSteps(s, i, depth, &steps_s);
      for (const int goal : in_o) {
        if (!free_in(s, goal)) continue;
        ++out.plans;
        out.bad += steps_s[goal] < 0 || steps_s[goal] > steps_o[goal];
      }
      for (const int goal : in_s) {
        if (!free_in(o, goal)) continue;
        ++out.plans;
        out.bad += steps_o[goal] < 0 || steps_o[goal] > steps_s[goal];
      }
      for (const int cell : in_o) steps_o[cell] = -1;
      for (const int cell : in_s) steps_s[cell] = -1;
    }
  }
  return out;
}

void ExpectGuarantees(const Grid& o, const Grid& s, int t, const std::string& what) {
  SCOPED_TRACE(what + " T=" + std::to_string(t));
  ASSERT_EQ(o.width(), s.width());
  ASSERT_EQ(o.height(), s.height());
  EXPECT_EQ(o.meta, s.meta);
  int occ_lost = 0, occ_new = 0, free_new = 0, free_lost = 0;
  for (int r = 0; r < o.height(); ++r) {
    for (int c = 0; c < o.width(); ++c) {
      if (o.at(c, r) == Cell::kOccupied) occ_lost += !HasWithin(s, c, r, Cell::kOccupied, t);
      if (s.at(c, r) == Cell::kOccupied) occ_new += !HasWithin(o, c, r, Cell::kOccupied, t);
      if (s.at(c, r) == Cell::kFree) free_new += !HasWithin(o, c, r, Cell::kFree, t);
      if (o.at(c, r) == Cell::kFree) free_lost += !HasWithin(s, c, r, Cell::kFree, t);
    }
  }
  EXPECT_EQ(occ_lost, 0) << "original obstacles without a decoded one within T";
  EXPECT_EQ(occ_new, 0) << "decoded obstacles without an original one within T";
  EXPECT_EQ(free_new, 0) << "decoded free cells (unknown turned free) beyond T";
  EXPECT_EQ(free_lost, 0) << "original free cells without decoded free within T";
  const TopologyCount topo = BruteTopology(o, s);
  EXPECT_EQ(topo.leaks, 0);
  EXPECT_EQ(topo.splits, 0);
  ExpectPlansAgree(o, s, 6);
  // Beyond guarantees 3 and 4 (regions of 50+ cells; sampled and local
  // plans), what the encoder's mending does: no pocket of free space is
  // joined or split either, so every pair has a plan on both maps or on
  // neither.
  EXPECT_EQ(PlansOnOneGridOnly(o, s), 0) << "pairs with a plan on one map only";
  ExpectLocalPlansAgree(o, s, LocalPlanSteps(t));
  // And the library's own check, which plans from the encoder's sampled
  // starts rather than the strided ones above.
  EXPECT_TRUE(CheckTolerance(o, s, t).Holds());
}

}  // namespace linemap::testing
