// Steps 2 and 3 of linemap's extractor (see linemap_extractor.cc): the edge
// cells are traced into ordered 8-connected chains, and each chain is split
// into the longest pieces that stay within split_epsilon_cells of their
// total-least-squares lines.
#ifndef LINEMAP_CODEC_LINES_EDGE_CHAINS_H_
#define LINEMAP_CODEC_LINES_EDGE_CHAINS_H_

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "codec/lines/edge_cells.h"
#include "codec/lines/line_fit.h"
#include "linemap/lines.h"

namespace linemap::lines_internal {

// Orders the edge cells flagged in `include` (width*height; 1 = take) into
// chains: each cell is 8-adjacent to the next. Every included cell is in
// exactly one chain. Chains start at contour ends where there are any.
std::vector<std::vector<std::uint32_t>> TraceEdgeChains(const EdgeMap& edges,
                                                        const std::vector<std::uint8_t>& include);

// Splits a chain into consecutive pieces, each within epsilon (cells) of its
// own total-least-squares line: greedy longest piece first, found by
// doubling then bisection. Returns the piece lengths in chain order.
std::vector<int> SplitChain(const std::vector<std::uint32_t>& chain, int width,
                            double epsilon_cells);

// Moments of chain prefixes: the fit of any sub-range in O(1).
class ChainMoments {
 public:
  ChainMoments() = default;
  ChainMoments(std::span<const std::uint32_t> chain, int width) { Assign(chain, width); }

  // The moments of `chain` (reusing this object's buffers).
  void Assign(std::span<const std::uint32_t> chain, int width) {
    const std::size_t n = chain.size();
    x_.resize(n);
    y_.resize(n);
    s_.assign(n + 1, {0, 0, 0, 0, 0});
    const CellXY origin = n > 0 ? CellOfIndex(chain[0], width) : CellXY{0, 0};
    ox_ = origin.col;
    oy_ = origin.row;
    for (std::size_t i = 0; i < n; ++i) {
      const CellXY c = CellOfIndex(chain[i], width);
      x_[i] = c.col;
      y_[i] = c.row;
      const double dx = c.col - ox_, dy = c.row - oy_;
      s_[i + 1] = {s_[i][0] + dx, s_[i][1] + dy, s_[i][2] + dx * dx, s_[i][3] + dx * dy,
                   s_[i][4] + dy * dy};
    }
  }

  int size() const { return static_cast<int>(x_.size()); }
  // Cell i of the chain (held as it was assigned: no division).
  CellXY Cell(int i) const { return {static_cast<int>(x_[i]), static_cast<int>(y_[i])}; }

  // TLS line of cells [begin, end).
  FittedLine Fit(int begin, int end) const {
    const double n = end - begin;
    const double sx = s_[end][0] - s_[begin][0], sy = s_[end][1] - s_[begin][1];
    const double mx = sx / n, my = sy / n;
    Eigen::Matrix2d cov;
    cov(0, 0) = std::max(0.0, (s_[end][2] - s_[begin][2]) / n - mx * mx);
    cov(1, 1) = std::max(0.0, (s_[end][4] - s_[begin][4]) / n - my * my);
    cov(0, 1) = cov(1, 0) = (s_[end][3] - s_[begin][3]) / n - mx * my;
    return FitFromCovariance({ox_ + mx, oy_ + my}, cov);
  }

  // Distance of cell i to the TLS line of the window of 2 * half + 1 chain
  // cells around it (shifted to stay inside the chain): the chain's local
  // noise at i, which a straight wall's digitisation keeps near 0.25 cells.
  double LocalResidual(int i, int half) const {
    const int n = static_cast<int>(x_.size());
    const int size = std::min(n, 2 * half + 1);
    const int begin = std::clamp(i - half, 0, n - size);
    if (size <= 2 || Monotone(begin, begin + size)) return 0;
    const FittedLine line = Fit(begin, begin + size);
    return std::abs((x_[i] - line.centroid.x()) * -line.direction.y() +
                    (y_[i] - line.centroid.y()) * line.direction.x());
  }

  // True when cells [begin, end) never turn back along either axis: a
  // staircase (a digitised straight wall or curve) has no noise to forgive,
  // a wall ragged by +-1 cell goes up and down.
  bool Monotone(int begin, int end) const {
    int sign_x = 0, sign_y = 0;
    for (int k = begin + 1; k < end; ++k) {
      const int dx = (x_[k] > x_[k - 1]) - (x_[k] < x_[k - 1]);
      const int dy = (y_[k] > y_[k - 1]) - (y_[k] < y_[k - 1]);
      if ((dx && sign_x && dx != sign_x) || (dy && sign_y && dy != sign_y)) return false;
      if (dx) sign_x = dx;
      if (dy) sign_y = dy;
    }
    return true;
  }

  // True when every cell of [begin, end) is within epsilon of its TLS line.
  bool Valid(int begin, int end, double epsilon) const {
    if (end - begin <= 2) return true;
    const FittedLine line = Fit(begin, end);
    if (line.mean_squared_residual > epsilon * epsilon) return false;
    const double nx = -line.direction.y(), ny = line.direction.x();
    for (int i = begin; i < end; ++i) {
      const double d = (x_[i] - line.centroid.x()) * nx + (y_[i] - line.centroid.y()) * ny;
      if (std::abs(d) > epsilon) return false;
    }
    return true;
  }

 private:
  std::vector<double> x_, y_;
  std::vector<std::array<double, 5>> s_;
  double ox_ = 0, oy_ = 0;
};

// Chains stored end to end: chain k is cells[begin[k], begin[k + 1]) (one
// array rather than a vector per chain).
struct FlatChains {
  std::vector<std::uint32_t> cells;
  std::vector<std::size_t> begin = {0};
  std::size_t size() const { return begin.size() - 1; }
  std::span<const std::uint32_t> operator[](std::size_t k) const {
    return std::span<const std::uint32_t>(cells).subspan(begin[k], begin[k + 1] - begin[k]);
  }
};

// TraceEdgeChains over the cells of `cells` (raster order) whose `open` flag
// is set; clears the flags as it goes.
FlatChains TraceChains(const EdgeMap& edges, const std::vector<std::uint32_t>& cells,
                       std::vector<std::uint8_t>& open);

// SplitChain over the chain of `moments`, into *pieces (cleared first).
void SplitChainMoments(const ChainMoments& moments, double epsilon_cells,
                       std::vector<int>* pieces_out);

}  // namespace linemap::lines_internal

#endif  // LINEMAP_CODEC_LINES_EDGE_CHAINS_H_
