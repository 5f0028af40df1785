// Plans compared on two grids: breadth-first 4-connected paths over free
// cells (what a planner that treats unknown as an obstacle can use) from
// sampled start cells to every cell free in both grids.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

#include "codec/tolerance/simplify.h"
#include "codec/tolerance/tolerance_internal.h"

namespace linemap::tolerance_internal {
namespace {

// Start cells per check, each planned to every cell free in both grids:
// 16 x 2 breadth-first searches per check (about 0.1 s per million cells).
constexpr int kSampledCells = 16;
constexpr int kDrawsPerCell = 64;

// Steps from `source` to every cell over free cells; -1 where unreachable.
// `order` (when given) receives the cells in the order reached, that is by
// steps.
std::vector<std::int32_t> FreeSteps(const Grid& grid, std::size_t source,
                                    std::vector<std::size_t>* order = nullptr) {
  std::vector<std::int32_t> steps(grid.size(), -1);
  std::vector<std::size_t> local;
  std::vector<std::size_t>& queue = order ? *order : local;
  queue.clear();
  queue.reserve(1024);
  steps[source] = 0;
  queue.push_back(source);
  // The neighbours by index, the map's edges tested by column and row (no
  // per-neighbour Contains: these searches are most of the fitting's time).
  const std::size_t w = static_cast<std::size_t>(grid.width());
  const std::size_t h = static_cast<std::size_t>(grid.height());
  const Cell* cells = grid.cells().data();
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const std::size_t i = queue[head];
    const std::int32_t s = steps[i] + 1;
    ForEachNeighbour(w, h, i, [&](std::size_t n) {
      if (steps[n] < 0 && cells[n] == Cell::kFree) {
        steps[n] = s;
        queue.push_back(n);
      }
    });
  }
  return steps;
}

// The cells of one shortest path from the search's source to `goal`.
void AppendPath(const Grid& grid, const std::vector<std::int32_t>& steps, std::size_t goal,
                std::vector<std::size_t>* out) {
  const std::size_t w = static_cast<std::size_t>(grid.width());
  const std::size_t h = static_cast<std::size_t>(grid.height());
  std::size_t i = goal;
  out->push_back(i);
  while (steps[i] > 0) {
    std::size_t next = i;
    ForEachNeighbour(w, h, i, [&](std::size_t n) {
      if (next == i && steps[n] == steps[i] - 1) next = n;
    });
    i = next;
    out->push_back(i);
  }
}

// Of all shortest plans on `grid` from the search's source, the ones that
// cross the fewest cells not free in `other`: for each reached cell, the
// neighbour one step nearer the source through which the fewest such cells
// lie (ties to the first of +col, -col, +row, -row). A plan that disagrees
// is mended by giving back the cells of one plan; of a map's many equally
// short plans (a 4-connected plan may take its turns anywhere) the one
// along a wall the blocks thickened needs dozens, the one beside it one
// or two (the cells of the doorway it passes).
class FewestChangesPlans {
 public:
  FewestChangesPlans(const Grid& grid, const std::vector<std::int32_t>& steps,
                     const std::vector<std::size_t>& order, const Grid& other)
      : width_(static_cast<std::size_t>(grid.width())), toward_(grid.size(), kSource) {
    std::vector<std::int32_t> changes(grid.size(), 0);
    const std::size_t w = width_;
    const std::size_t h = static_cast<std::size_t>(grid.height());
    const Cell* other_cells = other.cells().data();
    for (const std::size_t i : order) {
      const std::int32_t own = other_cells[i] != Cell::kFree ? 1 : 0;
      const std::int32_t before = steps[i] - 1;
      if (before < 0) {
        changes[i] = own;
        continue;
      }
      // The neighbours one step nearer, in the order +col, -col, +row,
      // -row (ties to the first).
      std::int32_t best = INT32_MAX;
      ForEachNeighbour(w, h, i, [&](std::size_t j) {
        if (steps[j] == before && changes[j] < best) {
          best = changes[j];
          toward_[i] = Direction(i, j);
        }
      });
      changes[i] = own + best;
    }
  }
  // The cell before `i` on its plan; kNone at the source.
  std::size_t Previous(std::size_t i) const {
    switch (toward_[i]) {
      case 0:
        return i + 1;
      case 1:
        return i - 1;
      case 2:
        return i + width_;
      case 3:
        return i - width_;
      default:
        return kNone;
    }
  }
  static constexpr std::size_t kNone = SIZE_MAX;

 private:
  // Which neighbour comes before each cell (+col, -col, +row, -row as
  // 0-3; kSource at the source and unreached cells): a byte a cell rather
  // than an index of 8, as one of these is made for the whole map per
  // sampled start.
  static constexpr std::uint8_t kSource = 4;
  // Which neighbour of i the 4-neighbour j is, in the order Previous reads.
  std::uint8_t Direction(std::size_t i, std::size_t j) const {
    return j == i + 1 ? 0 : j + 1 == i ? 1 : j == i + width_ ? 2 : 3;
  }
  std::size_t width_;
  std::vector<std::uint8_t> toward_;
};

// Walks the plan from `goal` back towards the source until a cell already
// walked (plans of one search form a tree), appending the cells whose
// value in `other` is not free.
void AppendUnfreeOnPath(const FewestChangesPlans& plans, std::size_t goal, const Grid& other,
                        std::vector<std::uint8_t>* walked, std::vector<std::size_t>* out) {
  for (std::size_t i = goal; i != FewestChangesPlans::kNone; i = plans.Previous(i)) {
    if ((*walked)[i]) break;
    (*walked)[i] = 1;
    if (other.cells()[i] != Cell::kFree) out->push_back(i);
  }
}

// Cells free in both grids, drawn by a fixed linear congruential sequence.
std::vector<std::size_t> SampleCells(const Grid& a, const Grid& b) {
  std::vector<std::size_t> cells;
  if (a.empty()) return cells;
  std::uint64_t state = 0x9E3779B97F4A7C15ull;
  for (int draw = 0; draw < kSampledCells * kDrawsPerCell && cells.size() < kSampledCells; ++draw) {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    const std::size_t i = static_cast<std::size_t>((state >> 17) % a.size());
    if (a.cells()[i] == Cell::kFree && b.cells()[i] == Cell::kFree) cells.push_back(i);
  }
  return cells;
}

}  // namespace

bool PlansAgree(std::int32_t la, std::int32_t lb) {
  return (la < 0) == (lb < 0) && (la < 0 || std::abs(lb - la) <= kPlanLengthTolerance * la);
}

std::vector<std::size_t> PlanCulprits(const Grid& original, const Grid& decoded) {
  std::vector<std::size_t> out;
  std::vector<std::size_t> order_a, order_b;
  for (const std::size_t source : SampleCells(original, decoded)) {
    const std::vector<std::int32_t> a = FreeSteps(original, source, &order_a);
    const std::vector<std::int32_t> b = FreeSteps(decoded, source, &order_b);
    std::vector<std::uint8_t> walked_a, walked_b;
    std::unique_ptr<FewestChangesPlans> plans_a, plans_b;  // made on the first use
    for (std::size_t g = 0; g < a.size(); ++g) {
      // Equal steps (most cells) agree, and so do cells neither reaches.
      if (a[g] == b[g] || g == source || original.cells()[g] != Cell::kFree ||
          decoded.cells()[g] != Cell::kFree || PlansAgree(a[g], b[g])) {
        continue;
      }
      // Longer or gone on the decode: the original plan crosses a cell that
      // is no longer free. Shorter or new: the decoded plan crosses a cell
      // that was not free.
      if (a[g] >= 0 && (b[g] < 0 || b[g] > a[g])) {
        if (!plans_a) {
          plans_a = std::make_unique<FewestChangesPlans>(original, a, order_a, decoded);
          walked_a.assign(a.size(), 0);
        }
        AppendUnfreeOnPath(*plans_a, g, decoded, &walked_a, &out);
      } else {
        if (!plans_b) {
          plans_b = std::make_unique<FewestChangesPlans>(decoded, b, order_b, original);
          walked_b.assign(b.size(), 0);
        }
        AppendUnfreeOnPath(*plans_b, g, original, &walked_b, &out);
      }
    }
  }
  return out;
}

PlanFaults ComparePlans(const Grid& original, const Grid& decoded, bool want_paths) {
  PlanFaults out;
  const std::vector<std::size_t> sources = SampleCells(original, decoded);
  for (const std::size_t source : sources) {
    const std::vector<std::int32_t> a = FreeSteps(original, source);
    const std::vector<std::int32_t> b = FreeSteps(decoded, source);
    // Every cell free in both is a goal: the searches reach them all anyway.
    std::size_t worst = 0;
    double worst_excess = -1;
    for (std::size_t g = 0; g < a.size(); ++g) {
      if (g == source || original.cells()[g] != Cell::kFree || decoded.cells()[g] != Cell::kFree) {
        continue;
      }
      ++out.pairs;
      const std::int32_t la = a[g];
      const std::int32_t lb = b[g];
      if (PlansAgree(la, lb)) continue;
      ++out.disagreements;
      const double excess = (la < 0 || lb < 0) ? 1e9 : static_cast<double>(std::abs(lb - la)) / la;
      if (excess > worst_excess) {
        worst_excess = excess;
        worst = g;
      }
    }
    if (!want_paths || worst_excess < 0) continue;
    // The worst goal's plans: undoing the changes along them removes the
    // shortcut or the detour; the next check finds any other.
    if (a[worst] >= 0) AppendPath(original, a, worst, &out.paths);
    if (b[worst] >= 0) AppendPath(decoded, b, worst, &out.paths);
    out.paths.push_back(source);
    out.paths.push_back(worst);
  }
  return out;
}

}  // namespace linemap::tolerance_internal
