// LocalDetourCulprits(), CountLocalPlans(), StretchDetourCulprits(): plans
// between nearby cells on either side of a change, and along long stretches
// of lost free space, for the plan guarantee between starts the sampled
// check never tries.
#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "codec/cells/cell_tiles.h"
#include "codec/tolerance/simplify.h"
#include "codec/tolerance/tolerance_internal.h"

namespace linemap::tolerance_internal {
namespace {

// A breadth-first search over the free cells of `grid` from one cell, at
// most `depth` steps, that keeps, of the shortest plans to each cell, the
// one crossing the fewest cells not free in `other` (as FewestChangesPlans
// does over the whole map for the goals it is asked for). A search of
// `depth` steps stays within `depth` cells of its source in each axis, so
// its arrays span that window only ((2 depth + 1)^2 cells, reset cell by
// cell): a map of 36 Mcells would otherwise need some 1.2 GB for them. Two
// searches of the same depth and clip from the same source share their
// window, so one's window index of a cell is the other's (StepsAt).
class LocalPlans {
 public:
  LocalPlans(const Grid& grid, const Grid& other, int depth)
      : grid_(grid),
        other_(other),
        depth_(depth),
        side_(2 * depth + 1),
        steps_(static_cast<std::size_t>(side_) * side_, -1),
        changes_(steps_.size(), 0),
        previous_(steps_.size(), -1),
        walked_(steps_.size(), 0),
        column_of_(steps_.size()),
        row_of_(steps_.size()),
        order_(steps_.size()),
        reached_(steps_.size()) {
    // The window's coordinates of each index, looked up: a division per
    // cell reached was a tenth of these searches' time.
    for (std::size_t k = 0; k < steps_.size(); ++k) {
      column_of_[k] = static_cast<int>(k % side_);
      row_of_[k] = static_cast<int>(k / side_);
    }
  }

  // The steps only: the plans crossing the fewest changes are worked out
  // when one is asked for (AppendChanged), as most searches find every
  // plan holds. `source` must lie inside the clip (callers search from the
  // cells beside a change, within the clip's box): each step tests only the
  // bound it moves towards.
  void Run(std::size_t source) {
    for (std::size_t n = 0; n < count_; ++n) steps_[order_[n]] = -1;
    if (tree_ready_) {
      for (std::size_t n = 0; n < count_; ++n) {
        previous_[order_[n]] = -1;
        walked_[order_[n]] = 0;
      }
    }
    tree_ready_ = false;
    const std::size_t w = static_cast<std::size_t>(grid_.width());
    c0_ = static_cast<int>(source % w) - depth_;
    r0_ = static_cast<int>(source / w) - depth_;
    SetBounds();
    const int centre = depth_ * side_ + depth_;
    order_[0] = centre;
    reached_[0] = source;
    count_ = 1;
    steps_[centre] = 0;
    const Cell* cells = grid_.cells().data();
    for (std::size_t head = 0; head < count_; ++head) {
      const int k = order_[head];
      const std::int32_t next = steps_[k] + 1;
      if (next > depth_) continue;
      const std::size_t i = reached_[head];
      const int lc = column_of_[k], lr = row_of_[k];
      // +col, -col, +row, -row, the order the plans' ties go by.
      auto reach = [&](bool inside, int n, std::size_t j) {
        if (!inside || steps_[n] >= 0 || cells[j] != Cell::kFree) return;
        steps_[n] = next;
        order_[count_] = n;
        reached_[count_] = j;
        ++count_;
      };
      reach(lc + 1 < col_end_, k + 1, i + 1);
      reach(lc > col_begin_, k - 1, i - 1);
      reach(lr + 1 < row_end_, k + side_, i + w);
      reach(lr > row_begin_, k - side_, i - w);
    }
  }
  // Keeps the searches inside the cells [x0, x1) x [y0, y1) of the map.
  void Clip(int x0, int y0, int x1, int y1) {
    clip_x0_ = x0;
    clip_y0_ = y0;
    clip_x1_ = x1;
    clip_y1_ = y1;
  }

  // The cells reached, nearest first: map index, window index.
  std::size_t reached_count() const { return count_; }
  std::size_t reached(std::size_t n) const { return reached_[n]; }
  int window_index(std::size_t n) const { return order_[n]; }
  // The steps to the cell of window index `k` (-1: not reached).
  std::int32_t StepsAt(int k) const { return steps_[k]; }
  // Appends the cells not free in `other` on the plan to `goal`, back to
  // where a plan of this search walked before.
  void AppendChanged(std::size_t goal, std::vector<std::size_t>* out) {
    if (!tree_ready_) FewestChangesTree();
    const std::size_t w = static_cast<std::size_t>(grid_.width());
    for (int k = Local(static_cast<int>(goal % w), static_cast<int>(goal / w));
         k >= 0 && !walked_[k]; k = previous_[k]) {
      walked_[k] = 1;
      const std::size_t i = grid_.Index(c0_ + k % side_, r0_ + k / side_);
      if (Changed(i)) out->push_back(i);
    }
  }

 private:
  // The window's cells inside the map and the clip: columns [col_begin_,
  // col_end_), rows [row_begin_, row_end_) of the window.
  void SetBounds() {
    auto begin = [](int c0, int clip0) { return std::max({0, -c0, clip0 - c0}); };
    auto end = [this](int c0, int size, int clip1) {
      const std::int64_t in_clip = static_cast<std::int64_t>(clip1) - c0;
      return static_cast<int>(std::min<std::int64_t>({side_, size - c0, in_clip}));
    };
    col_begin_ = begin(c0_, clip_x0_);
    row_begin_ = begin(r0_, clip_y0_);
    col_end_ = end(c0_, grid_.width(), clip_x1_);
    row_end_ = end(r0_, grid_.height(), clip_y1_);
  }
  // For each cell reached, in the order reached (so every cell one step
  // nearer is done first): the neighbour one step nearer through which the
  // fewest cells not free in `other` lie (ties to the first of +col, -col,
  // +row, -row), and that count.
  void FewestChangesTree() {
    tree_ready_ = true;
    changes_[order_[0]] = Changed(reached_[0]);
    for (std::size_t n = 1; n < count_; ++n) {
      const int k = order_[n];
      const int lc = column_of_[k], lr = row_of_[k];
      const std::int32_t before = steps_[k] - 1;
      std::int32_t best = INT32_MAX;
      auto consider = [&](bool inside, int j) {
        if (inside && steps_[j] == before && changes_[j] < best) {
          best = changes_[j];
          previous_[k] = j;
        }
      };
      consider(lc + 1 < col_end_, k + 1);
      consider(lc > col_begin_, k - 1);
      consider(lr + 1 < row_end_, k + side_);
      consider(lr > row_begin_, k - side_);
      changes_[k] = Changed(reached_[n]) + best;
    }
  }
  // The window index of map cell (c, r); -1 outside the window or the map.
  int Local(int c, int r) const {
    const int lc = c - c0_, lr = r - r0_;
    if (lc < col_begin_ || lr < row_begin_ || lc >= col_end_ || lr >= row_end_) return -1;
    return lr * side_ + lc;
  }
  std::int32_t Changed(std::size_t i) const { return other_.cells()[i] != Cell::kFree ? 1 : 0; }

  const Grid& grid_;
  const Grid& other_;
  int depth_, side_;
  int c0_ = 0, r0_ = 0;            // the window's first cell
  int clip_x0_ = 0, clip_y0_ = 0;  // Clip(): the whole map unless set
  int clip_x1_ = INT32_MAX, clip_y1_ = INT32_MAX;
  int col_begin_ = 0, col_end_ = 0, row_begin_ = 0, row_end_ = 0;  // SetBounds()
  bool tree_ready_ = false;  // changes_ and previous_ are this search's
  std::vector<std::int32_t> steps_, changes_, previous_;
  std::vector<std::uint8_t> walked_;
  std::vector<int> column_of_, row_of_;  // window coordinates by index
  // The cells reached, nearest first: window indices, and the same cells
  // as map indices; count_ of them. Sized for the whole window, so that
  // adding one tests no capacity.
  std::vector<int> order_;
  std::vector<std::size_t> reached_;
  std::size_t count_ = 0;
};

// Cells free in both maps with a 4-neighbour free in one map only.
std::vector<std::size_t> ChangeSides(const Grid& original, const Grid& decoded) {
  std::vector<std::size_t> out;
  const int w = original.width(), h = original.height();
  auto free_in_one = [&](std::size_t i) {
    return (original.cells()[i] == Cell::kFree) != (decoded.cells()[i] == Cell::kFree);
  };
  for (int r = 0; r < h; ++r) {
    for (int c = 0; c < w; ++c) {
      const std::size_t i = original.Index(c, r);
      if (original.cells()[i] != Cell::kFree || decoded.cells()[i] != Cell::kFree) continue;
      if ((c > 0 && free_in_one(i - 1)) || (c + 1 < w && free_in_one(i + 1)) ||
          (r > 0 && free_in_one(i - w)) || (r + 1 < h && free_in_one(i + w))) {
        out.push_back(i);
      }
    }
  }
  return out;
}

// Calls visit(plans, goal, holds) for each plan of `plans` up to `radius`
// steps to a cell free in `other`; it holds when `other_plans` (the same
// source on `other`, the same depth) makes it in as many steps.
template <typename Visit>
void VisitPlans(int radius, const Grid& other, const LocalPlans& other_plans, LocalPlans* plans,
                Visit&& visit) {
  for (std::size_t n = 0; n < plans->reached_count(); ++n) {
    const int k = plans->window_index(n);
    const std::int32_t here = plans->StepsAt(k);
    if (here > radius) break;
    // A cell the other search reached is free there; one it did not is
    // looked up on the map.
    const std::int32_t there = other_plans.StepsAt(k);
    const std::size_t goal = plans->reached(n);
    if (there < 0 && other.cells()[goal] != Cell::kFree) continue;
    visit(plans, goal, there >= 0 && there <= here);
  }
}

// The cells the local check searches from: free in both maps beside a
// cell free in one only (ChangeSides), and with `checked`, only those near
// a cell that differs from it. A search from a cell reaches `radius` steps,
// so no farther in Chebyshev distance: where nothing changed that near
// since `checked`, every plan it makes is as it was then.
std::vector<std::size_t> LocalSources(const Grid& original, const Grid& decoded, int radius,
                                      const Grid* checked) {
  std::vector<std::size_t> sources = ChangeSides(original, decoded);
  if (checked == nullptr) return sources;
  std::vector<std::uint8_t> changed(decoded.size());
  for (std::size_t i = 0; i < decoded.size(); ++i) {
    changed[i] = decoded.cells()[i] != checked->cells()[i];
  }
  const std::vector<std::uint8_t> near_change =
      WithinDistance(decoded.width(), decoded.height(), changed, radius);
  std::erase_if(sources, [&near_change](std::size_t i) { return !near_change[i]; });
  return sources;
}

// Sources per share of the local check's work. Each share makes its own
// pair of searches (arrays of (2 radius + 1)^2 cells, some 140 KB at 32
// steps) and its own result, and the shares' results are joined in order,
// so the result does not depend on the threads.
constexpr std::size_t kSourcesPerShare = 4096;

// For each share of LocalSources, in order: visit(plans, goal, holds,
// &result) for every plan of up to `radius` steps on either map from each
// of its sources, `result` the share's own (a Result{} at first); the
// shares run on up to `threads` threads (0: one per core). Returns the
// shares' results in order.
template <typename Result, typename Visit>
std::vector<Result> VisitLocalPlans(const Grid& original, const Grid& decoded, int radius,
                                    const Grid* checked, int threads, Visit&& visit) {
  const std::vector<std::size_t> sources = LocalSources(original, decoded, radius, checked);
  const std::size_t shares = (sources.size() + kSourcesPerShare - 1) / kSourcesPerShare;
  std::vector<Result> results(shares);
  ForEachIndexParallel(shares, threads, [&](std::uint64_t k) {
    LocalPlans on_original(original, decoded, radius), on_decoded(decoded, original, radius);
    const std::size_t end = std::min(sources.size(), (k + 1) * kSourcesPerShare);
    Result& result = results[k];
    const auto visit_share = [&](LocalPlans* plans, std::size_t goal, bool holds) {
      visit(plans, goal, holds, &result);
    };
    for (std::size_t n = k * kSourcesPerShare; n < end; ++n) {
      // A plan of up to `radius` steps on one map must be there in as many
      // steps on the other: both searches go that deep.
      on_original.Run(sources[n]);
      on_decoded.Run(sources[n]);
      // Longer on the decode (a detour), then shorter (a shortcut).
      VisitPlans(radius, decoded, on_decoded, &on_original, visit_share);
      VisitPlans(radius, original, on_original, &on_decoded, visit_share);
    }
  });
  return results;
}

// A component (8-connected) of cells free on the original map only: its box
// (inclusive) and the cells free on both maps 4-adjacent to it.
struct LostStretch {
  int c0 = 0, r0 = 0, c1 = 0, r1 = 0;
  std::vector<std::size_t> sides;
};

// The cells free on both maps 4-adjacent to `cells`, each once (`taken`
// marks them while this runs, and is all 0 again after).
std::vector<std::size_t> SidesOf(const Grid& original, const Grid& decoded,
                                 const std::vector<std::size_t>& cells,
                                 std::vector<std::uint8_t>* taken) {
  std::vector<std::size_t> sides;
  const std::size_t w = static_cast<std::size_t>(original.width());
  const std::size_t h = static_cast<std::size_t>(original.height());
  for (const std::size_t i : cells) {
    ForEachNeighbour(w, h, i, [&](std::size_t n) {
      if ((*taken)[n] || original.cells()[n] != Cell::kFree || decoded.cells()[n] != Cell::kFree) {
        return;
      }
      (*taken)[n] = 1;
      sides.push_back(n);
    });
  }
  for (const std::size_t n : sides) (*taken)[n] = 0;
  return sides;
}

// The stretches of lost free space (LostStretch) whose box is more than
// `min_extent` cells long in either axis.
std::vector<LostStretch> LongLostStretches(const Grid& original, const Grid& decoded,
                                           int min_extent) {
  const int w = original.width();
  auto lost = [&](std::size_t i) {
    return original.cells()[i] == Cell::kFree && decoded.cells()[i] != Cell::kFree;
  };
  std::vector<std::uint8_t> seen(original.size(), 0), taken(original.size(), 0);
  std::vector<std::size_t> stack, cells;
  std::vector<LostStretch> out;
  for (std::size_t start = 0; start < original.size(); ++start) {
    if (seen[start] || !lost(start)) continue;
    seen[start] = 1;
    stack.assign(1, start);
    cells.clear();
    LostStretch s;
    s.c0 = s.c1 = static_cast<int>(start % w);
    s.r0 = s.r1 = static_cast<int>(start / w);
    while (!stack.empty()) {
      const std::size_t i = stack.back();
      stack.pop_back();
      cells.push_back(i);
      const int c = static_cast<int>(i % w), r = static_cast<int>(i / w);
      s.c0 = std::min(s.c0, c);
      s.c1 = std::max(s.c1, c);
      s.r0 = std::min(s.r0, r);
      s.r1 = std::max(s.r1, r);
      for (int dr = -1; dr <= 1; ++dr) {
        for (int dc = -1; dc <= 1; ++dc) {
          if (!original.Contains(c + dc, r + dr)) continue;
          const std::size_t n = original.Index(c + dc, r + dr);
          if (seen[n] || !lost(n)) continue;
          seen[n] = 1;
          stack.push_back(n);
        }
      }
    }
    if (std::max(s.c1 - s.c0, s.r1 - s.r0) + 1 <= min_extent) continue;
    s.sides = SidesOf(original, decoded, cells, &taken);
    out.push_back(std::move(s));
  }
  return out;
}

// Whether any cell of the rectangle [x0, x1) x [y0, y1) (clipped to the
// map) differs between `a` and `b`.
bool ChangedIn(const Grid& a, const Grid& b, int x0, int y0, int x1, int y1) {
  x0 = std::max(x0, 0);
  y0 = std::max(y0, 0);
  x1 = std::min(x1, a.width());
  y1 = std::min(y1, a.height());
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) {
      if (a.at(x, y) != b.at(x, y)) return true;
    }
  }
  return false;
}

}  // namespace

std::vector<std::size_t> StretchDetourCulprits(const Grid& original, const Grid& decoded,
                                               int radius, int max_steps, const Grid* checked) {
  // Plans may leave a stretch's box by this many cells: a wall grown by up
  // to 4 cells (T = 4) is walked round within them.
  constexpr int kMargin = 8;
  const std::vector<LostStretch> stretches = LongLostStretches(original, decoded, radius - kMargin);
  if (stretches.empty()) return {};
  // A plan inside a box and the margin around it, turning at most once,
  // takes up to the sum of the sides' lengths.
  auto steps_of = [&](const LostStretch& s) {
    return std::min(max_steps, (s.c1 - s.c0 + 1) + (s.r1 - s.r0 + 1) + 4 * kMargin);
  };
  // One pair of searches for every stretch: their arrays span (2 depth +
  // 1)^2 cells, and each search resets only the cells it reached.
  int depth = 0;
  for (const LostStretch& s : stretches) depth = std::max(depth, steps_of(s));
  LocalPlans on_original(original, decoded, depth), on_decoded(decoded, original, depth);
  std::vector<std::uint8_t> given(original.size(), 0);
  std::vector<std::size_t> out, path;
  for (const LostStretch& s : stretches) {
    const int x0 = s.c0 - kMargin, y0 = s.r0 - kMargin;
    const int x1 = s.c1 + kMargin + 1, y1 = s.r1 + kMargin + 1;
    // The searches stay inside this window: where nothing in it changed
    // since `checked`, every plan they make is as it was then.
    if (checked != nullptr && !ChangedIn(decoded, *checked, x0, y0, x1, y1)) continue;
    for (LocalPlans* plans : {&on_original, &on_decoded}) plans->Clip(x0, y0, x1, y1);
    const int steps = steps_of(s);
    // Every side cell is a source: a plan walks round the growth only
    // between cells past its ends or in gaps of the wall along it (a
    // doorway), and which side cells those are depends on the stretch's
    // shape; a search inside the box's margin is cheap.
    for (const std::size_t source : s.sides) {
      on_original.Run(source);
      on_decoded.Run(source);
      // Within 3 %, the guarantee itself, not the same length: these plans
      // are the pieces of longer ones near a stretch, and pieces each
      // within 3 % make a plan within 3 %. Holding them to their length
      // gave back a third of the cells of a 1024 x 1024 map of corridors
      // at T = 4 (336,130 against 6,609 before this check).
      for (std::size_t n = 0; n < on_original.reached_count(); ++n) {
        const int k = on_original.window_index(n);
        const std::int32_t here = on_original.StepsAt(k);
        if (here > steps) break;
        const std::size_t goal = on_original.reached(n);
        if (decoded.cells()[goal] != Cell::kFree) continue;
        const std::int32_t there = on_decoded.StepsAt(k);
        if (there >= 0 && PlansAgree(here, there)) continue;
        path.clear();
        on_original.AppendChanged(goal, &path);
        for (const std::size_t i : path) {
          if (!given[i]) out.push_back(i);
          given[i] = 1;
        }
      }
    }
  }
  return out;
}

std::vector<std::size_t> LocalDetourCulprits(const Grid& original, const Grid& decoded, int radius,
                                             const Grid* checked, int threads) {
  const std::vector<std::vector<std::size_t>> shares = VisitLocalPlans<std::vector<std::size_t>>(
      original, decoded, radius, checked, threads,
      [](LocalPlans* plans, std::size_t goal, bool holds, std::vector<std::size_t>* out) {
        if (!holds) plans->AppendChanged(goal, out);
      });
  std::vector<std::size_t> out;
  for (const std::vector<std::size_t>& share : shares) {
    out.insert(out.end(), share.begin(), share.end());
  }
  return out;
}

LocalPlanCount CountLocalPlans(const Grid& original, const Grid& decoded, int radius) {
  const auto count_plan = [](LocalPlans*, std::size_t, bool holds, LocalPlanCount* share) {
    ++share->plans;
    share->disagreements += holds ? 0 : 1;
  };
  LocalPlanCount count;
  for (const LocalPlanCount& share :
       VisitLocalPlans<LocalPlanCount>(original, decoded, radius, nullptr, 1, count_plan)) {
    count.plans += share.plans;
    count.disagreements += share.disagreements;
  }
  return count;
}

}  // namespace linemap::tolerance_internal
