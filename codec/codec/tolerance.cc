// SimplifyWithinTolerance(): smoothing proposed by morphology, then every
// guarantee checked on the whole result and the changes undone block by
// block where one fails, until all hold. CheckTolerance(): the guarantees'
// figures.
#include "codec/codec/tolerance.h"

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "codec/codec/tolerance_internal.h"
#include "codec/codec/tolerance_smoothing.h"

namespace linemap {
namespace {

using tolerance_internal::CellMask;
using tolerance_internal::ChebyshevDistance;
using tolerance_internal::kFar;

// Changes are undone in square blocks of this side (cells): large enough
// that a few rounds settle, small enough that one failing doorway does not
// undo a room's worth of smoothing.
constexpr int kUndoBlockCells = 16;
// Rounds of checks before giving up and returning the input (each round
// undoes at least one changed cell, so this only bounds pathological maps).
constexpr int kMaxRounds = 64;

// Resets every cell of `simplified` that breaks a distance guarantee to
// its original value; returns how many. Every breaking cell is a changed
// cell (an unchanged one is its own witness), so undoing them converges.
std::size_t UndoDistanceFaults(const Grid& original, int t, Grid* simplified) {
  const int w = original.width();
  const int h = original.height();
  const auto o_occ = ChebyshevDistance(w, h, CellMask(original, Cell::kOccupied));
  const auto o_free = ChebyshevDistance(w, h, CellMask(original, Cell::kFree));
  const auto s_occ = ChebyshevDistance(w, h, CellMask(*simplified, Cell::kOccupied));
  const auto s_free = ChebyshevDistance(w, h, CellMask(*simplified, Cell::kFree));
  std::size_t undone = 0;
  std::vector<Cell>& cells = simplified->mutable_cells();
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const Cell a = original.cells()[i];
    const Cell b = cells[i];
    const bool fault = (b == Cell::kOccupied && o_occ[i] > t) ||
                       (a == Cell::kOccupied && s_occ[i] > t) ||
                       (b == Cell::kFree && o_free[i] > t) || (a == Cell::kFree && s_free[i] > t);
    if (fault && a != b) {
      cells[i] = a;
      ++undone;
    }
  }
  return undone;
}

// Resets the blocks holding any of `cells` (grid indices) to the original,
// after growing each cell by `reach` cells; returns the changed cells reset.
std::size_t UndoBlocks(const Grid& original, const std::vector<std::size_t>& cells, int reach,
                       Grid* simplified) {
  const int w = original.width();
  const int h = original.height();
  const int bw = (w + kUndoBlockCells - 1) / kUndoBlockCells;
  const int bh = (h + kUndoBlockCells - 1) / kUndoBlockCells;
  std::vector<std::uint8_t> marked(static_cast<std::size_t>(bw) * bh, 0);
  for (const std::size_t i : cells) {
    const int c = static_cast<int>(i % w);
    const int r = static_cast<int>(i / w);
    const int b0 = std::max(0, c - reach) / kUndoBlockCells;
    const int b1 = std::min(w - 1, c + reach) / kUndoBlockCells;
    const int a0 = std::max(0, r - reach) / kUndoBlockCells;
    const int a1 = std::min(h - 1, r + reach) / kUndoBlockCells;
    for (int br = a0; br <= a1; ++br) {
      for (int bc = b0; bc <= b1; ++bc) marked[static_cast<std::size_t>(br) * bw + bc] = 1;
    }
  }
  std::size_t undone = 0;
  for (int r = 0; r < h; ++r) {
    for (int c = 0; c < w; ++c) {
      if (!marked[static_cast<std::size_t>(r / kUndoBlockCells) * bw + c / kUndoBlockCells]) {
        continue;
      }
      const Cell a = original.at(c, r);
      if (simplified->at(c, r) != a) {
        simplified->set(c, r, a);
        ++undone;
      }
    }
  }
  return undone;
}

}  // namespace

namespace tolerance_internal {

Grid EnforceGuarantees(const Grid& original, Grid proposal, int t) {
  Grid& simplified = proposal;
  for (int round = 0; round < kMaxRounds; ++round) {
    if (UndoDistanceFaults(original, t, &simplified) > 0) continue;
    const TopologyFaults topology = FindTopologyFaults(original, simplified, true);
    if (topology.leaks > 0 || topology.splits > 0) {
      if (UndoBlocks(original, topology.culprits, 1, &simplified) == 0) return original;
      continue;
    }
    const PlanFaults plans = ComparePlans(original, simplified, true);
    if (plans.disagreements > 0) {
      // The changes that made the plans differ lie near either path.
      if (UndoBlocks(original, plans.paths, t + 1, &simplified) == 0) return original;
      continue;
    }
    return simplified;
  }
  return original;
}

}  // namespace tolerance_internal

bool ToleranceReport::Holds() const {
  return same_size && hausdorff_original_to_decoded >= 0 &&
         hausdorff_original_to_decoded <= tolerance_cells && hausdorff_decoded_to_original >= 0 &&
         hausdorff_decoded_to_original <= tolerance_cells && free_moved_beyond == 0 &&
         free_lost_beyond == 0 && unknown_turned_free_beyond == 0 && leaks == 0 && splits == 0 &&
         plan_disagreements == 0;
}

StatusOr<Grid> SimplifyWithinTolerance(const Grid& grid, int tolerance_cells) {
  if (tolerance_cells < 0 || tolerance_cells > kMaxToleranceCells) {
    return InvalidArgumentError("tolerance " + std::to_string(tolerance_cells) +
                                " cells is outside 0.." + std::to_string(kMaxToleranceCells));
  }
  if (tolerance_cells == 0 || grid.empty()) return grid;
  return tolerance_internal::EnforceGuarantees(
      grid, tolerance_internal::ProposeSmoothing(grid, tolerance_cells), tolerance_cells);
}

ToleranceReport CheckTolerance(const Grid& original, const Grid& decoded, int tolerance_cells) {
  ToleranceReport out;
  out.tolerance_cells = tolerance_cells;
  if (original.width() != decoded.width() || original.height() != decoded.height()) return out;
  out.same_size = true;
  const int w = original.width();
  const int h = original.height();
  const auto o_occ = ChebyshevDistance(w, h, CellMask(original, Cell::kOccupied));
  const auto o_free = ChebyshevDistance(w, h, CellMask(original, Cell::kFree));
  const auto s_occ = ChebyshevDistance(w, h, CellMask(decoded, Cell::kOccupied));
  const auto s_free = ChebyshevDistance(w, h, CellMask(decoded, Cell::kFree));
  const int t = tolerance_cells;
  auto hausdorff = [](int current, std::int32_t d) {
    if (current < 0 || d >= kFar) return -1;
    return std::max(current, static_cast<int>(d));
  };
  for (int r = 0; r < h; ++r) {
    for (int c = 0; c < w; ++c) {
      const std::size_t i = original.Index(c, r);
      const Cell a = original.cells()[i];
      const Cell b = decoded.cells()[i];
      if (a == Cell::kOccupied) {
        out.hausdorff_original_to_decoded = hausdorff(out.hausdorff_original_to_decoded, s_occ[i]);
        const bool surface = (c > 0 && original.at(c - 1, r) == Cell::kFree) ||
                             (c + 1 < w && original.at(c + 1, r) == Cell::kFree) ||
                             (r > 0 && original.at(c, r - 1) == Cell::kFree) ||
                             (r + 1 < h && original.at(c, r + 1) == Cell::kFree);
        if (surface) {
          ++out.wall_surface_cells;
          out.wall_surface_kept += s_occ[i] <= t;
        }
      }
      if (b == Cell::kOccupied) {
        out.hausdorff_decoded_to_original = hausdorff(out.hausdorff_decoded_to_original, o_occ[i]);
      }
      if (b == Cell::kFree && o_free[i] > t) {
        ++out.free_moved_beyond;
        out.unknown_turned_free_beyond += a == Cell::kUnknown;
      }
      out.free_lost_beyond += a == Cell::kFree && s_free[i] > t;
    }
  }
  const auto topology = tolerance_internal::FindTopologyFaults(original, decoded, false);
  out.leaks = topology.leaks;
  out.splits = topology.splits;
  const auto plans = tolerance_internal::ComparePlans(original, decoded, false);
  out.plan_pairs = plans.pairs;
  out.plan_disagreements = plans.disagreements;
  return out;
}

}  // namespace linemap
