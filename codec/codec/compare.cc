// CompareGrids(): the quality measures of issue 6 (cells equal, obstacle
// recall / precision within one cell, free IoU, leaks, unknown turned free).
#include <algorithm>
#include <set>

#include "linemap/codec.h"

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

// Labels the 4-connected free components of `grid`; returns labels (0 = not
// free) and fills `sizes` (index = label).
std::vector<std::uint32_t> LabelFree(const Grid& grid, std::vector<std::size_t>* sizes) {
  const int w = grid.width();
  const int h = grid.height();
  std::vector<std::uint32_t> label(grid.size(), 0);
  sizes->assign(1, 0);
  std::vector<std::size_t> stack;
  for (std::size_t start = 0; start < label.size(); ++start) {
    if (label[start] || grid.cells()[start] != Cell::kFree) continue;
    const std::uint32_t id = static_cast<std::uint32_t>(sizes->size());
    sizes->push_back(0);
    label[start] = id;
    stack.push_back(start);
    while (!stack.empty()) {
      const std::size_t i = stack.back();
      stack.pop_back();
      ++(*sizes)[id];
      const int c = static_cast<int>(i % w);
      const int r = static_cast<int>(i / w);
      auto push = [&](std::size_t j) {
        if (!label[j] && grid.cells()[j] == Cell::kFree) {
          label[j] = id;
          stack.push_back(j);
        }
      };
      if (c > 0) push(i - 1);
      if (c + 1 < w) push(i + 1);
      if (r > 0) push(i - w);
      if (r + 1 < h) push(i + w);
    }
  }
  return label;
}

}  // namespace

GridComparison CompareGrids(const Grid& original, const Grid& decoded) {
  GridComparison out;
  out.same_geometry = original.width() == decoded.width() &&
                      original.height() == decoded.height() &&
                      original.meta.resolution == decoded.meta.resolution &&
                      original.meta.origin == decoded.meta.origin;
  if (original.width() != decoded.width() || original.height() != decoded.height()) return out;
  out.cells = original.size();
  std::size_t occ_orig = 0, occ_recalled = 0, occ_dec = 0, occ_precise = 0;
  std::size_t free_both = 0, free_any = 0, free_orig = 0;
  for (int r = 0; r < original.height(); ++r) {
    for (int c = 0; c < original.width(); ++c) {
      const Cell a = original.at(c, r);
      const Cell b = decoded.at(c, r);
      out.cells_equal += a == b;
      if (a == Cell::kOccupied) {
        ++occ_orig;
        occ_recalled += OccupiedNear(decoded, c, r);
      }
      if (b == Cell::kOccupied) {
        ++occ_dec;
        occ_precise += OccupiedNear(original, c, r);
      }
      const bool fa = a == Cell::kFree;
      const bool fb = b == Cell::kFree;
      free_orig += fa;
      free_both += fa && fb;
      free_any += fa || fb;
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
  // free component.
  std::vector<std::size_t> orig_sizes, dec_sizes;
  const std::vector<std::uint32_t> orig_label = LabelFree(original, &orig_sizes);
  const std::vector<std::uint32_t> dec_label = LabelFree(decoded, &dec_sizes);
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;  // (decoded, original)
  for (std::size_t i = 0; i < orig_label.size(); ++i) {
    if (orig_label[i] && dec_label[i] && orig_sizes[orig_label[i]] >= kLeakRegionCells) {
      pairs.emplace_back(dec_label[i], orig_label[i]);
    }
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  for (std::size_t i = 1; i < pairs.size(); ++i) out.leaks += pairs[i].first == pairs[i - 1].first;
  return out;
}

}  // namespace linemap
