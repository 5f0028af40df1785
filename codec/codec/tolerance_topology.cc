// Distance transforms and free-space topology for the tolerance checks.
#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include "codec/codec/compare_internal.h"
#include "codec/codec/tolerance_internal.h"
#include "linemap/codec.h"
#include "linemap/labeling.h"

namespace linemap::tolerance_internal {

std::vector<std::uint8_t> CellMask(const Grid& grid, Cell value) {
  std::vector<std::uint8_t> mask(grid.size());
  for (std::size_t i = 0; i < mask.size(); ++i) mask[i] = grid.cells()[i] == value;
  return mask;
}

std::vector<std::int32_t> ChebyshevDistance(int width, int height,
                                            const std::vector<std::uint8_t>& mask) {
  std::vector<std::int32_t> d(mask.size());
  for (std::size_t i = 0; i < mask.size(); ++i) d[i] = mask[i] ? 0 : kFar;
  const std::size_t w = static_cast<std::size_t>(width);
  // Forward pass: the neighbours already visited (left, and the row below
  // in index order); backward pass: the others.
  for (int r = 0; r < height; ++r) {
    for (int c = 0; c < width; ++c) {
      const std::size_t i = r * w + c;
      std::int32_t best = d[i];
      if (c > 0) best = std::min(best, d[i - 1] + 1);
      if (r > 0) {
        best = std::min(best, d[i - w] + 1);
        if (c > 0) best = std::min(best, d[i - w - 1] + 1);
        if (c + 1 < width) best = std::min(best, d[i - w + 1] + 1);
      }
      d[i] = std::min(best, kFar);
    }
  }
  for (int r = height - 1; r >= 0; --r) {
    for (int c = width - 1; c >= 0; --c) {
      const std::size_t i = r * w + c;
      std::int32_t best = d[i];
      if (c + 1 < width) best = std::min(best, d[i + 1] + 1);
      if (r + 1 < height) {
        best = std::min(best, d[i + w] + 1);
        if (c + 1 < width) best = std::min(best, d[i + w + 1] + 1);
        if (c > 0) best = std::min(best, d[i + w - 1] + 1);
      }
      d[i] = std::min(best, kFar);
    }
  }
  return d;
}

namespace {

// Distinct (a, b) pairs of labels over the cells where both are non-zero
// and `keep_a(a)` holds, sorted.
template <typename Keep>
std::vector<std::pair<std::int32_t, std::int32_t>> LabelPairs(const std::vector<std::int32_t>& a,
                                                              const std::vector<std::int32_t>& b,
                                                              Keep keep_a) {
  std::vector<std::pair<std::int32_t, std::int32_t>> pairs;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i] && b[i] && keep_a(a[i])) {
      // Runs repeat the pair: one per run keeps the sort small.
      const std::pair<std::int32_t, std::int32_t> pair(a[i], b[i]);
      if (pairs.empty() || pairs.back() != pair) pairs.push_back(pair);
    }
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  return pairs;
}

}  // namespace

TopologyFaults FindTopologyFaults(const Grid& original, const Grid& decoded, bool want_culprits) {
  TopologyFaults out;
  const Labeling orig = codec_internal::LabelFree(original);
  const Labeling dec = codec_internal::LabelFree(decoded);
  auto big = [&](std::int32_t label) {
    return orig.components[label - 1].cell_count >= kLeakRegionCells;
  };
  // Leaks: a decoded component over several big original regions.
  std::vector<std::uint8_t> joining(dec.components.size() + 1, 0);
  const auto dec_orig = LabelPairs(dec.labels, orig.labels, [&](std::int32_t) { return true; });
  for (std::size_t i = 0, j = 0; i < dec_orig.size(); i = j) {
    std::size_t regions = 0;
    for (j = i; j < dec_orig.size() && dec_orig[j].first == dec_orig[i].first; ++j) {
      regions += big(dec_orig[j].second);
    }
    if (regions > 1) {
      out.leaks += regions - 1;
      joining[dec_orig[i].first] = 1;
    }
  }
  // Splits: a big original region over several decoded components; the
  // piece holding most of its cells is the region, the others split off.
  std::vector<std::int32_t> main_piece(orig.components.size() + 1, 0);
  std::vector<std::uint8_t> split(orig.components.size() + 1, 0);
  const auto orig_dec = LabelPairs(orig.labels, dec.labels, big);
  for (std::size_t i = 0, j = 0; i < orig_dec.size(); i = j) {
    std::size_t best_cells = 0;
    for (j = i; j < orig_dec.size() && orig_dec[j].first == orig_dec[i].first; ++j) {
      const std::size_t cells = dec.components[orig_dec[j].second - 1].cell_count;
      if (cells > best_cells) {
        best_cells = cells;
        main_piece[orig_dec[i].first] = orig_dec[j].second;
      }
    }
    if (j - i > 1) {
      ++out.splits;
      split[orig_dec[i].first] = 1;
    }
  }
  if (!want_culprits || (out.leaks == 0 && out.splits == 0)) return out;
  const int w = original.width();
  const int h = original.height();
  for (int r = 0; r < h; ++r) {
    for (int c = 0; c < w; ++c) {
      const std::size_t i = original.Index(c, r);
      const std::int32_t d = dec.labels[i];
      const std::int32_t o = orig.labels[i];
      if (d && !o && joining[d]) out.culprits.push_back(i);
      if (o && !d && split[o]) {
        // A lost free cell beside a split-off piece of its region.
        static constexpr int kDc[4] = {1, -1, 0, 0};
        static constexpr int kDr[4] = {0, 0, 1, -1};
        for (int k = 0; k < 4; ++k) {
          const std::int32_t n = dec.get(c + kDc[k], r + kDr[k]);
          if (n && n != main_piece[o]) {
            out.culprits.push_back(i);
            out.split_culprits.push_back(i);
            break;
          }
        }
      }
    }
  }
  return out;
}

}  // namespace linemap::tolerance_internal
