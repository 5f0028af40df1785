// Plans compared on two grids: breadth-first 4-connected paths over free
// cells (what a planner that treats unknown as an obstacle can use) from
// sampled start cells to every cell free in both grids.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

#include "codec/cells/cell_tiles.h"
#include "codec/tolerance/simplify.h"
#include "codec/tolerance/tolerance_internal.h"

namespace linemap::tolerance_internal {
namespace {

// Start cells per check, each planned to every cell free in both grids:
// 16 x 2 breadth-first searches per check (about 0.1 s per million cells).
constexpr int kSampledCells = 16;
constexpr int kDrawsPerCell = 64;

// Which ways a cell can be left within the map (its column decides the
// first two), and whether it is free: a byte a cell that the searches read
// instead of the grid, so that no cell's column is divided out of its index.
enum Move : std::uint8_t { kFreeCell = 1, kToNextColumn = 2, kToPreviousColumn = 4 };

std::vector<std::uint8_t> MovesOf(const Grid& grid) {
  std::vector<std::uint8_t> moves(grid.size());
  const std::size_t w = static_cast<std::size_t>(grid.width());
  const Cell* cells = grid.cells().data();
  for (std::size_t row = 0; row < grid.size(); row += w) {
    for (std::size_t c = 0; c < w; ++c) {
      moves[row + c] = static_cast<std::uint8_t>((cells[row + c] == Cell::kFree ? kFreeCell : 0) |
                                                 (c + 1 < w ? kToNextColumn : 0) |
                                                 (c > 0 ? kToPreviousColumn : 0));
    }
  }
  return moves;
}

// Breadth-first searches over the free cells of one grid, one source at a
// time: the steps to every cell (-1 where a free cell is unreachable, -2 on
// a cell that is not free). The steps array is kept from one search to the
// next and only the span of cells the last search reached is reset: a fresh
// array of the whole map per search, filled, was a tenth of the fitting's
// time (tsc at T = 1). Cells that are not free hold -2 for good, so that a
// search tests one array per neighbour (steps == -1: free and not reached
// yet) rather than the steps and the cell. The search runs a level of steps
// at a time, so what it holds besides the steps is two levels of cells, not
// every cell it reached (a list of those, 8 bytes a cell reached in each of
// the two searches, was a fifth of the fitting's peak memory on tsc at
// T = 1).
class FreeSearch {
 public:
  explicit FreeSearch(const Grid& grid) : grid_(grid), moves_(MovesOf(grid)), steps_(grid.size()) {
    ResetSteps(0, grid.size());
  }

  void Run(std::size_t source) {
    if (reached_first_ <= reached_last_) ResetSteps(reached_first_, reached_last_ + 1);
    const std::size_t w = static_cast<std::size_t>(grid_.width());
    const std::size_t n = grid_.size();
    std::int32_t* steps = steps_.data();
    std::size_t first = source, last = source;
    steps[source] = 0;
    level_.assign(1, source);
    for (std::int32_t s = 1; !level_.empty(); ++s) {
      next_.clear();
      for (const std::size_t i : level_) {
        const std::uint8_t moves = moves_[i];
        auto reach = [&](std::size_t j) {
          if (steps[j] == kUnreached) {
            steps[j] = s;
            next_.push_back(j);
          }
        };
        if (moves & kToNextColumn) reach(i + 1);
        if (moves & kToPreviousColumn) reach(i - 1);
        if (i + w < n) reach(i + w);
        if (i >= w) reach(i - w);
      }
      // The span reached, a level at a time (a level is not in cell order).
      for (const std::size_t j : next_) {
        first = std::min(first, j);
        last = std::max(last, j);
      }
      level_.swap(next_);
    }
    reached_first_ = first;
    reached_last_ = last;
  }
  const Grid& grid() const { return grid_; }
  const std::vector<std::uint8_t>& moves() const { return moves_; }
  const std::vector<std::int32_t>& steps() const { return steps_; }

 private:
  static constexpr std::int32_t kUnreached = -1, kNotFree = -2;

  // Steps [begin, end) back to before any search: -1 on free cells, -2 on
  // the others.
  void ResetSteps(std::size_t begin, std::size_t end) {
    const std::uint8_t* moves = moves_.data();
    std::int32_t* steps = steps_.data();
    for (std::size_t i = begin; i < end; ++i) {
      steps[i] = (moves[i] & kFreeCell) ? kUnreached : kNotFree;
    }
  }

  const Grid& grid_;
  std::vector<std::uint8_t> moves_;
  std::vector<std::int32_t> steps_;
  // The span of cells the last search reached (empty: first > last).
  std::size_t reached_first_ = 1, reached_last_ = 0;
  std::vector<std::size_t> level_, next_;  // the cells of this and the next step
};

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

// Of all shortest plans of a search on a grid, the ones that cross the
// fewest cells not free in `other`: for each reached cell, the neighbour
// one step nearer the source through which the fewest such cells lie (ties
// to the first of +col, -col, +row, -row). A plan that disagrees is mended
// by giving back the cells of one plan; of a map's many equally short
// plans (a 4-connected plan may take its turns anywhere) the one along a
// wall the blocks thickened needs dozens, the one beside it one or two (the
// cells of the doorway it passes). Only the cells on shortest plans to the
// goals asked for are worked out: a search's disagreeing goals are few, and
// working out every cell it reached was an eighth of tsc's T = 1 save. The
// arrays (5 bytes a cell, against 2 before they were packed with the plans'
// directions) are made on the first goal of a search and freed once its
// goals are walked: most searches need none, and one side's are freed
// before the other side's are made (PlanCulprits).
class FewestChangesPlans {
 public:
  explicit FewestChangesPlans(const Grid& other) : other_(other) {}

  // Forgets the plans of the last search: `search` has run again.
  void Reset(const FreeSearch& search) {
    search_ = &search;
    Release();
  }

  // Frees the plans worked out (5 bytes a cell once a goal was asked).
  void Release() {
    std::vector<std::uint8_t>().swap(state_);
    std::vector<std::int32_t>().swap(changes_);
  }

  // Walks the plan from `goal` back towards the source until a cell
  // already walked since Reset (plans of one search form a tree),
  // appending the cells whose value in `other` is not free.
  void AppendUnfreeOnPath(std::size_t goal, std::vector<std::size_t>* out) {
    WorkOut(goal);
    for (std::size_t i = goal; i != kNone; i = Previous(i)) {
      if (state_[i] & kWalked) break;
      state_[i] |= kWalked;
      if (other_.cells()[i] != Cell::kFree) out->push_back(i);
    }
  }

 private:
  static constexpr std::size_t kNone = SIZE_MAX;
  // A cell's byte of state_: which neighbour comes before it (+col, -col,
  // +row, -row as 0-3; kSource at the source) in the low bits, and
  // whether it is worked out, and walked.
  static constexpr std::uint8_t kTowardMask = 7, kSource = 4, kDone = 8, kWalked = 16;

  // Works out the plans to `goal` and to every cell one step nearer on a
  // shortest plan to it, depth first: a cell is done once the cells one
  // step nearer are (its fewest changes are theirs plus its own).
  void WorkOut(std::size_t goal) {
    const std::size_t n = search_->grid().size();
    if (state_.empty()) {
      state_.assign(n, 0);
      changes_.assign(n, 0);
    }
    if (state_[goal] & kDone) return;
    const std::int32_t* steps = search_->steps().data();
    const Cell* other_cells = other_.cells().data();
    pending_.assign(1, goal);
    while (!pending_.empty()) {
      const std::size_t i = pending_.back();
      if (state_[i] & kDone) {
        pending_.pop_back();
        continue;
      }
      const std::int32_t own = other_cells[i] != Cell::kFree ? 1 : 0;
      if (steps[i] <= 0) {  // 0: the source (every cell queued is reached)
        changes_[i] = own;
        state_[i] |= kDone | kSource;
        pending_.pop_back();
      } else if (!AwaitNearer(i)) {
        pending_.pop_back();
        Settle(i, own);
      }
    }
  }

  // Calls f(j, direction) for each 4-neighbour j of cell i within the map,
  // in the order +col, -col, +row, -row (directions 0-3): ForEachNeighbour
  // with the direction, reading the search's moves rather than dividing
  // out i's column.
  template <typename F>
  void ForEachWay(std::size_t i, F f) const {
    const std::uint8_t moves = search_->moves()[i];
    const std::size_t w = static_cast<std::size_t>(search_->grid().width());
    if (moves & kToNextColumn) f(i + 1, std::uint8_t{0});
    if (moves & kToPreviousColumn) f(i - 1, std::uint8_t{1});
    if (i + w < search_->grid().size()) f(i + w, std::uint8_t{2});
    if (i >= w) f(i - w, std::uint8_t{3});
  }

  // Queues the neighbours one step nearer the source that are not worked
  // out yet; true when there were any (cell i waits for them).
  bool AwaitNearer(std::size_t i) {
    const std::int32_t* steps = search_->steps().data();
    const std::int32_t before = steps[i] - 1;
    bool waiting = false;
    ForEachWay(i, [&](std::size_t j, std::uint8_t) {
      if (steps[j] == before && !(state_[j] & kDone)) {
        pending_.push_back(j);
        waiting = true;
      }
    });
    return waiting;
  }

  // Works out cell i, whose nearer neighbours are worked out: its fewest
  // changes are the least of theirs (ties to the first in ForEachWay's
  // order) plus its own (`own`: 1 when it is not free in `other`).
  void Settle(std::size_t i, std::int32_t own) {
    const std::int32_t* steps = search_->steps().data();
    const std::int32_t before = steps[i] - 1;
    std::int32_t best = INT32_MAX;
    std::uint8_t toward = kSource;
    ForEachWay(i, [&](std::size_t j, std::uint8_t direction) {
      if (steps[j] == before && changes_[j] < best) {
        best = changes_[j];
        toward = direction;
      }
    });
    changes_[i] = own + best;
    state_[i] |= kDone | toward;
  }

  // The cell before `i` on its plan; kNone at the source.
  std::size_t Previous(std::size_t i) const {
    const std::size_t w = static_cast<std::size_t>(search_->grid().width());
    switch (state_[i] & kTowardMask) {
      case 0:
        return i + 1;
      case 1:
        return i - 1;
      case 2:
        return i + w;
      case 3:
        return i - w;
      default:
        return kNone;
    }
  }

  const Grid& other_;
  const FreeSearch* search_ = nullptr;
  std::vector<std::uint8_t> state_;
  std::vector<std::int32_t> changes_;
  std::vector<std::size_t> pending_;  // cells waiting for those one step nearer
};

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

// Which side's plan a disagreeing goal mends: longer or gone on the
// decode, the original plan crosses a cell that is no longer free
// (kOnOriginal); shorter or new, the decoded plan crosses a cell that was
// not free (kOnDecoded).
enum class MendSide { kNone, kOnOriginal, kOnDecoded };
MendSide SideToMend(std::int32_t a, std::int32_t b) {
  if (PlansAgree(a, b)) return MendSide::kNone;
  return a >= 0 && (b < 0 || b > a) ? MendSide::kOnOriginal : MendSide::kOnDecoded;
}

// The two searches from one sampled source: steps on the original (a) and
// on the decode (b).
struct SourceSearches {
  const Grid& original;
  const Grid& decoded;
  std::size_t source;
  const std::int32_t* a;
  const std::int32_t* b;
};

// What one side's walks appended: `cells`, goal by goal (a goal's cells are
// cells[begin, end) of its share; goals that appended none have no share).
struct SideWalks {
  struct Share {
    std::size_t goal, begin, end;
  };
  std::vector<std::size_t> cells;
  std::vector<Share> shares;
};

// Cells per block of DifferingBlocks.
constexpr std::size_t kStepBlock = 64;

// The blocks of kStepBlock cells (block k: cells [64 k, 64 k + 64)) where
// the two searches' steps differ, in order. Most cells have equal steps:
// cells free in both grids that both searches reach as fast, or that
// neither reaches (-1 on both), and cells free in neither (-2 on both), so
// stretches of them are skipped with memcmp before any cell is read. Kept
// as block numbers, at most an eighth of a byte a cell, rather than as the
// goals: this is the phase the save's peak memory is budgeted for.
void DifferingBlocks(const SourceSearches& s, std::vector<std::size_t>* blocks) {
  blocks->clear();
  const std::size_t n = s.original.size();
  for (std::size_t begin = 0; begin < n; begin += kStepBlock) {
    const std::size_t end = std::min(n, begin + kStepBlock);
    if (std::memcmp(s.a + begin, s.b + begin, (end - begin) * sizeof(std::int32_t)) != 0) {
      blocks->push_back(begin / kStepBlock);
    }
  }
}

// Walks `plans` (reset on the search of the grid whose plans `side` mends)
// to every goal of `blocks` whose disagreement `side` mends: cells free in
// both grids, but the source, in raster order. Then frees the plans.
void WalkSide(const SourceSearches& s, const std::vector<std::size_t>& blocks, MendSide side,
              FewestChangesPlans* plans, SideWalks* out) {
  out->cells.clear();
  out->shares.clear();
  const Cell* original_cells = s.original.cells().data();
  const Cell* decoded_cells = s.decoded.cells().data();
  const std::size_t n = s.original.size();
  for (const std::size_t block : blocks) {
    const std::size_t end = std::min(n, (block + 1) * kStepBlock);
    for (std::size_t g = block * kStepBlock; g < end; ++g) {
      if (s.a[g] == s.b[g] || g == s.source || original_cells[g] != Cell::kFree ||
          decoded_cells[g] != Cell::kFree || SideToMend(s.a[g], s.b[g]) != side) {
        continue;
      }
      const std::size_t begin = out->cells.size();
      plans->AppendUnfreeOnPath(g, &out->cells);
      if (out->cells.size() > begin) out->shares.push_back({g, begin, out->cells.size()});
    }
  }
  plans->Release();
}

// Appends the two sides' cells to *out in their goals' raster order, as if
// the goals had been walked one by one, each on its side.
void AppendInGoalOrder(const SideWalks& x, const SideWalks& y, std::vector<std::size_t>* out) {
  std::size_t ix = 0, iy = 0;
  while (ix < x.shares.size() || iy < y.shares.size()) {
    const bool take_x =
        iy == y.shares.size() || (ix < x.shares.size() && x.shares[ix].goal < y.shares[iy].goal);
    const SideWalks& side = take_x ? x : y;
    const SideWalks::Share& share = take_x ? x.shares[ix++] : y.shares[iy++];
    out->insert(out->end(), side.cells.begin() + static_cast<std::ptrdiff_t>(share.begin),
                side.cells.begin() + static_cast<std::ptrdiff_t>(share.end));
  }
}

}  // namespace

bool PlansAgree(std::int32_t la, std::int32_t lb) {
  return (la < 0) == (lb < 0) && (la < 0 || std::abs(lb - la) <= kPlanLengthTolerance * la);
}

std::vector<std::size_t> PlanCulprits(const Grid& original, const Grid& decoded, int threads) {
  std::vector<std::size_t> out;
  FreeSearch on_original(original), on_decoded(decoded);
  FewestChangesPlans plans_a(decoded), plans_b(original);
  SideWalks walks_a, walks_b;
  std::vector<std::size_t> blocks;
  for (const std::size_t source : SampleCells(original, decoded)) {
    // The two searches share nothing but the source: side by side on two
    // threads, with no more memory (both arrays exist anyway).
    ForEachIndexParallel(
        2, threads, [&](std::uint64_t map) { (map == 0 ? on_original : on_decoded).Run(source); });
    const SourceSearches searches{original, decoded, source, on_original.steps().data(),
                                  on_decoded.steps().data()};
    // One side's plans at a time (each holds 5 bytes a cell while its
    // goals are walked), then their cells in the goals' order: the order
    // decides which of two cells of one block unfills the block
    // (Mender::Unfill).
    DifferingBlocks(searches, &blocks);
    plans_a.Reset(on_original);
    WalkSide(searches, blocks, MendSide::kOnOriginal, &plans_a, &walks_a);
    plans_b.Reset(on_decoded);
    WalkSide(searches, blocks, MendSide::kOnDecoded, &plans_b, &walks_b);
    AppendInGoalOrder(walks_a, walks_b, &out);
  }
  return out;
}

PlanFaults ComparePlans(const Grid& original, const Grid& decoded, bool want_paths) {
  PlanFaults out;
  FreeSearch on_original(original), on_decoded(decoded);
  for (const std::size_t source : SampleCells(original, decoded)) {
    on_original.Run(source);
    on_decoded.Run(source);
    const std::vector<std::int32_t>& a = on_original.steps();
    const std::vector<std::int32_t>& b = on_decoded.steps();
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
