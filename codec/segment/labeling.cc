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

}  // namespace

Labeling LabelComponents(const BinaryMask& mask, Connectivity connectivity) {
  Labeling result;
  result.width = mask.width;
  result.height = mask.height;
  const int w = mask.width;
  const int h = mask.height;
  // First pass: provisional labels (union-find ids + 1; 0 = background).
  // Neighbours already labelled are copied without a find where the
  // neighbourhood guarantees they are joined already (in 8-connectivity N
  // touches NW, NE and W; NW touches W).
  std::vector<std::int32_t> provisional = LargeVector<std::int32_t>(mask.bits.size(), 0);
  UnionFind table;
  const bool eight = connectivity == Connectivity::kEight;
  for (int row = 0; row < h; ++row) {
    const std::size_t base = static_cast<std::size_t>(row) * w;
    const std::int32_t* up = row > 0 ? &provisional[base - w] : nullptr;
    std::int32_t* cur = &provisional[base];
    const std::uint8_t* bits = &mask.bits[base];
    for (int col = 0; col < w; ++col) {
      if (!bits[col]) {
        col = FirstNonZeroByte(bits, col, w) - 1;
        continue;
      }
      const std::int32_t north = up ? up[col] : 0;
      // Inside a blob (most cells of a large one) the north label decides
      // in 8-connectivity: taken before the other neighbours are read.
      if (eight && north) {
        cur[col] = north;
        continue;
      }
      const std::int32_t west = col > 0 ? cur[col - 1] : 0;
      std::int32_t label = 0;
      if (eight) {
        const std::int32_t north_west = (up && col > 0) ? up[col - 1] : 0;
        const std::int32_t north_east = (up && col + 1 < w) ? up[col + 1] : 0;
        if (north) {
          label = north;
        } else if (north_east) {
          const std::int32_t other = west ? west : north_west;
          label = other ? table.Union(north_east - 1, other - 1) + 1 : north_east;
        } else {
          label = west ? west : north_west;
        }
      } else if (north && west && north != west) {
        label = table.Union(north - 1, west - 1) + 1;
      } else {
        label = north ? north : west;
      }
      cur[col] = label ? label : table.Add() + 1;
    }
  }
  // Roots are the labels of first cells (unions keep the smaller id and ids
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
    for (int col = 0; col < w; ++col) {
      const std::int32_t p = labels[col];
      if (!p) {
        col = FirstNonZeroByte(bits, col, w) - 1;
        continue;
      }
      // The run of cells with this provisional label is one component's:
      // its statistics are updated once for the run, not once a cell.
      int end = col + 1;
      while (end < w && labels[end] == p) ++end;
      const std::int32_t label = final_label[p - 1];
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
      col = end - 1;
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
