// Edge map by connected domain: Liu & Zhang, "RM-Line", Appl. Sci. 2022, 12,
// 9754, section 2.1 (Figure 1).
//
// The paper's AuxMap holds 0 (not reached), 1 (free cell of the connected
// domain) and 2 (edge point: an obstacle cell 4-adjacent to the domain). Its
// OpenArray is the explicit queue below, so the flood is linear in the number
// of cells and needs no recursion (a 4000 x 4000 map cannot overflow a stack).
#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

#include "format/large_vector.h"
#include "linemap/grid.h"
#include "linemap/lines.h"

namespace linemap {
namespace {

enum AuxValue : std::uint8_t { kNotReached = 0, kDomain = 1, kEdgePoint = 2 };

// Floods the free cells 4-connected to `seed` (a free cell), marking the
// domain and its obstacle neighbours in `aux`. `open` is reused scratch space.
void FloodConnectedDomain(const Grid& grid, std::size_t seed, std::vector<std::uint8_t>* aux,
                          std::vector<std::uint32_t>* open) {
  const int width = grid.width();
  const int height = grid.height();
  const std::vector<Cell>& cells = grid.cells();
  open->clear();
  open->push_back(static_cast<std::uint32_t>(seed));
  (*aux)[seed] = kDomain;
  for (std::size_t head = 0; head < open->size(); ++head) {
    const std::uint32_t index = (*open)[head];
    const int col = static_cast<int>(index % static_cast<std::uint32_t>(width));
    const int row = static_cast<int>(index / static_cast<std::uint32_t>(width));
    // The paper's p_i0..p_i3: (x+1,y), (x-1,y), (x,y+1), (x,y-1).
    const int neighbour_cols[4] = {col + 1, col - 1, col, col};
    const int neighbour_rows[4] = {row, row, row + 1, row - 1};
    for (int k = 0; k < 4; ++k) {
      const int ncol = neighbour_cols[k];
      const int nrow = neighbour_rows[k];
      if (ncol < 0 || nrow < 0 || ncol >= width || nrow >= height) continue;
      const std::size_t neighbour = grid.Index(ncol, nrow);
      if (cells[neighbour] == Cell::kFree && (*aux)[neighbour] == kNotReached) {
        (*aux)[neighbour] = kDomain;
        open->push_back(static_cast<std::uint32_t>(neighbour));
      } else if (cells[neighbour] == Cell::kOccupied) {
        (*aux)[neighbour] = kEdgePoint;
      }
    }
  }
}

// The obstacle cells with a free 4-neighbour, straight into `is_edge`
// (sized to the grid) with their count: one pass over the rows through
// plain pointers, the columns off the map's sides tested apart so that the
// loop over the others has no branch (most cells decide nothing).
std::size_t MarkObstaclesNextToFree(const Grid& grid, std::vector<std::uint8_t>* is_edge) {
  const int w = grid.width(), h = grid.height();
  if (w == 0 || h == 0) return 0;
  const std::vector<Cell> outside(static_cast<std::size_t>(w), Cell::kUnknown);  // never free
  std::size_t count = 0;
  for (int r = 0; r < h; ++r) {
    const Cell* row = grid.cells().data() + grid.Index(0, r);
    const Cell* up = r > 0 ? row - w : outside.data();
    const Cell* down = r + 1 < h ? row + w : outside.data();
    std::uint8_t* out = is_edge->data() + grid.Index(0, r);
    const auto edge = [&](int c, bool left_free, bool right_free) {
      const bool free_beside =
          left_free | right_free | (up[c] == Cell::kFree) | (down[c] == Cell::kFree);
      return static_cast<std::uint8_t>((row[c] == Cell::kOccupied) & free_beside);
    };
    std::size_t row_count = 0;
    for (int c = 1; c + 1 < w; ++c) {
      out[c] = edge(c, row[c - 1] == Cell::kFree, row[c + 1] == Cell::kFree);
      row_count += out[c];
    }
    out[0] = edge(0, false, w > 1 && row[1] == Cell::kFree);
    if (w > 1) out[w - 1] = edge(w - 1, row[w - 2] == Cell::kFree, false);
    count += row_count + out[0] + (w > 1 ? out[w - 1] : 0);
  }
  return count;
}

}  // namespace

EdgeMap ComputeEdgeMap(const Grid& grid, std::optional<CellPoint> robot) {
  EdgeMap edges;
  edges.width = grid.width();
  edges.height = grid.height();
  if (!robot) {
    // Flooding every free component marks exactly the obstacle cells with a
    // free 4-neighbour, so one direct pass gives the same AuxMap edge points.
    AssignLarge<std::uint8_t>(&edges.is_edge, grid.size(), 0);
    edges.edge_count = MarkObstaclesNextToFree(grid, &edges.is_edge);
    return edges;
  }
  std::vector<std::uint8_t> aux = LargeVector<std::uint8_t>(grid.size(), kNotReached);
  std::vector<std::uint32_t> open;
  // The robot's cell; a position off the map or not on a free cell floods
  // nothing (ExtractLines reports that case as an error).
  const double col = std::floor(robot->col + 0.5);
  const double row = std::floor(robot->row + 0.5);
  if (col >= 0 && row >= 0 && col < grid.width() && row < grid.height()) {
    const std::size_t seed = grid.Index(static_cast<int>(col), static_cast<int>(row));
    if (grid.cells()[seed] == Cell::kFree) FloodConnectedDomain(grid, seed, &aux, &open);
  }
  AssignLarge<std::uint8_t>(&edges.is_edge, grid.size(), 0);
  for (std::size_t i = 0; i < aux.size(); ++i) {
    if (aux[i] == kEdgePoint) {
      edges.is_edge[i] = 1;
      ++edges.edge_count;
    }
  }
  return edges;
}

}  // namespace linemap
