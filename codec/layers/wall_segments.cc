// The wall segments of a file: the extractor's lines (layer_extraction.h)
// on the lattice, kept on the walls, straightened and thinned out against
// the edge cells (layer_extraction_internal.h).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "codec/layers/layer_extraction.h"
#include "codec/layers/layer_extraction_internal.h"
#include "codec/layers/raster.h"
#include "codec/lines/extract_lines.h"
#include "linemap/lines.h"

namespace linemap {
namespace {

// The file's walls follow the pixel steps of slanted walls and keep both
// faces of a two-cell wall where that pays in distance, as the RM-Line
// paper's DisPL_ave (the mean distance of the edge cells to the nearest
// wall) rewards: the extractor's defaults with a tighter distance budget
// (0.03 cells instead of 0.05), a segment priced at half a cell of summed
// distance instead of 0.95 (so a two-cell wall longer than one cell keeps
// its two faces) and no specks handed to the furniture layer. Measured on
// the 25 maps of ../shared/maps, default files, DisPL_ave of the file's
// walls against that of RM-Line's lines:
//   StraightWalls()        189,175 bytes; 5 maps above RM-Line's (f1tenth
//                          columbia, levinelobby, mtl, nav2/map and
//                          tb3_sandbox, up to 2.1x its value)
//   extractor defaults     191,636; 2 above (tb3_sandbox 0.139 against
//                          0.109 cells, nav2/map 0.064 against 0.061)
//   budget 0.04, price 0.5 191,606; none above, nav2/map at 0.85x
//   budget 0.03, price 0.5 191,557 (+1.3 %); none above, the closest at
//                          0.68x (f1tenth/columbia 0.078 against 0.114)
// (the budgets measured without specks, as below). The last leaves a
// margin for maps not measured here. Walls drawn more exactly also make
// the cells a little cheaper (their context reads them), which is why a
// tighter budget costs so little.
LineExtractionOptions FileWallOptions() {
  LineExtractionOptions options;
  options.target_mean_distance_cells = 0.03;
  options.free_merge_cost_cells = 0.5;
  // Specks stay with the extractor, which fits them closer than the
  // covering pass (wall_cover.h) that would draw them otherwise: with
  // the default 3, DisPL_ave rose on SLAM maps (stage_ros/willow-full
  // 0.36 -> 0.57 cells) for 66 bytes less over the 25 maps.
  options.speck_max_cells = 0;
  return options;
}

}  // namespace

StatusOr<std::vector<LineSegment>> ExtractWallLines(const Grid& grid,
                                                    const EncodeOptions& options) {
  if (grid.empty()) return std::vector<LineSegment>{};
  // A file saved within a tolerance is for bandwidth: its walls are
  // straight (T = 1: 158,149 against 161,200 bytes over the 25 maps of
  // ../shared/maps) and fitted within T cells of the wall cells rather than
  // one, as the cells themselves are (T = 3: 133,697 -> 120,172 bytes, with
  // the covering pass left out as ExtractWholeMapLayers says).
  const bool straight = options.straight_walls || options.tolerance_cells > 0;
  LineExtractionOptions line_options =
      straight ? StraightWalls(LineExtractionOptions{}) : FileWallOptions();
  line_options.method = options.method;
  line_options.epsilon_cells =
      std::max(options.epsilon_cells, static_cast<double>(options.tolerance_cells));
  // Not seeded from the robot's pose: a file's walls are the whole map's
  // (seeded, the walls of the other free spaces were left to the covering
  // pieces: on depot 889 walls at a DisPL_ave of 4.4 cm against 320 at 0.46).
  return ExtractLineSegments(grid, line_options);
}

LatticeSegment ToLattice(const LineSegment& line, int width, int height) {
  auto clamp = [](double v, int hi) {
    const double r = std::nearbyint(v);
    return static_cast<int>(std::clamp(r, 0.0, static_cast<double>(hi)));
  };
  return LatticeSegment{{clamp(line.x1, width - 1), clamp(line.y1, height - 1)},
                        {clamp(line.x2, width - 1), clamp(line.y2, height - 1)}};
}

namespace {

using layer_extraction_internal::EdgeCells;
using layer_extraction_internal::PointSegmentDistance;

bool NearOccupied(const Grid& grid, int c, int r) {
  for (int dr = -1; dr <= 1; ++dr) {
    for (int dc = -1; dc <= 1; ++dc) {
      if (grid.Contains(c + dc, r + dr) && grid.at(c + dc, r + dr) == Cell::kOccupied) return true;
    }
  }
  return false;
}

bool OnWalls(const Grid& grid, const LatticeSegment& s) {
  bool near = true;
  RasterizeSegment(s.a, s.b, [&](int c, int r) { near = near && NearOccupied(grid, c, r); });
  return near;
}

// A line rounded to the lattice can leave the wall where the extractor fit
// it across a gap or past a wall's end: each of its cells must stay within
// one cell of an occupied cell, so a line that does not is cut into the
// runs of its cells that do (a run whose own segment still leaves the wall,
// by the rounding of the shorter line, is dropped).
void AddOnWalls(const Grid& grid, const LatticeSegment& s, std::vector<LatticeSegment>* out) {
  if (OnWalls(grid, s)) {
    out->push_back(s);
    return;
  }
  std::vector<CellIndex> run;
  const auto flush = [&] {
    if (run.size() >= 2) {
      const LatticeSegment piece{run.front(), run.back()};
      if (OnWalls(grid, piece)) out->push_back(piece);
    }
    run.clear();
  };
  RasterizeSegment(s.a, s.b, [&](int c, int r) {
    if (NearOccupied(grid, c, r)) {
      run.push_back({c, r});
    } else {
      flush();
    }
  });
  flush();
}

// Ends of a slanted segment moved by at most one cell across its main axis
// where that makes it axis-aligned: the extractor fits its lines between a
// wall's faces and rounding tilts a straight wall by a cell or two; an
// axis-aligned step codes without the offset across (spec/format.md 5.2).
// Only when the moved segment stays on the walls, still holds every edge
// cell within one cell that it held, and is no more than kMoveSlack farther
// from any edge cell near it (eval's DisPL_ave barely moves). Measured on
// the 25 maps of ../shared/maps with DropRedundantSegments: WALL 42,305 ->
// 41,969 bytes, CELL 119,389 -> 119,221; edge cells within one cell of a
// wall 0.9443 -> 0.9444, DisPL_ave 1.1700 -> 1.1686 cells (means over the
// maps); a slack of one cell saved 2,100 more WALL bytes but cost 2,000
// CELL bytes and raised DisPL_ave 2 %.
constexpr double kMoveSlack = 0.5;  // cells

void StraightenSegments(const Grid& grid, EdgeCells* edges, std::vector<LatticeSegment>* segments) {
  for (LatticeSegment& s : *segments) {
    const int dc = s.b.col - s.a.col, dr = s.b.row - s.a.row;
    if (dc == 0 || dr == 0) continue;
    const bool col_main = std::abs(dc) >= std::abs(dr);
    const int minor = col_main ? dr : dc;
    if (std::abs(minor) > 2) continue;
    const std::vector<std::pair<std::size_t, double>> near = edges->Near(s);
    // Candidates: a and b each moved by up to one cell across the main axis.
    std::vector<LatticeSegment> cands;
    for (int ma = -1; ma <= 1; ++ma) {
      for (int mb = -1; mb <= 1; ++mb) {
        LatticeSegment t = s;
        if (col_main) {
          t.a.row += ma;
          t.b.row += mb;
          if (t.a.row != t.b.row) continue;
        } else {
          t.a.col += ma;
          t.b.col += mb;
          if (t.a.col != t.b.col) continue;
        }
        if (!grid.Contains(t.a.col, t.a.row) || !grid.Contains(t.b.col, t.b.row)) continue;
        cands.push_back(t);
      }
    }
    for (const LatticeSegment& t : cands) {
      if (!OnWalls(grid, t)) continue;
      bool ok = true;
      for (const auto& [c, d] : near) {
        const CellIndex p{static_cast<int>(c % grid.width()), static_cast<int>(c / grid.width())};
        const double nd = PointSegmentDistance(p, t.a, t.b);
        if ((d <= 1.0 && nd > 1.0) || nd > d + kMoveSlack) {
          ok = false;
          break;
        }
      }
      if (ok) {
        s = t;
        break;
      }
    }
  }
}

// An edge cell and a segment near it (EdgeCells::Near).
struct NearPair {
  std::size_t cell;
  std::size_t segment;
  double distance;
};

// Indices of `pairs` ordered by cell, then by index. The pairs come in
// index order, so a stable sort by cell gives that order: counting-sort
// passes over 12 bits of the cell at a time, on keys packed cell above
// index (on a 16-Mcell map there are millions of pairs, and a comparison
// sort of indices that reads the pairs took 3 % of the encode).
std::vector<std::size_t> PairsByCell(const std::vector<NearPair>& pairs) {
  std::vector<std::size_t> by_cell(pairs.size());
  std::size_t max_cell = 0;
  for (const NearPair& p : pairs) max_cell = std::max(max_cell, p.cell);
  if (pairs.size() > 0xffffffffu || max_cell > 0xffffffffu) {
    for (std::size_t k = 0; k < by_cell.size(); ++k) by_cell[k] = k;
    std::stable_sort(by_cell.begin(), by_cell.end(),
                     [&](std::size_t x, std::size_t y) { return pairs[x].cell < pairs[y].cell; });
    return by_cell;
  }
  std::vector<std::uint64_t> keys(pairs.size()), sorted(pairs.size());
  for (std::size_t k = 0; k < keys.size(); ++k) {
    keys[k] = (static_cast<std::uint64_t>(pairs[k].cell) << 32) | k;
  }
  constexpr int kDigitBits = 12;
  constexpr std::uint64_t kDigitMask = (1u << kDigitBits) - 1;
  for (int shift = 32; shift < 64 && (max_cell >> (shift - 32)) != 0; shift += kDigitBits) {
    std::vector<std::size_t> start(kDigitMask + 2, 0);
    for (const std::uint64_t key : keys) ++start[((key >> shift) & kDigitMask) + 1];
    for (std::size_t d = 1; d < start.size(); ++d) start[d] += start[d - 1];
    for (const std::uint64_t key : keys) sorted[start[(key >> shift) & kDigitMask]++] = key;
    keys.swap(sorted);
  }
  for (std::size_t k = 0; k < keys.size(); ++k) by_cell[k] = keys[k] & 0xffffffffu;
  return by_cell;
}

}  // namespace

namespace layer_extraction_internal {

// Drops, fewest near edge cells first, each segment such that every edge
// cell near it has another kept segment no more than kMoveSlack farther
// than the nearest of all the segments was (and within one cell when that
// one was): a broken, doubled or overlapping wall piece costs some 20 bits
// in WALL and adds little to what eval measures. Measured with
// StraightenSegments (above); dropping every segment whose edge cells
// within one cell others hold saved 3,200 WALL bytes but cost 750 CELL
// bytes and doubled DisPL_ave on some maps (nav2/depot 0.13 -> 0.29).
void DropRedundantSegments(EdgeCells* edges, std::vector<LatticeSegment>* segments) {
  // Every (edge cell, segment near it) pair, grouped by cell: flat arrays,
  // not hash maps, since a large map has millions of pairs.
  std::vector<NearPair> pairs;
  std::vector<std::size_t> first(segments->size() + 1,
                                 0);  // segment i: pairs [first[i], first[i+1])
  for (std::size_t i = 0; i < segments->size(); ++i) {
    for (const auto& [c, d] : edges->Near((*segments)[i])) pairs.push_back({c, i, d});
    first[i + 1] = pairs.size();
  }
  std::vector<std::size_t> by_cell = PairsByCell(pairs);
  // For each pair, its cell's run in by_cell and the nearest distance of
  // all the segments to that cell.
  std::vector<std::size_t> run_begin(pairs.size()), run_end(pairs.size());
  std::vector<double> nearest(pairs.size());
  for (std::size_t b = 0; b < by_cell.size();) {
    std::size_t e = b;
    double best = pairs[by_cell[b]].distance;
    while (e < by_cell.size() && pairs[by_cell[e]].cell == pairs[by_cell[b]].cell) {
      best = std::min(best, pairs[by_cell[e]].distance);
      ++e;
    }
    for (std::size_t k = b; k < e; ++k) {
      run_begin[by_cell[k]] = b;
      run_end[by_cell[k]] = e;
      nearest[by_cell[k]] = best;
    }
    b = e;
  }
  std::vector<std::size_t> order(segments->size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return first[a + 1] - first[a] < first[b + 1] - first[b];
  });
  std::vector<bool> keep(segments->size(), true);
  for (std::size_t i : order) {
    bool redundant = true;
    for (std::size_t k = first[i]; k < first[i + 1] && redundant; ++k) {
      // Against the nearest distance of the start, not the kept ones', so
      // that drops do not add up their slack.
      const double best = nearest[k];
      const double limit = best <= 1.0 ? std::min(1.0, best + kMoveSlack) : best + kMoveSlack;
      redundant = false;
      for (std::size_t q = run_begin[k]; q < run_end[k] && !redundant; ++q) {
        const NearPair& other = pairs[by_cell[q]];
        redundant = other.segment != i && keep[other.segment] && other.distance <= limit;
      }
    }
    if (redundant) keep[i] = false;
  }
  std::vector<LatticeSegment> kept;
  for (std::size_t i = 0; i < segments->size(); ++i) {
    if (keep[i]) kept.push_back((*segments)[i]);
  }
  *segments = std::move(kept);
}

StatusOr<std::vector<LatticeSegment>> WallSegments(const Grid& grid, const EncodeOptions& options) {
  LINEMAP_ASSIGN_OR_RETURN(std::vector<LineSegment> lines, ExtractWallLines(grid, options));
  std::vector<LatticeSegment> segments;
  segments.reserve(lines.size());
  for (const LineSegment& line : lines) {
    AddOnWalls(grid, ToLattice(line, grid.width(), grid.height()), &segments);
  }
  EdgeCells edges(grid);
  StraightenSegments(grid, &edges, &segments);
  return segments;
}

}  // namespace layer_extraction_internal
}  // namespace linemap
