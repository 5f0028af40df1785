// Two-pass connected-component labelling with a union-find equivalence table
// (Kosteley et al., section 3.2 B: 4-connected neighbours W and N; section
// 3.2 C: 8-connected, adding NW and NE). The second pass renumbers the
// components in the raster order of their first cells and collects the
// paper's statistics: cell count, first cell, bounding box.
// Outer contours: Moore-neighbour tracing with Jacob's stopping rule.
#include "linemap/labeling.h"

#include <algorithm>
#include <array>

#include "codec/segment/byte_scan.h"
#include "format/large_vector.h"

namespace linemap {
namespace {

class UnionFind {
 public:
  std::int32_t Add() {
    parent_.push_back(static_cast<std::int32_t>(parent_.size()));
    return parent_.back();
  }
  std::int32_t Find(std::int32_t x) {
    std::int32_t root = x;
    while (parent_[root] != root) root = parent_[root];
    while (parent_[x] != root) {  // path compression
      const std::int32_t next = parent_[x];
      parent_[x] = root;
      x = next;
    }
    return root;
  }
  // Keeps the smaller root, as the paper's "minimum value" rule.
  std::int32_t Union(std::int32_t a, std::int32_t b) {
    a = Find(a);
    b = Find(b);
    if (a == b) return a;
    if (b < a) std::swap(a, b);
    parent_[b] = a;
    return a;
  }
  std::size_t size() const { return parent_.size(); }

 private:
  std::vector<std::int32_t> parent_;
};

// The label a run of set cells [col, end) of a row takes from the runs of
// the row above it (`up` their provisional labels, `up_bits` their mask
// row) that it touches: those over [col, end) in 4-connectivity, over
// [col - 1, end] in 8 (`reach` 1). Every cell of a run above holds its
// run's label, so each run above is read once, at its first cell within
// reach. 0 when it touches none.
std::int32_t LabelFromAbove(const std::int32_t* up, const std::uint8_t* up_bits, int col, int end,
                            int w, int reach, UnionFind* table) {
  const int hi = std::min(end + reach, w);
  std::int32_t label = 0;
  for (int x = FirstNonZeroByte(up_bits, std::max(col - reach, 0), hi); x < hi;
       x = FirstNonZeroByte(up_bits, FirstZeroByte(up_bits, x, hi), hi)) {
    const std::int32_t above = up[x];
    if (label == 0) {
      label = above;
    } else if (above != label) {
      label = table->Union(above - 1, label - 1) + 1;
    }
  }
  return label;
}

}  // namespace

Labeling LabelComponents(const BinaryMask& mask, Connectivity connectivity) {
  Labeling result;
  result.width = mask.width;
  result.height = mask.height;
  const int w = mask.width;
  const int h = mask.height;
  // A mask of no columns (or no rows) has no cells to label; its rows below
  // would index an empty vector.
  if (w == 0 || h == 0) return result;
  // First pass: provisional labels (union-find ids + 1; 0 = background),
  // one per run of set cells in a row, found eight cells at a time: a run
  // joins the runs above it that it touches. Cell by cell this pass and
  // the next were 7-9 % of an encode (the obstacles' labelling, whose
  // unknown and wall areas are long runs).
  std::vector<std::int32_t> provisional = LargeVector<std::int32_t>(mask.bits.size(), 0);
  UnionFind table;
  const int reach = connectivity == Connectivity::kEight ? 1 : 0;
  for (int row = 0; row < h; ++row) {
    const std::size_t base = static_cast<std::size_t>(row) * w;
    const std::uint8_t* bits = &mask.bits[base];
    std::int32_t* cur = &provisional[base];
    for (int col = FirstNonZeroByte(bits, 0, w); col < w;) {
      const int end = FirstZeroByte(bits, col, w);
      std::int32_t label =
          row > 0 ? LabelFromAbove(cur - w, bits - w, col, end, w, reach, &table) : 0;
      if (label == 0) label = table.Add() + 1;
      std::fill(cur + col, cur + end, label);
      col = FirstNonZeroByte(bits, end, w);
    }
  }
  // Roots are the labels of first runs (unions keep the smaller id and ids
  // grow in raster order), so numbering roots by id numbers components in
  // the raster order of their first cells.
  std::vector<std::int32_t> final_label(table.size(), 0);
  std::int32_t count = 0;
  for (std::size_t i = 0; i < table.size(); ++i) {
    const std::int32_t id = static_cast<std::int32_t>(i);
    const std::int32_t root = table.Find(id);
    final_label[i] = root == id ? ++count : final_label[root];
  }
  result.components.resize(static_cast<std::size_t>(count));
  result.labels = std::move(provisional);  // relabelled in place
  for (int row = 0; row < h; ++row) {
    std::int32_t* labels = result.labels.data() + static_cast<std::size_t>(row) * w;
    const std::uint8_t* bits = &mask.bits[static_cast<std::size_t>(row) * w];
    for (int col = FirstNonZeroByte(bits, 0, w); col < w;) {
      // A run of set cells holds one provisional label: the statistics are
      // updated once for the run, not once a cell.
      const int end = FirstZeroByte(bits, col, w);
      const std::int32_t label = final_label[labels[col] - 1];
      std::fill(labels + col, labels + end, label);
      ComponentStats& stats = result.components[label - 1];
      if (stats.cell_count == 0) {
        stats.first_cell = {col, row};
        stats.box = {col, row, col, row};
      } else {
        if (col < stats.box.min_col) stats.box.min_col = col;
        stats.box.max_row = row;  // rows are visited in increasing order
      }
      if (end - 1 > stats.box.max_col) stats.box.max_col = end - 1;
      stats.cell_count += static_cast<std::size_t>(end - col);
      col = FirstNonZeroByte(bits, end, w);
    }
  }
  return result;
}

std::vector<CellIndex> TraceOuterContour(const Labeling& labeling, std::int32_t label) {
  std::vector<CellIndex> chain;
  if (label < 1 || static_cast<std::size_t>(label) > labeling.components.size()) return chain;
  // Clockwise (rows up) starting west.
  static constexpr std::array<CellIndex, 8> kDirs = {
      {{-1, 0}, {-1, 1}, {0, 1}, {1, 1}, {1, 0}, {1, -1}, {0, -1}, {-1, -1}}};
  auto direction_of = [](int dc, int dr) {
    for (int d = 0; d < 8; ++d) {
      if (kDirs[d].col == dc && kDirs[d].row == dr) return d;
    }
    return 0;
  };
  auto inside = [&](CellIndex c) { return labeling.get(c.col, c.row) == label; };
  // The first cell: everything west of it and in the row below is outside.
  const CellIndex start = labeling.components[label - 1].first_cell;
  chain.push_back(start);
  // Finds the next boundary cell clockwise from the backtrack direction.
  auto step = [&](CellIndex cur, int backtrack, CellIndex* next, int* next_backtrack) {
    for (int k = 1; k <= 8; ++k) {
      const int d = (backtrack + k) % 8;
      const CellIndex n{cur.col + kDirs[d].col, cur.row + kDirs[d].row};
      if (!inside(n)) continue;
      const int prev = (d + 7) % 8;
      const CellIndex p{cur.col + kDirs[prev].col, cur.row + kDirs[prev].row};
      *next = n;
      *next_backtrack = direction_of(p.col - n.col, p.row - n.row);
      return true;
    }
    return false;
  };
  CellIndex second;
  int backtrack = 0;
  if (!step(start, 0, &second, &backtrack)) return chain;  // isolated cell
  CellIndex cur = second;
  const std::size_t limit = 4 * labeling.components[label - 1].cell_count + 8;
  while (chain.size() <= limit) {
    CellIndex next;
    int next_backtrack = 0;
    step(cur, backtrack, &next, &next_backtrack);
    if (cur == start && next == second) break;  // Jacob's stopping rule
    chain.push_back(cur);
    cur = next;
    backtrack = next_backtrack;
  }
  return chain;
}

}  // namespace linemap
