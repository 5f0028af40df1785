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

// One coordinate's offset at step i of a lattice segment, floor((i * step +
// n) / 2n) with step = 2 dx or 2 dy (spec 8.1's rounding), for i rising by
// one at a time: |step| <= 2n, so each step carries at most one, and no
// division runs per cell.
struct MinorStepper {
  std::int64_t step, two_n, q, rem;
  MinorStepper(std::int64_t i0, std::int64_t step_, std::int64_t n)
      : step(step_),
        two_n(2 * n),
        q(FloorDiv(i0 * step_ + n, 2 * n)),
        rem(i0 * step_ + n - FloorDiv(i0 * step_ + n, 2 * n) * 2 * n) {}
  void Next() {
    rem += step;
    if (rem >= two_n) {
      rem -= two_n;
      ++q;
    } else if (rem < 0) {
      rem += two_n;
      --q;
    }
  }
};

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
  // The floors are stepped (MinorStepper) rather than divided out per cell:
  // step 0's quotients are 0, their remainders n.
  MinorStepper col(0, 2 * dx, n), row(0, 2 * dy, n);
  for (std::int64_t i = 0; i <= n; ++i) {
    visit(static_cast<int>(a.col + col.q), static_cast<int>(a.row + row.q));
    col.Next();
    row.Next();
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
