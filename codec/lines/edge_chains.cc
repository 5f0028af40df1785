// Steps 2 and 3 of linemap's extractor: chains (traced as in EDLines'
// edge linking) and their split into pieces (see linemap_extractor.cc).
#include "codec/lines/edge_chains.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace linemap::lines_internal {
namespace {

// Angle between two of the 8 directions of kDcol/kDrow, in 45-degree steps (0..4).
int TurnSteps(int a, int b) {
  // Each direction's angle from +x in 45-degree steps (counter-clockwise in
  // (col, row)).
  constexpr int kOctant[8] = {0, 2, 4, 6, 1, 3, 5, 7};
  const int diff = (kOctant[a] - kOctant[b] + 8) % 8;
  return std::min(diff, 8 - diff);
}

}  // namespace

FlatChains TraceChains(const EdgeMap& edges, const std::vector<std::uint32_t>& cells,
                       std::vector<std::uint8_t>& open) {
  const int width = edges.width, height = edges.height;
  // Away from the map's sides a cell's 8 neighbours are read without
  // bounds tests (the tracing was 2 % of an encode): offset[k] is
  // neighbour k's index offset.
  const auto inside = [&](int col, int row) {
    return col > 0 && row > 0 && col + 1 < width && row + 1 < height;
  };
  std::ptrdiff_t offset[8];
  for (int k = 0; k < 8; ++k) offset[k] = static_cast<std::ptrdiff_t>(kDrow[k]) * width + kDcol[k];
  auto untraced_neighbours = [&](int col, int row) {
    int count = 0;
    if (inside(col, row)) {
      const std::uint8_t* p = open.data() + (static_cast<std::size_t>(row) * width + col);
      for (int k = 0; k < 8; ++k) count += p[offset[k]] != 0;
      return count;
    }
    for (int k = 0; k < 8; ++k) {
      const int c = col + kDcol[k], r = row + kDrow[k];
      if (c >= 0 && r >= 0 && c < width && r < height &&
          open[static_cast<std::size_t>(r) * width + c]) {
        ++count;
      }
    }
    return count;
  };
  // Extends `chain` from its last cell until no untraced neighbour is left,
  // going straight on where possible (so that the two sides of a two-cell
  // wall become two chains rather than one zig-zag), then turning as little
  // as possible; ties go to the neighbour with fewer untraced neighbours.
  auto walk = [&](std::vector<std::uint32_t>* chain) {
    int heading = -1;  // direction of the last step, index into kDcol/kDrow
    if (chain->size() >= 2) {
      const CellXY a = CellOfIndex((*chain)[chain->size() - 2], width);
      const CellXY b = CellOfIndex(chain->back(), width);
      for (int k = 0; k < 8; ++k) {
        if (a.col + kDcol[k] == b.col && a.row + kDrow[k] == b.row) heading = k;
      }
    }
    for (;;) {
      const CellXY c = CellOfIndex(chain->back(), width);
      const bool all_inside = inside(c.col, c.row);
      int best = -1, best_k = -1, best_score = 1 << 30;
      for (int k = 0; k < 8; ++k) {
        const int col = c.col + kDcol[k], row = c.row + kDrow[k];
        if (!all_inside && (col < 0 || row < 0 || col >= width || row >= height)) continue;
        if (!open[static_cast<std::size_t>(row) * width + col]) continue;
        const int turn = heading < 0 ? 0 : TurnSteps(heading, k);
        const int score = 32 * turn + 2 * untraced_neighbours(col, row) + (k >= 4 ? 1 : 0);
        if (score < best_score) {
          best_score = score;
          best = row * width + col;
          best_k = k;
        }
      }
      if (best < 0) return;
      open[best] = 0;
      chain->push_back(static_cast<std::uint32_t>(best));
      heading = best_k;
    }
  };
  FlatChains chains;
  chains.cells.reserve(cells.size());
  std::vector<std::uint32_t> chain;  // the chain being traced (reused)
  auto trace_from = [&](std::size_t seed) {
    chain.assign(1, static_cast<std::uint32_t>(seed));
    open[seed] = 0;
    walk(&chain);
    std::reverse(chain.begin(), chain.end());
    walk(&chain);  // the other way from the seed
    chains.cells.insert(chains.cells.end(), chain.begin(), chain.end());
    chains.begin.push_back(chains.cells.size());
  };
  // Contour ends first, then whatever is left (closed contours).
  for (int pass = 0; pass < 2; ++pass) {
    for (std::uint32_t i : cells) {
      if (!open[i]) continue;
      const CellXY c = CellOfIndex(i, width);
      if (pass == 0 && untraced_neighbours(c.col, c.row) > 1) continue;
      trace_from(i);
    }
  }
  return chains;
}

std::vector<std::vector<std::uint32_t>> TraceEdgeChains(const EdgeMap& edges,
                                                        const std::vector<std::uint8_t>& include) {
  std::vector<std::uint8_t> open = include;
  std::vector<std::uint32_t> cells;
  for (std::size_t i = 0; i < include.size(); ++i) {
    if (include[i]) cells.push_back(static_cast<std::uint32_t>(i));
  }
  const FlatChains flat = TraceChains(edges, cells, open);
  std::vector<std::vector<std::uint32_t>> chains;
  for (std::size_t k = 0; k < flat.size(); ++k) chains.emplace_back(flat[k].begin(), flat[k].end());
  return chains;
}

void SplitChainMoments(const ChainMoments& moments, double epsilon_cells,
                       std::vector<int>* pieces_out) {
  const int n = moments.size();
  std::vector<int>& pieces = *pieces_out;
  pieces.clear();
  for (int begin = 0; begin < n;) {
    int good = std::min(2, n - begin);
    int bad = -1;
    while (good < n - begin) {
      const int trial = std::min(2 * good, n - begin);
      if (moments.Valid(begin, begin + trial, epsilon_cells)) {
        good = trial;
      } else {
        bad = trial;
        break;
      }
    }
    while (bad > 0 && bad - good > 1) {
      const int mid = (good + bad) / 2;
      (moments.Valid(begin, begin + mid, epsilon_cells) ? good : bad) = mid;
    }
    pieces.push_back(good);
    begin += good;
  }
}

std::vector<int> SplitChain(const std::vector<std::uint32_t>& chain, int width,
                            double epsilon_cells) {
  std::vector<int> pieces;
  SplitChainMoments(ChainMoments(chain, width), epsilon_cells, &pieces);
  return pieces;
}

}  // namespace linemap::lines_internal
