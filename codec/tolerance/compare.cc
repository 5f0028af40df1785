// CompareGrids(): the quality measures of a decoded map (cells equal, obstacle
// recall / precision within one cell, free IoU, leaks, unknown turned free).
#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include "codec/tolerance/compare_internal.h"
#include "linemap/codec.h"
#include "linemap/labeling.h"

namespace linemap {
namespace {

// True when `grid` has an occupied cell within Chebyshev distance 1 of (c, r).
bool OccupiedNear(const Grid& grid, int c, int r) {
  for (int dr = -1; dr <= 1; ++dr) {
    for (int dc = -1; dc <= 1; ++dc) {
      if (grid.Contains(c + dc, r + dr) && grid.at(c + dc, r + dr) == Cell::kOccupied) return true;
    }
  }
  return false;
}

}  // namespace

namespace codec_internal {

Labeling LabelFree(const Grid& grid) {
  BinaryMask free(grid.width(), grid.height());
  for (std::size_t i = 0; i < free.bits.size(); ++i) free.bits[i] = grid.cells()[i] == Cell::kFree;
  return LabelComponents(free, Connectivity::kFour);
}

}  // namespace codec_internal

GridComparison CompareGrids(const Grid& original, const Grid& decoded) {
  GridComparison out;
  out.same_geometry = original.width() == decoded.width() &&
                      original.height() == decoded.height() &&
                      original.meta.resolution == decoded.meta.resolution &&
                      original.meta.origin == decoded.meta.origin;
  if (original.width() != decoded.width() || original.height() != decoded.height()) return out;
  out.cells = original.size();
  std::size_t occ_orig = 0, occ_recalled = 0, occ_dec = 0, occ_precise = 0;
  std::size_t free_both = 0, free_any = 0, free_orig = 0, free_only_decoded = 0;
  for (int r = 0; r < original.height(); ++r) {
    for (int c = 0; c < original.width(); ++c) {
      const Cell a = original.at(c, r);
      const Cell b = decoded.at(c, r);
      out.cells_equal += a == b;
      // A cell occupied in both is its own neighbour within one cell.
      if (a == Cell::kOccupied) {
        ++occ_orig;
        occ_recalled += b == Cell::kOccupied || OccupiedNear(decoded, c, r);
      }
      if (b == Cell::kOccupied) {
        ++occ_dec;
        occ_precise += a == Cell::kOccupied || OccupiedNear(original, c, r);
      }
      const bool fa = a == Cell::kFree;
      const bool fb = b == Cell::kFree;
      free_orig += fa;
      free_both += fa && fb;
      free_any += fa || fb;
      free_only_decoded += fb && !fa;
      out.unknown_turned_free += a == Cell::kUnknown && fb;
    }
  }
  if (occ_orig) out.obstacle_recall_1 = static_cast<double>(occ_recalled) / occ_orig;
  if (occ_dec) out.obstacle_precision_1 = static_cast<double>(occ_precise) / occ_dec;
  if (free_any) out.free_iou = static_cast<double>(free_both) / free_any;
  if (free_orig) {
    out.unknown_turned_free_share = static_cast<double>(out.unknown_turned_free) / free_orig;
  } else if (out.unknown_turned_free) {
    out.unknown_turned_free_share = 1.0;
  }
  // Leaks: original regions of kLeakRegionCells+ cells that share a decoded
  // free component. When every decoded free cell is free in the original,
  // each decoded component lies inside one original component: no leaks,
  // and no labelling needed.
  if (free_only_decoded == 0) return out;
  const Labeling orig = codec_internal::LabelFree(original);
  const Labeling dec = codec_internal::LabelFree(decoded);
  std::vector<std::pair<std::int32_t, std::int32_t>> pairs;  // (decoded, original)
  for (std::size_t i = 0; i < orig.labels.size(); ++i) {
    const std::int32_t a = orig.labels[i];
    const std::int32_t b = dec.labels[i];
    if (a && b && orig.components[a - 1].cell_count >= kLeakRegionCells) {
      // Runs of cells repeat the pair: keeping one per run makes the sort
      // below cost O(boundary) instead of O(free cells * log).
      const std::pair<std::int32_t, std::int32_t> pair(b, a);
      if (pairs.empty() || pairs.back() != pair) pairs.push_back(pair);
    }
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  for (std::size_t i = 1; i < pairs.size(); ++i) out.leaks += pairs[i].first == pairs[i - 1].first;
  return out;
}

}  // namespace linemap
