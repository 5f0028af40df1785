// RM-Line (Liu & Zhang, Appl. Sci. 2022, 12, 9754), implemented as written:
//   2.2 screening model -> active points,
//   2.3 ray model -> best ray pair -> cluster -> least-squares line (Eq. 1-4),
//   2.4 raster scan, locking the active points of every cluster.
//
// Parameters the paper leaves open (it gives no values):
//   dtheta (degrees, default 1): the angular step of the rays. A ray whose
//     angle is off the wall's by at most dtheta/2 stays within half a cell of
//     a one-cell-thick contour for 0.5 / tan(dtheta/2) cells, i.e. 57 cells
//     (2.9 m at 5 cm) for 1 degree; axis-aligned and 45-degree walls are hit
//     exactly because 1 divides 45. Cost grows as 180/dtheta rays per start.
//   ds (cells, default 0.5): the spacing of the scoring points. Half a cell
//     samples every cell a ray crosses along the axes and at 45 degrees, so a
//     one-cell gap always stops the ray; larger steps could jump gaps.
// Eq. (1)-(2) score a ray by counting its scoring points on OBSTACLE cells
// before the first other one (the stop-point). The paper's input to the
// screening and ray models is the edge map (Figures 3a and 4b), so OBSTACLE
// here means "edge point": interior obstacle cells are not followed.
#include "codec/lines/rmline.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "codec/lines/line_fit.h"
#include "format/large_vector.h"

namespace linemap::lines_internal {
namespace {

// The per-direction steps of the rays, computed once per extraction.
struct RayTable {
  std::vector<double> step_col;  // ds * cos(n * dtheta)
  std::vector<double> step_row;  // ds * sin(n * dtheta)
};

RayTable MakeRayTable(double dtheta_deg, double ds_cells) {
  RayTable table;
  const int last = static_cast<int>(std::floor(180.0 / dtheta_deg + 1e-9));
  for (int n = 0; n <= last; ++n) {
    const double theta = n * dtheta_deg * std::numbers::pi / 180.0;
    table.step_col.push_back(ds_cells * std::cos(theta));
    table.step_row.push_back(ds_cells * std::sin(theta));
  }
  return table;
}

bool IsEdge(const EdgeMap& edges, int col, int row) {
  return col >= 0 && row >= 0 && col < edges.width && row < edges.height &&
         edges.is_edge[static_cast<std::size_t>(row) * edges.width + col] != 0;
}

// The cell holding a scoring point: the nearest cell centre (a point exactly
// on a cell border, e.g. x = 2.5 with ds = 0.5, goes to the higher cell).
int CellOf(double coordinate) { return static_cast<int>(std::floor(coordinate + 0.5)); }

// Number of scoring points k = 0, 1, ... on edge points before the
// stop-point, from (col, row) with the given step.
int ScoreRay(const EdgeMap& edges, int col, int row, double step_col, double step_row) {
  int score = 0;
  for (int k = 0;; ++k) {
    if (!IsEdge(edges, CellOf(col + k * step_col), CellOf(row + k * step_row))) return score;
    ++score;
  }
}

void AppendRayCells(const EdgeMap& edges, int col, int row, double step_col, double step_row,
                    int points, std::vector<std::uint32_t>* cells) {
  for (int k = 0; k < points; ++k) {
    const int c = CellOf(col + k * step_col);
    const int r = CellOf(row + k * step_row);
    const auto index = static_cast<std::uint32_t>(r * edges.width + c);
    if (cells->empty() || cells->back() != index) cells->push_back(index);
  }
}

RayPair BestRayPair(const EdgeMap& edges, const RayTable& table, int col, int row) {
  RayPair best;
  best.score = -1;
  int best_forward = 0, best_backward = 0;
  for (std::size_t n = 0; n < table.step_col.size(); ++n) {
    const int forward = ScoreRay(edges, col, row, table.step_col[n], table.step_row[n]);
    const int backward = ScoreRay(edges, col, row, -table.step_col[n], -table.step_row[n]);
    if (forward + backward > best.score) {
      best.score = forward + backward;
      best.direction_index = static_cast<int>(n);
      best_forward = forward;
      best_backward = backward;
    }
  }
  const std::size_t n = static_cast<std::size_t>(best.direction_index);
  AppendRayCells(edges, col, row, table.step_col[n], table.step_row[n], best_forward, &best.cells);
  AppendRayCells(edges, col, row, -table.step_col[n], -table.step_row[n], best_backward,
                 &best.cells);
  std::sort(best.cells.begin(), best.cells.end());
  best.cells.erase(std::unique(best.cells.begin(), best.cells.end()), best.cells.end());
  return best;
}

// Eq. (3)-(4): the least-squares line through the cluster's cell centres,
// cut at the projections of its extreme cells.
LineSegment FitCluster(const std::vector<std::uint32_t>& cells, int width, std::vector<double>* xs,
                       std::vector<double>* ys) {
  PointMoments moments;
  xs->clear();
  ys->clear();
  for (std::uint32_t index : cells) {
    const double x = static_cast<double>(index % static_cast<std::uint32_t>(width));
    const double y = static_cast<double>(index / static_cast<std::uint32_t>(width));
    moments.Add(x, y);
    xs->push_back(x);
    ys->push_back(y);
  }
  return SegmentFromProjections(moments.Fit(), xs->data(), ys->data(), xs->size());
}

}  // namespace

const std::array<CellOffset, 8>& ScreeningNeighbours() {
  static const std::array<CellOffset, 8> kNeighbours = {
      {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}}};
  return kNeighbours;
}

std::array<CellOffset, 3> TailPoints(const CellOffset& neighbour) {
  const std::array<CellOffset, 8>& ring = ScreeningNeighbours();
  int i = 0;
  while (i < 8 && !(ring[i] == neighbour)) ++i;
  std::array<CellOffset, 3> tails;
  for (int j = 0; j < 3; ++j) {
    const CellOffset& turned = ring[(i + 7 + j) % 8];  // d turned by (j - 1) * 45 degrees
    tails[j] = {neighbour.dcol + turned.dcol, neighbour.drow + turned.drow};
  }
  return tails;
}

std::vector<std::uint8_t> ScreenActivePoints(const EdgeMap& edges) {
  std::array<std::array<CellOffset, 3>, 8> tails;
  for (int i = 0; i < 8; ++i) tails[i] = TailPoints(ScreeningNeighbours()[i]);
  std::vector<std::uint8_t> active = LargeVector<std::uint8_t>(edges.is_edge.size(), 0);
  for (int row = 0; row < edges.height; ++row) {
    for (int col = 0; col < edges.width; ++col) {
      if (!IsEdge(edges, col, row)) continue;
      for (int i = 0; i < 8; ++i) {
        const CellOffset& p = ScreeningNeighbours()[i];
        if (!IsEdge(edges, col + p.dcol, row + p.drow)) continue;
        bool tail_is_edge = false;
        for (const CellOffset& t : tails[i]) {
          tail_is_edge = tail_is_edge || IsEdge(edges, col + t.dcol, row + t.drow);
        }
        if (tail_is_edge) {
          active[static_cast<std::size_t>(row) * edges.width + col] = 1;
          break;
        }
      }
    }
  }
  return active;
}

RayPair CastBestRayPair(const EdgeMap& edges, int col, int row, double dtheta_deg,
                        double ds_cells) {
  return BestRayPair(edges, MakeRayTable(dtheta_deg, ds_cells), col, row);
}

StatusOr<std::vector<LineSegment>> ExtractRmLine(const EdgeMap& edges, double dtheta_deg,
                                                 double ds_cells) {
  if (!(dtheta_deg > 0 && dtheta_deg <= 180)) {
    return InvalidArgumentError("RM-Line dtheta must be in (0, 180] degrees");
  }
  if (!(ds_cells > 0 && ds_cells <= 1)) {
    return InvalidArgumentError("RM-Line ds must be in (0, 1] cells");
  }
  const RayTable table = MakeRayTable(dtheta_deg, ds_cells);
  std::vector<std::uint8_t> free_active = ScreenActivePoints(edges);  // 1 = active, not locked
  std::vector<LineSegment> segments;
  std::vector<double> xs, ys;
  for (int row = 0; row < edges.height; ++row) {
    for (int col = 0; col < edges.width; ++col) {
      if (!free_active[static_cast<std::size_t>(row) * edges.width + col]) continue;
      const RayPair pair = BestRayPair(edges, table, col, row);
      for (std::uint32_t index : pair.cells) free_active[index] = 0;  // step (7): lock
      // A cluster of one cell has no direction; it yields no segment.
      if (pair.cells.size() >= 2) segments.push_back(FitCluster(pair.cells, edges.width, &xs, &ys));
    }
  }
  return segments;
}

}  // namespace linemap::lines_internal
