// Two-pass connected-component labelling with a union-find equivalence table
// (Kosteley et al., section 3.2 B: 4-connected neighbours W and N; section
// 3.2 C: 8-connected, adding NW and NE). The second pass renumbers the
// components in the raster order of their first cells and collects the
// paper's statistics: cell count, first cell, bounding box.
// Outer contours: Moore-neighbour tracing with Jacob's stopping rule.
#include "linemap/labeling.h"

#include <algorithm>
#include <array>

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

}  // namespace

Labeling LabelComponents(const BinaryMask& mask, Connectivity connectivity) {
  Labeling result;
  result.width = mask.width;
  result.height = mask.height;
  const int w = mask.width;
  const int h = mask.height;
  // Provisional labels are 1-based union-find ids + 1; 0 = background.
  std::vector<std::int32_t> provisional(mask.bits.size(), 0);
  UnionFind table;
  const bool eight = connectivity == Connectivity::kEight;
  for (int row = 0; row < h; ++row) {
    const std::size_t base = static_cast<std::size_t>(row) * w;
    for (int col = 0; col < w; ++col) {
      if (!mask.bits[base + col]) continue;
      std::array<std::int32_t, 4> neighbours{};
      int n = 0;
      if (col > 0 && provisional[base + col - 1]) neighbours[n++] = provisional[base + col - 1];
      if (row > 0) {
        const std::size_t up = base - w;
        if (provisional[up + col]) neighbours[n++] = provisional[up + col];
        if (eight && col > 0 && provisional[up + col - 1]) {
          neighbours[n++] = provisional[up + col - 1];
        }
        if (eight && col + 1 < w && provisional[up + col + 1]) {
          neighbours[n++] = provisional[up + col + 1];
        }
      }
      if (n == 0) {
        provisional[base + col] = table.Add() + 1;
        continue;
      }
      std::int32_t root = table.Find(neighbours[0] - 1);
      for (int i = 1; i < n; ++i) root = table.Union(root, neighbours[i] - 1);
      provisional[base + col] = root + 1;
    }
  }
  // Second pass: final labels in raster order of first cells, and statistics.
  std::vector<std::int32_t> final_label(table.size(), 0);
  result.labels.assign(mask.bits.size(), 0);
  for (int row = 0; row < h; ++row) {
    const std::size_t base = static_cast<std::size_t>(row) * w;
    for (int col = 0; col < w; ++col) {
      const std::int32_t p = provisional[base + col];
      if (!p) continue;
      const std::int32_t root = table.Find(p - 1);
      if (!final_label[root]) {
        result.components.push_back({0, {col, row}, {col, row, col, row}});
        final_label[root] = static_cast<std::int32_t>(result.components.size());
      }
      const std::int32_t label = final_label[root];
      result.labels[base + col] = label;
      ComponentStats& stats = result.components[label - 1];
      ++stats.cell_count;
      stats.box.min_col = std::min(stats.box.min_col, col);
      stats.box.max_col = std::max(stats.box.max_col, col);
      stats.box.max_row = row;  // rows are visited in increasing order
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
