#include "codec/layers/wall_cover.h"

#include <algorithm>
#include <cstddef>

#include "codec/layers/raster.h"
#include "codec/lines/line_fit.h"
#include "codec/lines/segment_index.h"
#include "codec/segment/byte_scan.h"
#include "linemap/lines.h"

namespace linemap {
namespace {

// Eval's test: within one cell, Euclidean, of the segment.
constexpr double kNear = 1.0;

LineSegment AsLine(CellIndex a, CellIndex b) {
  return {static_cast<double>(a.col), static_cast<double>(a.row), static_cast<double>(b.col),
          static_cast<double>(b.row)};
}

std::int64_t SquaredDistance(CellIndex a, CellIndex b) {
  const std::int64_t dc = a.col - b.col, dr = a.row - b.row;
  return dc * dc + dr * dr;
}

// The cell of `cells` farthest from `from` (the first on a tie).
CellIndex Farthest(const std::vector<CellIndex>& cells, CellIndex from) {
  CellIndex best = cells[0];
  for (const CellIndex& c : cells) {
    if (SquaredDistance(c, from) > SquaredDistance(best, from)) best = c;
  }
  return best;
}

// Every cell the segment is drawn over has an occupied cell among its
// 8-neighbours or is one: the piece stays on the obstacle it covers.
bool OnObstacles(const Grid& grid, CellIndex a, CellIndex b) {
  bool on = true;
  RasterizeSegment(a, b, [&](int c, int r) {
    if (!on) return;
    bool near = false;
    for (int dr = -1; dr <= 1 && !near; ++dr) {
      for (int dc = -1; dc <= 1 && !near; ++dc) {
        near = grid.Contains(c + dc, r + dr) && grid.at(c + dc, r + dr) == Cell::kOccupied;
      }
    }
    on = on && near;
  });
  return on;
}

// A one-cell segment on a lone cell: to a neighbour inside the grid (a
// wall needs two distinct points; the cell lies on it).
LatticeSegment Stub(const Grid& grid, CellIndex p) {
  for (const CellIndex d : {CellIndex{1, 0}, CellIndex{-1, 0}, CellIndex{0, 1}, CellIndex{0, -1}}) {
    const CellIndex q{p.col + d.col, p.row + d.row};
    if (grid.Contains(q.col, q.row)) return {p, q};
  }
  return {p, p};  // a 1 x 1 grid: nothing to draw a wall in
}

// Segments covering `cells` (a cluster, or part of one): the chord between
// its two farthest cells when that holds them all within kNear and stays on
// obstacles, else the two halves along the chord, each covered alike.
void Cover(const Grid& grid, std::vector<CellIndex> cells, std::vector<LatticeSegment>* out) {
  if (cells.size() == 1) {
    const LatticeSegment stub = Stub(grid, cells[0]);
    if (!(stub.a == stub.b)) out->push_back(stub);
    return;
  }
  const CellIndex a = Farthest(cells, cells[0]);
  const CellIndex b = Farthest(cells, a);
  const LineSegment chord = AsLine(a, b);
  bool holds = true;
  for (std::size_t i = 0; i < cells.size() && holds; ++i) {
    holds = lines_internal::PointSegmentDistance(cells[i].col, cells[i].row, chord) <= kNear;
  }
  holds = holds && OnObstacles(grid, a, b);
  if (holds) {
    out->push_back({a, b});
    return;
  }
  // Halves by the position along the chord (ties by the cells' order, so
  // that each half is non-empty).
  const std::int64_t dc = b.col - a.col, dr = b.row - a.row;
  std::vector<std::pair<std::int64_t, std::size_t>> along(cells.size());
  for (std::size_t i = 0; i < cells.size(); ++i) {
    along[i] = {(cells[i].col - a.col) * dc + (cells[i].row - a.row) * dr, i};
  }
  std::sort(along.begin(), along.end());
  const std::size_t half = cells.size() / 2;
  std::vector<CellIndex> first, second;
  for (std::size_t k = 0; k < along.size(); ++k) {
    (k < half ? first : second).push_back(cells[along[k].second]);
  }
  Cover(grid, std::move(first), out);
  Cover(grid, std::move(second), out);
}

// The 8-connected clusters of the marked cells, each in breadth-first
// order from its first cell in grid-row order.
std::vector<std::vector<CellIndex>> Clusters(const Grid& grid, std::vector<std::uint8_t> marked) {
  std::vector<std::vector<CellIndex>> clusters;
  const int w = grid.width();
  for (int r = 0; r < grid.height(); ++r) {
    const std::uint8_t* marked_row = marked.data() + grid.Index(0, r);
    for (int c = FirstNonZeroByte(marked_row, 0, w); c < w;
         c = FirstNonZeroByte(marked_row, c + 1, w)) {
      std::vector<CellIndex> cluster{{c, r}};
      marked[grid.Index(c, r)] = 0;
      for (std::size_t k = 0; k < cluster.size(); ++k) {
        const CellIndex p = cluster[k];
        for (int dr = -1; dr <= 1; ++dr) {
          for (int dc = -1; dc <= 1; ++dc) {
            const int x = p.col + dc, y = p.row + dr;
            if (!grid.Contains(x, y) || !marked[grid.Index(x, y)]) continue;
            marked[grid.Index(x, y)] = 0;
            cluster.push_back({x, y});
          }
        }
      }
      clusters.push_back(std::move(cluster));
    }
  }
  return clusters;
}

}  // namespace

std::vector<LatticeSegment> CoveringSegments(const Grid& grid,
                                             const std::vector<LatticeSegment>& walls,
                                             const std::vector<std::uint8_t>* covered) {
  return CoveringSegments(grid, walls, covered, ComputeEdgeMap(grid).is_edge.data());
}

std::vector<LatticeSegment> CoveringSegments(const Grid& grid,
                                             const std::vector<LatticeSegment>& walls,
                                             const std::vector<std::uint8_t>* covered,
                                             const std::uint8_t* edge) {
  std::vector<LineSegment> lines;
  lines.reserve(walls.size());
  for (const LatticeSegment& s : walls) lines.push_back(AsLine(s.a, s.b));
  lines_internal::SegmentIndex index(&lines, grid.width(), grid.height());
  std::vector<std::uint8_t> left_out(grid.size(), 0);
  bool any = false;
  const int w = grid.width();
  for (int r = 0; r < grid.height(); ++r) {
    // Edge cells are a few in a hundred: skipped to eight bytes at a time.
    const std::uint8_t* edge_row = edge + grid.Index(0, r);
    for (int c = FirstNonZeroByte(edge_row, 0, w); c < w;
         c = FirstNonZeroByte(edge_row, c + 1, w)) {
      const std::size_t i = grid.Index(c, r);
      if (covered != nullptr && (*covered)[i]) continue;
      if (!lines.empty() && index.AnyWithin(c, r, kNear)) continue;
      left_out[i] = 1;
      any = true;
    }
  }
  std::vector<LatticeSegment> out;
  if (!any) return out;
  for (std::vector<CellIndex>& cluster : Clusters(grid, std::move(left_out))) {
    Cover(grid, std::move(cluster), &out);
  }
  return out;
}

}  // namespace linemap
