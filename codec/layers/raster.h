// The normative integer rasterisation of spec/format.md section
// "Rasterisation": which cells a lattice segment covers and which cells a
// closed 8-connected chain encloses. Integer arithmetic only, so every
// platform draws the same cells.
#ifndef LINEMAP_CODEC_LAYERS_RASTER_H_
#define LINEMAP_CODEC_LAYERS_RASTER_H_

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "linemap/segmentation.h"

namespace linemap {

// floor(num / den) for den > 0.
inline std::int64_t FloorDiv(std::int64_t num, std::int64_t den) {
  std::int64_t q = num / den;
  if ((num % den) != 0 && num < 0) --q;
  return q;
}

// Visits the n+1 cells of the segment a -> b, n = max(|dx|, |dy|): step i
// covers (a.col + floor((2 i dx + n) / 2n), a.row + floor((2 i dy + n) / 2n)),
// i.e. the cell whose centre is nearest the exact point, halves rounded up.
template <typename Visit>
void RasterizeSegment(CellIndex a, CellIndex b, Visit&& visit) {
  const std::int64_t dx = std::int64_t{b.col} - a.col;
  const std::int64_t dy = std::int64_t{b.row} - a.row;
  const std::int64_t n = std::max(std::llabs(dx), std::llabs(dy));
  if (n == 0) {
    visit(a.col, a.row);
    return;
  }
  // The quotients and remainders of (2 i dx + n) / 2n (and of dy's) are
  // carried from step to step rather than divided anew: each numerator
  // grows by 2 dx, at most the divisor, so each remainder leaves [0, 2n) by
  // at most one divisor a step. Step 0's are 0 and n.
  const std::int64_t den = 2 * n;
  std::int64_t col = a.col, row = a.row;
  std::int64_t col_rem = n, row_rem = n;
  for (std::int64_t i = 0; i <= n; ++i) {
    visit(static_cast<int>(col), static_cast<int>(row));
    col_rem += 2 * dx;
    if (col_rem >= den) {
      col_rem -= den;
      ++col;
    } else if (col_rem < 0) {
      col_rem += den;
      --col;
    }
    row_rem += 2 * dy;
    if (row_rem >= den) {
      row_rem -= den;
      ++row;
    } else if (row_rem < 0) {
      row_rem += den;
      --row;
    }
  }
}

// Visits every cell enclosed by the closed chain (consecutive cells and the
// last and first are 8-adjacent or equal): the chain's own cells, plus each
// cell (c, r) for which an odd number of chain steps p -> q with
// (p.row > r) != (q.row > r) cross row r at a column x > c, where x is the
// column of whichever of p, q lies on row r. Cells may be visited twice.
template <typename Visit>
void FillChain(const std::vector<CellIndex>& chain, Visit&& visit) {
  std::vector<std::pair<int, int>> crossings;  // (row, column)
  const std::size_t n = chain.size();
  for (std::size_t i = 0; i < n; ++i) {
    const CellIndex p = chain[i];
    const CellIndex q = chain[(i + 1) % n];
    visit(p.col, p.row);
    if ((p.row > q.row ? p.row - q.row : q.row - p.row) != 1) continue;
    const int r = std::min(p.row, q.row);
    crossings.emplace_back(r, p.row == r ? p.col : q.col);
  }
  std::sort(crossings.begin(), crossings.end());
  for (std::size_t i = 0; i + 1 < crossings.size(); i += 2) {
    // Crossings come in pairs on each row (a closed curve crosses the line
    // row + 1/2 an even number of times); cells in [x0, x1) are inside.
    const int row = crossings[i].first;
    for (int c = crossings[i].second; c < crossings[i + 1].second; ++c) visit(c, row);
  }
}

// Whether the closed chain encloses `cell` (FillChain's cells, one cell
// tested): on the chain, or an odd number of its steps cross the line
// row + 1/2 at a column right of the cell.
inline bool ChainEncloses(const std::vector<CellIndex>& chain, CellIndex cell) {
  bool inside = false;
  const std::size_t n = chain.size();
  for (std::size_t i = 0; i < n; ++i) {
    const CellIndex p = chain[i];
    const CellIndex q = chain[(i + 1) % n];
    if (p == cell) return true;
    // A step crossing row + 1/2 joins rows r and r + 1; its end on row r
    // is where it crosses.
    const bool crosses = (p.row == cell.row && q.row == cell.row + 1) ||
                         (q.row == cell.row && p.row == cell.row + 1);
    const int x = p.row == cell.row ? p.col : q.col;
    if (crosses && x > cell.col) inside = !inside;
  }
  return inside;
}

}  // namespace linemap

#endif  // LINEMAP_CODEC_LAYERS_RASTER_H_
