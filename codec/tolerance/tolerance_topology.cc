// Distance transforms and free-space topology for the tolerance checks.
#include <algorithm>
#include <cstdint>
#include <deque>
#include <utility>
#include <vector>

#include "codec/tolerance/compare_internal.h"
#include "codec/tolerance/tolerance_internal.h"
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

// out[p] = 1 where some in[q] (q < count) is non-zero with |q - p| <=
// radius.
void SpreadLine(const std::uint8_t* in, std::uint8_t* out, std::size_t count, std::size_t radius) {
  std::size_t inside = 0;  // non-zero cells in the window of the next p
  for (std::size_t q = 0; q < count + radius; ++q) {
    if (q < count) inside += in[q] != 0;
    if (q < radius) continue;
    const std::size_t p = q - radius;
    out[p] = inside > 0;
    if (p >= radius) inside -= in[p - radius] != 0;
  }
}

}  // namespace

std::vector<std::uint8_t> WithinDistance(int width, int height,
                                         const std::vector<std::uint8_t>& mask, int radius) {
  const std::size_t w = static_cast<std::size_t>(width);
  const std::size_t h = static_cast<std::size_t>(height);
  const std::size_t r = static_cast<std::size_t>(radius);
  std::vector<std::uint8_t> rows(mask.size());
  for (std::size_t y = 0; y < h; ++y) SpreadLine(mask.data() + y * w, rows.data() + y * w, w, r);
  // The columns a row at a time, so that the passes read memory in order:
  // `inside` counts the window's non-zero cells of each column.
  std::vector<std::uint8_t> out(mask.size());
  std::vector<std::uint32_t> inside(w, 0);
  for (std::size_t q = 0; q < h + r; ++q) {
    if (q < h) {
      const std::uint8_t* add = rows.data() + q * w;
      for (std::size_t x = 0; x < w; ++x) inside[x] += add[x];
    }
    if (q < r) continue;
    const std::size_t p = q - r;
    std::uint8_t* row = out.data() + p * w;
    for (std::size_t x = 0; x < w; ++x) row[x] = inside[x] > 0;
    if (p >= r) {
      const std::uint8_t* drop = rows.data() + (p - r) * w;
      for (std::size_t x = 0; x < w; ++x) inside[x] -= drop[x];
    }
  }
  return out;
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

// The 4-neighbour i of cell j as a byte (kFromNone: none), and back.
constexpr std::uint8_t kFromNone = 0, kFromPreviousColumn = 1, kFromNextColumn = 2,
                       kFromRowBelow = 3, kFromRowAbove = 4;
std::uint8_t FromOf(std::size_t i, std::size_t j, std::size_t w) {
  if (i + 1 == j) return kFromPreviousColumn;
  if (i == j + 1) return kFromNextColumn;
  return i + w == j ? kFromRowBelow : kFromRowAbove;
}
std::size_t CellFrom(std::size_t j, std::uint8_t from, std::size_t w) {
  switch (from) {
    case kFromPreviousColumn:
      return j - 1;
    case kFromNextColumn:
      return j + 1;
    case kFromRowBelow:
      return j - w;
    default:
      return j + w;
  }
}

// The order in which a 0-1 breadth-first search settles its cells, as a
// deque into which every source was pushed at the back first, in raster
// order, then cells reached at the same cost at the front and at one more
// at the back: without the sources in it. The deque is always the cells
// pushed at the front (last in, first out), then the sources not yet taken
// (raster order), then the cells pushed at the back (first in, first out),
// so its front is the top of the first, else the next source, else the
// head of the last. A split region's main piece is most of the map's free
// space on a map the decode cut in two: its cells, 8 bytes each in the
// deque, were the largest array of the search (23 % of the tolerance
// save's peak on a generated 1024 x 1024 office map, about 6 bytes a cell).
template <typename IsSource>
class ZeroOneOrder {
 public:
  // `is_source(i)` for each cell i < n, asked in raster order.
  ZeroOneOrder(std::size_t n, IsSource is_source) : n_(n), is_source_(std::move(is_source)) {}

  void PushFront(std::size_t i) { front_.push_back(i); }
  void PushBack(std::size_t i) { back_.push_back(i); }

  // The next cell of the deque, false when it is empty.
  bool Pop(std::size_t* i) {
    if (!front_.empty()) {
      *i = front_.back();
      front_.pop_back();
      return true;
    }
    while (next_source_ < n_) {
      const std::size_t k = next_source_++;
      if (is_source_(k)) {
        *i = k;
        return true;
      }
    }
    if (back_.empty()) return false;
    *i = back_.front();
    back_.pop_front();
    return true;
  }

 private:
  std::size_t n_;
  IsSource is_source_;
  std::size_t next_source_ = 0;
  std::vector<std::size_t> front_;
  std::deque<std::size_t> back_;
};

// The lost free cells (free in the original, not in the decode) whose
// return joins every split-off piece to the main piece of its region: a
// 0-1 breadth-first search over each split region's original cells from its
// main piece, a lost cell costing 1 and a decoded free one 0, traced back
// from the first cell reached of each other piece. Giving back every lost
// cell beside a piece would also work, but along the ragged edge of a SLAM
// map's free space that is dozens of cells where one or two reopen the way.
std::vector<std::size_t> ReconnectingCells(const std::vector<std::int32_t>& orig,
                                           const std::vector<std::int32_t>& dec,
                                           std::size_t dec_components,
                                           const std::vector<std::uint8_t>& split,
                                           const std::vector<std::int32_t>& main_piece,
                                           const Grid& grid) {
  constexpr std::int32_t kUnreached = INT32_MAX;
  const std::size_t n = orig.size();
  const std::size_t w = static_cast<std::size_t>(grid.width());
  const std::size_t h = static_cast<std::size_t>(grid.height());
  const auto is_source = [&](std::size_t i) {
    return orig[i] && split[orig[i]] && dec[i] && dec[i] == main_piece[orig[i]];
  };
  std::vector<std::int32_t> cost(n, kUnreached);
  for (std::size_t i = 0; i < n; ++i) {
    if (is_source(i)) cost[i] = 0;
  }
  // Which neighbour each cell was last reached from (a byte a cell, not
  // the neighbour's index: 7 bytes a cell less at the fitting's peak).
  std::vector<std::uint8_t> from(n, kFromNone);
  ZeroOneOrder order(n, is_source);
  std::vector<std::uint8_t> piece_seen(dec_components + 1, 0);
  std::vector<std::size_t> piece_first;  // the first cell settled of each other piece
  std::vector<std::uint8_t> settled(n, 0);
  for (std::size_t i = 0; order.Pop(&i);) {
    if (settled[i]) continue;
    settled[i] = 1;
    if (dec[i] && dec[i] != main_piece[orig[i]] && !piece_seen[dec[i]]) {
      piece_seen[dec[i]] = 1;
      piece_first.push_back(i);
    }
    ForEachNeighbour(w, h, i, [&](std::size_t j) {
      if (orig[j] != orig[i]) return;
      // A decoded free cell costs nothing (front of the queue), a lost one 1.
      const std::int32_t step = dec[j] ? 0 : 1;
      if (cost[i] + step >= cost[j]) return;
      cost[j] = cost[i] + step;
      from[j] = FromOf(i, j, w);
      if (step == 0) {
        order.PushFront(j);
      } else {
        order.PushBack(j);
      }
    });
  }
  std::vector<std::size_t> out;
  // The search is over and `settled` is not read again: it marks the
  // cells walked back from now on.
  std::vector<std::uint8_t>& walked = settled;
  std::fill(walked.begin(), walked.end(), 0);
  for (const std::size_t first : piece_first) {
    std::size_t i = first;
    while (!walked[i]) {
      walked[i] = 1;
      if (!dec[i]) out.push_back(i);
      if (from[i] == kFromNone) break;
      i = CellFrom(i, from[i], w);
    }
  }
  return out;
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
  const auto dec_orig = LabelPairs(dec.labels, orig.labels, [&](std::int32_t) { return true; });
  for (std::size_t i = 0, j = 0; i < dec_orig.size(); i = j) {
    std::size_t regions = 0;
    for (j = i; j < dec_orig.size() && dec_orig[j].first == dec_orig[i].first; ++j) {
      regions += big(dec_orig[j].second);
    }
    if (regions > 1) out.leaks += regions - 1;
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
  if (!want_culprits || out.splits == 0) return out;
  out.split_culprits = ReconnectingCells(orig.labels, dec.labels, dec.components.size(), split,
                                         main_piece, original);
  return out;
}

}  // namespace linemap::tolerance_internal
