// FitBlockCells(): the map in blocks of T + 1 cells a side, mended where a
// guarantee of linemap/tolerance.h fails.
#include "codec/tolerance/tolerance_blocks.h"

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "codec/tolerance/compare_internal.h"
#include "codec/tolerance/simplify.h"
#include "codec/tolerance/tolerance_internal.h"
#include "linemap/codec.h"

namespace linemap {
namespace {

using tolerance_internal::CellMask;
using tolerance_internal::WithinDistance;

// Rounds of checks. Each round restores cells or turns a block unknown, and
// neither is ever undone, so the rounds end; this bounds pathological maps,
// which then get the exact cells.
constexpr int kMaxRounds = 96;

// The block side: T + 1 cells, the largest that keeps every cell within T
// of its block's value (an occupied block grows an obstacle by at most T
// cells; the format allows sides up to 5, spec 6.4). A larger side codes
// fewer blocks but lets walls grow further, which narrows doorways and
// corridors and lengthens the plans that turn around a wall's end; the plan
// checks find those and give the free cells back, each at about 5 bits.
// Fewer blocks win: bytes of the cells-only file at T = 3 (willow-full
// 0.05, fetch 4_26_15, tsc, cs_lg, mrpt map1) with sides 2 / 3 / 4:
// 17,909 / 15,396 / 14,686, 6,940 / 5,545 / 5,306, 13,297 / 11,584 /
// 11,233, 1,385 / 1,068 / 1,034, 4,549 / 3,955 / 3,794; at T = 2 side 3
// saves 7-15 % against 2, at T = 4 side 5 22-36 %. (nav2 depot, a clean
// plan, is smallest with side 3 at T = 3: 706 / 557 / 627.)
int BlockSide(int tolerance_cells) { return std::min(tolerance_cells + 1, kMaxBlockCells); }

// How far the encoder's check of the plans beside a change reaches, for
// blocks of `block_side` cells: kLocalPlanSteps (the guarantee's own
// reach) for side 2, twice that beyond. A wall grown by more than a cell
// lengthens plans too long for 16 steps to see whole, between starts no
// sampled plan tries. Measured on ../shared/maps with sides 3 / 4 / 5 at
// T = 2 / 3 / 4 (`build/bench_tolerance`: 24 strided starts x ~1000 goals
// per map that the encoder never samples, about 607,000 plans per T):
// with 16 steps 9 / 58 / 102 plans differed by more than 3 % (side 2 at
// every T: 5 / 5 / 1), with 32 steps 0 / 19 / 33, for files under 1 %
// larger; 16 steps per cell of side (64 and 80 at T = 3 and 4) took tsc's
// T = 4 save from 12 to 111 s. The search is about (2 steps + 1)^2 cells
// from each cell beside a change.
int LocalCheckSteps(int block_side) {
  return block_side <= kMinBlockCells ? kLocalPlanSteps : 2 * kLocalPlanSteps;
}

// How far the check along long stretches of lost free space reaches at
// tolerance t: a wall grown by up to t cells adds at most 2t steps to a
// plan that walks round it, more than 3 % only of plans under 200 t / 3
// steps (StretchDetourCulprits); 2 steps more for the rounding.
int StretchCheckSteps(int t) { return (200 * t + 2) / 3 + 2; }

// Whether the free cells of the block at (x0, y0) (side f) and of the ring
// of cells around it are one 4-connected piece inside that window. If so,
// filling the block's unknown cells opens no new way through it (a plan
// gains at most a corner's steps); if not, the unknown cells separate free
// space (a laser shadow across a room, the gap between two scans) and
// filling them would be a shortcut.
bool FreeConnectedAround(const Grid& grid, int x0, int y0, int f) {
  const int wx0 = std::max(0, x0 - 1), wy0 = std::max(0, y0 - 1);
  const int wx1 = std::min(grid.width(), x0 + f + 1), wy1 = std::min(grid.height(), y0 + f + 1);
  const int ww = wx1 - wx0, wh = wy1 - wy0;
  std::vector<std::uint8_t> seen(static_cast<std::size_t>(ww) * wh, 0);
  std::vector<int> stack;
  int pieces = 0;
  for (int y = wy0; y < wy1; ++y) {
    for (int x = wx0; x < wx1; ++x) {
      const int k = (y - wy0) * ww + (x - wx0);
      if (seen[k] || grid.at(x, y) != Cell::kFree) continue;
      if (++pieces > 1) return false;
      seen[k] = 1;
      stack.push_back(k);
      while (!stack.empty()) {
        const int j = stack.back();
        stack.pop_back();
        const int cx = j % ww, cy = j / ww;
        const int nx[4] = {cx + 1, cx - 1, cx, cx};
        const int ny[4] = {cy, cy, cy + 1, cy - 1};
        for (int n = 0; n < 4; ++n) {
          if (nx[n] < 0 || nx[n] >= ww || ny[n] < 0 || ny[n] >= wh) continue;
          const int m = ny[n] * ww + nx[n];
          if (seen[m] || grid.at(wx0 + nx[n], wy0 + ny[n]) != Cell::kFree) continue;
          seen[m] = 1;
          stack.push_back(m);
        }
      }
    }
  }
  return true;
}

// The blocks before any mending: occupied if any cell is (so every
// occupied cell keeps one within T); else free if any cell is and that
// fills no gap between free cells (FreeConnectedAround); else unknown.
// Unknown cells turned free lie within T of a free cell of their block.
BlockCells BlocksOf(const Grid& grid, int f) {
  BlockCells b;
  b.block_cells = f;
  b.blocks_x = (grid.width() + f - 1) / f;
  b.blocks_y = (grid.height() + f - 1) / f;
  b.blocks.assign(static_cast<std::size_t>(b.blocks_x) * b.blocks_y, Cell::kUnknown);
  for (int by = 0; by < b.blocks_y; ++by) {
    for (int bx = 0; bx < b.blocks_x; ++bx) {
      bool occupied = false, free = false, unknown = false;
      for (int y = by * f; y < std::min(grid.height(), by * f + f); ++y) {
        for (int x = bx * f; x < std::min(grid.width(), bx * f + f); ++x) {
          const Cell v = grid.at(x, y);
          occupied |= v == Cell::kOccupied;
          free |= v == Cell::kFree;
          unknown |= v == Cell::kUnknown;
        }
      }
      Cell& block = b.blocks[static_cast<std::size_t>(by) * b.blocks_x + bx];
      if (occupied) {
        block = Cell::kOccupied;
      } else if (free && (!unknown || FreeConnectedAround(grid, bx * f, by * f, f))) {
        block = Cell::kFree;
      }
    }
  }
  b.restored.assign(grid.size(), 0);
  return b;
}

// The mending of one round, counted so that a round that mends nothing
// ends the fitting.
struct Mender {
  const Grid& original;
  const Grid& decoded;
  BlockCells* b;
  std::size_t mended = 0;

  // Gives `cells` their original values (where they differ).
  void Restore(const std::vector<std::size_t>& cells) {
    for (const std::size_t i : cells) {
      if (original.cells()[i] != decoded.cells()[i] && !b->restored[i]) {
        b->restored[i] = 1;
        ++mended;
      }
    }
  }

  // A free cell the blocks made out of an unknown one: its block turns
  // unknown (it holds no occupied cell, or it would be occupied), which
  // closes a shortcut or a bridge as wide as the block. Any other changed
  // cell gets its original value.
  void Unfill(std::size_t i) {
    if (original.cells()[i] == decoded.cells()[i] || b->restored[i]) return;
    if (original.cells()[i] == Cell::kUnknown && decoded.cells()[i] == Cell::kFree) {
      const int w = original.width(), f = b->block_cells;
      const int c = static_cast<int>(i % w), r = static_cast<int>(i / w);
      Cell& block = b->blocks[static_cast<std::size_t>(r / f) * b->blocks_x + c / f];
      if (block == Cell::kFree) {
        block = Cell::kUnknown;
        ++mended;
        return;
      }
    }
    Restore({i});
  }
};

// What the distance checks read of the original map, which no round
// changes, so it is worked out once: 1 where an occupied (a free) cell of
// the original lies within T. (Its free regions are labelled again each
// round: kept, they would add 4 bytes a cell to the peak of the plan
// checks for some 2 % of the time.)
struct OriginalNear {
  OriginalNear(const Grid& original, int t)
      : occupied(WithinDistance(original.width(), original.height(),
                                CellMask(original, Cell::kOccupied), t)),
        free(WithinDistance(original.width(), original.height(), CellMask(original, Cell::kFree),
                            t)) {}
  std::vector<std::uint8_t> occupied, free;
};

// Cells where a distance guarantee fails. With blocks built as above only
// "an original free cell with no decoded free cell within T" can fail (a
// free cell in an occupied block); the other three are checked too, so
// that a change to BlocksOf() cannot slip through. The first kind goes to
// `lost_free`, the others to `faults`.
void DistanceFaults(const Grid& original, const OriginalNear& near, const Grid& decoded, int t,
                    std::vector<std::size_t>* faults, std::vector<std::size_t>* lost_free) {
  const int w = original.width(), h = original.height();
  const auto s_occ = WithinDistance(w, h, CellMask(decoded, Cell::kOccupied), t);
  const auto s_free = WithinDistance(w, h, CellMask(decoded, Cell::kFree), t);
  for (std::size_t i = 0; i < original.size(); ++i) {
    const Cell a = original.cells()[i], b = decoded.cells()[i];
    if ((b == Cell::kOccupied && !near.occupied[i]) || (a == Cell::kOccupied && !s_occ[i]) ||
        (b == Cell::kFree && !near.free[i])) {
      faults->push_back(i);
    } else if (a == Cell::kFree && !s_free[i]) {
      lost_free->push_back(i);
    }
  }
}

// Where blocks join two free regions of the original (each of
// kLeakRegionCells+ cells) that are apart: a breadth-first search over the
// decoded free cells from both regions at once meets in the middle of each
// bridge; the cells where it meets are returned. Mending them cuts the
// bridge (a wide one over several rounds), where mending every cell the
// blocks made free in the joining component would, on a SLAM map, mend the
// whole ragged edge of its free space.
std::vector<std::size_t> LeakBridges(const Grid& original, const Grid& decoded) {
  const int w = original.width(), h = original.height();
  const Cell* original_cells = original.cells().data();
  const Cell* decoded_cells = decoded.cells().data();
  // Each cell's region where it is free in both maps, 0 elsewhere: the
  // search's sources, and then what it reached.
  std::vector<std::int32_t> owner = std::move(codec_internal::LabelFree(original).labels);
  for (std::size_t i = 0; i < owner.size(); ++i) {
    if (decoded_cells[i] != Cell::kFree) owner[i] = 0;
  }
  std::vector<std::size_t> bridges;
  std::vector<std::size_t> next;
  const auto expand = [&](std::size_t i) {
    const int c = static_cast<int>(i % w), r = static_cast<int>(i / w);
    const std::size_t near[4] = {i + 1, i - 1, i + w, i - w};
    const bool inside[4] = {c + 1 < w, c > 0, r + 1 < h, r > 0};
    for (int k = 0; k < 4; ++k) {
      if (!inside[k] || decoded_cells[near[k]] != Cell::kFree) continue;
      if (owner[near[k]] == 0) {
        owner[near[k]] = owner[i];
        next.push_back(near[k]);
      } else if (owner[near[k]] != owner[i]) {
        bridges.push_back(i);
        bridges.push_back(near[k]);
      }
    }
  };
  // A level at a time, the sources first in raster order: the order a
  // first-in first-out queue holding every source would take, without
  // holding them (8 bytes a free cell, the fitting's peak on office maps).
  for (std::size_t i = 0; i < owner.size(); ++i) {
    if (original_cells[i] == Cell::kFree && decoded_cells[i] == Cell::kFree) expand(i);
  }
  std::vector<std::size_t> level;
  while (!next.empty()) {
    level.swap(next);
    next.clear();
    for (const std::size_t i : level) expand(i);
  }
  return bridges;
}

// One round of checks: true when every guarantee holds on `decoded`;
// otherwise mends what fails first (distances, then topology, then plans).
// `checked`: the decode the local plan check last ran on (empty before the
// first), which the round updates when it runs it; `stretch_checked` the
// same for the check along long stretches. `threads`: for the plan checks.
bool MendRound(Mender* m, const OriginalNear& near, int t, int threads, Grid* checked,
               Grid* stretch_checked) {
  std::vector<std::size_t> faults, lost_free;
  DistanceFaults(m->original, near, m->decoded, t, &faults, &lost_free);
  if (!faults.empty() || !lost_free.empty()) {
    m->Restore(faults);
    m->Restore(tolerance_internal::FreeCover(m->original, m->decoded, lost_free, t));
    return false;
  }
  const auto topology = tolerance_internal::FindTopologyFaults(m->original, m->decoded, true);
  // Any two free regions joined (not only the kLeakRegionCells+ ones of
  // the leak guarantee): a plan into a small pocket of free space must not
  // appear either.
  const std::vector<std::size_t> bridges = LeakBridges(m->original, m->decoded);
  if (topology.splits > 0 || !bridges.empty()) {
    // A split-off piece: the fewest lost cells that join it to the main
    // piece of its region come back.
    m->Restore(topology.split_culprits);
    for (const std::size_t i : bridges) m->Unfill(i);
    return false;
  }
  // A plan that differs passes a changed cell: a detour leaves a cell of the
  // original plan that is no longer free (restored), a shortcut takes a
  // cell the blocks made free (its block unfilled). Either is on one of the
  // two plans. The short plans beside the changes come first: their check
  // looks only near what changed since it last ran, while the sampled
  // starts' plans are two searches of the whole map per start (32 a round,
  // most of a round's time). Those run once the short plans agree, and
  // their few culprits cost a round of their own now and then (over the 25
  // maps of ../shared/maps at T = 1..4, 54 rounds more in all, at most 3
  // more and 17 in all for one save). The saves (cells only) took 130 s of
  // CPU against 168 s when both ran every round; 3-9 % of that is
  // FreeSearch's one-array test, which came with it. The files were 296,600
  // bytes against 296,713. (The opposite order, the short plans only once
  // the sampled ones agree, had cost tsc 5.1 s at T = 1, in an older build,
  // against 4.3 s with both every round.)
  std::vector<std::size_t> culprits = tolerance_internal::LocalDetourCulprits(
      m->original, m->decoded, LocalCheckSteps(m->b->block_cells),
      checked->empty() ? nullptr : checked, threads);
  *checked = m->decoded;
  if (culprits.empty()) {
    culprits = tolerance_internal::PlanCulprits(m->original, m->decoded, threads);
  }
  // The long stretches last: they are few, and most of their detours are
  // gone once the plans above agree.
  if (culprits.empty()) {
    culprits = tolerance_internal::StretchDetourCulprits(
        m->original, m->decoded, LocalCheckSteps(m->b->block_cells), StretchCheckSteps(t),
        stretch_checked->empty() ? nullptr : stretch_checked);
    *stretch_checked = m->decoded;
  }
  if (culprits.empty()) return true;
  for (const std::size_t i : culprits) m->Unfill(i);
  return false;
}

}  // namespace

StatusOr<BlockCells> FitBlockCells(const Grid& grid, int tolerance_cells,
                                   const std::function<void(int)>& after_round, int threads) {
  if (tolerance_cells < 1 || tolerance_cells > kMaxToleranceCells) {
    return InvalidArgumentError("tolerance " + std::to_string(tolerance_cells) +
                                " cells is outside 1.." + std::to_string(kMaxToleranceCells));
  }
  BlockCells b = BlocksOf(grid, BlockSide(tolerance_cells));
  const OriginalNear near(grid, tolerance_cells);
  Grid checked, stretch_checked;
  for (int round = 0; round < kMaxRounds; ++round) {
    const Grid decoded = ComposeBlockCells(grid, b);
    Mender mender{grid, decoded, &b};
    if (MendRound(&mender, near, tolerance_cells, threads, &checked, &stretch_checked)) return b;
    if (mender.mended == 0) break;  // nothing left to mend: the exact map below
    if (after_round) after_round(round + 1);
  }
  std::fill(b.restored.begin(), b.restored.end(), 1);
  return b;
}

}  // namespace linemap
