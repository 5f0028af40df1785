// SimplifyWithinTolerance(): the map in blocks (tolerance_blocks.h).
// CheckTolerance(): the guarantees' figures.
#include "codec/tolerance/simplify.h"

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "codec/tolerance/tolerance_blocks.h"
#include "codec/tolerance/tolerance_internal.h"

namespace linemap {

using tolerance_internal::CellMask;
using tolerance_internal::ChebyshevDistance;
using tolerance_internal::kFar;

bool ToleranceReport::Holds() const {
  return same_size && hausdorff_original_to_decoded >= 0 &&
         hausdorff_original_to_decoded <= tolerance_cells && hausdorff_decoded_to_original >= 0 &&
         hausdorff_decoded_to_original <= tolerance_cells && free_moved_beyond == 0 &&
         free_lost_beyond == 0 && unknown_turned_free_beyond == 0 && leaks == 0 && splits == 0 &&
         plan_disagreements == 0 && local_plan_disagreements == 0;
}

StatusOr<Grid> SimplifyWithinTolerance(const Grid& grid, int tolerance_cells) {
  if (tolerance_cells < 0 || tolerance_cells > kMaxToleranceCells) {
    return InvalidArgumentError("tolerance " + std::to_string(tolerance_cells) +
                                " cells is outside 0.." + std::to_string(kMaxToleranceCells));
  }
  if (tolerance_cells == 0 || grid.empty()) return grid;
  LINEMAP_ASSIGN_OR_RETURN(BlockCells blocks, FitBlockCells(grid, tolerance_cells));
  return ComposeBlockCells(grid, blocks);
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
  const auto local = tolerance_internal::CountLocalPlans(original, decoded, kLocalPlanSteps);
  out.local_plans = local.plans;
  out.local_plan_disagreements = local.disagreements;
  return out;
}

}  // namespace linemap
