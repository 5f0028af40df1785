// LocalDetourCulprits(): plans between nearby cells on either side of a
// change, for the plan guarantee between starts the sampled check never
// tries.
#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "codec/codec/tolerance.h"
#include "codec/codec/tolerance_internal.h"

namespace linemap::tolerance_internal {
namespace {

constexpr std::size_t kNone = SIZE_MAX;

// A breadth-first search over the free cells of `grid` from one cell, at
// most `depth` steps, that keeps, of the shortest plans to each cell, the
// one crossing the fewest cells not free in `other` (as FewestChangesPlans
// does for the whole map). Its arrays span the grid and are reset cell by
// cell, so one search costs what it visits.
class LocalPlans {
 public:
  LocalPlans(const Grid& grid, const Grid& other)
      : grid_(grid),
        other_(other),
        steps_(grid.size(), -1),
        changes_(grid.size(), 0),
        previous_(grid.size(), kNone),
        walked_(grid.size(), 0) {}

  void Run(std::size_t source, int depth) {
    for (const std::size_t i : order_) {
      steps_[i] = -1;
      previous_[i] = kNone;
      walked_[i] = 0;
    }
    order_.assign(1, source);
    steps_[source] = 0;
    changes_[source] = Changed(source);
    const std::size_t w = static_cast<std::size_t>(grid_.width());
    for (std::size_t head = 0; head < order_.size(); ++head) {
      const std::size_t i = order_[head];
      const int c = static_cast<int>(i % w), r = static_cast<int>(i / w);
      const int dc[4] = {1, -1, 0, 0}, dr[4] = {0, 0, 1, -1};
      if (steps_[i] > 0) {
        // Every cell one step nearer was reached before this one left the
        // queue: the fewest changes through any of them are final.
        std::int32_t best = INT32_MAX;
        for (int k = 0; k < 4; ++k) {
          if (!grid_.Contains(c + dc[k], r + dr[k])) continue;
          const std::size_t n = grid_.Index(c + dc[k], r + dr[k]);
          if (steps_[n] == steps_[i] - 1 && changes_[n] < best) {
            best = changes_[n];
            previous_[i] = n;
          }
        }
        changes_[i] = Changed(i) + best;
      }
      if (steps_[i] == depth) continue;
      for (int k = 0; k < 4; ++k) {
        if (!grid_.Contains(c + dc[k], r + dr[k])) continue;
        const std::size_t n = grid_.Index(c + dc[k], r + dr[k]);
        if (steps_[n] >= 0 || grid_.cells()[n] != Cell::kFree) continue;
        steps_[n] = steps_[i] + 1;
        order_.push_back(n);
      }
    }
  }
  // The cells reached, nearest first, and their steps (-1: not reached).
  const std::vector<std::size_t>& reached() const { return order_; }
  std::int32_t steps(std::size_t i) const { return steps_[i]; }
  // Appends the cells not free in `other` on the plan to `goal`, back to
  // where a plan of this search walked before.
  void AppendChanged(std::size_t goal, std::vector<std::size_t>* out) {
    for (std::size_t i = goal; i != kNone && !walked_[i]; i = previous_[i]) {
      walked_[i] = 1;
      if (Changed(i)) out->push_back(i);
    }
  }

 private:
  std::int32_t Changed(std::size_t i) const { return other_.cells()[i] != Cell::kFree ? 1 : 0; }

  const Grid& grid_;
  const Grid& other_;
  std::vector<std::int32_t> steps_, changes_;
  std::vector<std::size_t> previous_;
  std::vector<std::uint8_t> walked_;
  std::vector<std::size_t> order_;
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

}  // namespace

std::vector<std::size_t> LocalDetourCulprits(const Grid& original, const Grid& decoded, int radius,
                                             const Grid* checked) {
  std::vector<std::size_t> out;
  // A search from a cell reaches radius + slack steps, so no farther in
  // Chebyshev distance: where nothing changed that near since `checked`,
  // every plan it makes is as it was then.
  std::vector<std::int32_t> near_change;
  if (checked != nullptr) {
    std::vector<std::uint8_t> changed(decoded.size());
    for (std::size_t i = 0; i < decoded.size(); ++i) {
      changed[i] = decoded.cells()[i] != checked->cells()[i];
    }
    near_change = ChebyshevDistance(decoded.width(), decoded.height(), changed);
  }
  LocalPlans on_original(original, decoded), on_decoded(decoded, original);
  for (const std::size_t source : ChangeSides(original, decoded)) {
    if (checked != nullptr && near_change[source] > radius + kPlanSlackSteps) continue;
    // A plan up to `radius` steps on one map must be there within the
    // slack on the other: search that much deeper.
    on_original.Run(source, radius + kPlanSlackSteps);
    on_decoded.Run(source, radius + kPlanSlackSteps);
    for (const std::size_t goal : on_original.reached()) {
      const std::int32_t a = on_original.steps(goal);
      if (a > radius) break;
      if (decoded.cells()[goal] != Cell::kFree) continue;
      const std::int32_t b = on_decoded.steps(goal);
      if (b < 0 || b > a + kPlanSlackSteps) on_original.AppendChanged(goal, &out);
    }
    for (const std::size_t goal : on_decoded.reached()) {
      const std::int32_t b = on_decoded.steps(goal);
      if (b > radius) break;
      if (original.cells()[goal] != Cell::kFree) continue;
      const std::int32_t a = on_original.steps(goal);
      if (a < 0 || a > b + kPlanSlackSteps) on_decoded.AppendChanged(goal, &out);
    }
  }
  return out;
}

}  // namespace linemap::tolerance_internal
