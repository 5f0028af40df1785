// Morphological smoothing of a trinary map, proposed to the tolerance
// checks. Erosion and dilation by a square are thresholds on a Chebyshev
// distance transform, so every radius costs the same two raster passes.
#include "codec/codec/tolerance_smoothing.h"

#include <algorithm>
#include <cstdint>
#include <vector>

#include "codec/codec/tolerance_internal.h"
#include "linemap/labeling.h"

namespace linemap::tolerance_internal {
namespace {

std::vector<std::uint8_t> Not(const std::vector<std::uint8_t>& mask) {
  std::vector<std::uint8_t> out(mask.size());
  for (std::size_t i = 0; i < mask.size(); ++i) out[i] = !mask[i];
  return out;
}

// Cells within `radius` of a cell of `mask`.
std::vector<std::uint8_t> Dilate(int w, int h, const std::vector<std::uint8_t>& mask, int radius) {
  const auto d = ChebyshevDistance(w, h, mask);
  std::vector<std::uint8_t> out(mask.size());
  for (std::size_t i = 0; i < mask.size(); ++i) out[i] = d[i] <= radius;
  return out;
}

// Cells further than `radius` from every cell outside `mask` (the map's
// outside does not erode: free space along the border stays).
std::vector<std::uint8_t> Erode(int w, int h, const std::vector<std::uint8_t>& mask, int radius) {
  return Not(Dilate(w, h, Not(mask), radius));
}

// Small occupied components inside free space, near a larger one, become
// free: a speck next to a wall is noise the wall already stands for.
void DropSpecks(const Grid& original, int t, int speck_cells, Grid* grid) {
  const int w = original.width();
  const int h = original.height();
  BinaryMask occ(w, h);
  occ.bits = CellMask(original, Cell::kOccupied);
  const Labeling labels = LabelComponents(occ, Connectivity::kEight);
  std::vector<std::uint8_t> large(original.size(), 0);
  for (std::size_t i = 0; i < large.size(); ++i) {
    const std::int32_t l = labels.labels[i];
    large[i] = l && labels.components[l - 1].cell_count > static_cast<std::size_t>(speck_cells);
  }
  const auto to_large = ChebyshevDistance(w, h, large);
  for (std::size_t k = 0; k < labels.components.size(); ++k) {
    const ComponentStats& s = labels.components[k];
    if (s.cell_count > static_cast<std::size_t>(speck_cells)) continue;
    const std::int32_t label = static_cast<std::int32_t>(k + 1);
    bool droppable = true;
    for (int r = s.box.min_row - 1; r <= s.box.max_row + 1 && droppable; ++r) {
      for (int c = s.box.min_col - 1; c <= s.box.max_col + 1 && droppable; ++c) {
        if (!original.Contains(c, r)) continue;
        const std::size_t i = original.Index(c, r);
        if (labels.labels[i] == label) {
          droppable = to_large[i] <= t;
        } else if (labels.labels[i] == 0 && original.cells()[i] != Cell::kFree) {
          // Touches unknown space: beside a frontier it is a wall's end.
          bool touches = false;
          for (int dr = -1; dr <= 1; ++dr) {
            for (int dc = -1; dc <= 1; ++dc) touches |= labels.get(c + dc, r + dr) == label;
          }
          droppable = !touches;
        }
      }
    }
    if (!droppable) continue;
    for (int r = s.box.min_row; r <= s.box.max_row; ++r) {
      for (int c = s.box.min_col; c <= s.box.max_col; ++c) {
        if (labels.at(c, r) == label) grid->set(c, r, Cell::kFree);
      }
    }
  }
}

// Opens and closes the free space of `grid`.
void SmoothFreeSpace(const SmoothingParams& p, Grid* grid) {
  const int w = grid->width();
  const int h = grid->height();
  std::vector<Cell>& cells = grid->mutable_cells();
  if (p.open_radius > 0) {
    const auto free = CellMask(*grid, Cell::kFree);
    const auto opened = Dilate(w, h, Erode(w, h, free, p.open_radius), p.open_radius);
    const auto near_occ = Dilate(w, h, CellMask(*grid, Cell::kOccupied), p.open_radius + 1);
    for (std::size_t i = 0; i < cells.size(); ++i) {
      if (free[i] && !opened[i] && !near_occ[i]) cells[i] = Cell::kUnknown;
    }
  }
  if (p.close_radius > 0) {
    const auto free = CellMask(*grid, Cell::kFree);
    const auto closed = Erode(w, h, Dilate(w, h, free, p.close_radius), p.close_radius);
    for (std::size_t i = 0; i < cells.size(); ++i) {
      if (closed[i] && cells[i] == Cell::kUnknown) cells[i] = Cell::kFree;
    }
  }
}

// Majority of occupied against unknown among cells without a free
// 8-neighbour: the ragged backs of walls and noise in unknown space. Free
// space and the wall surfaces facing it are left alone.
void SmoothWallBacks(int passes, Grid* grid) {
  const int w = grid->width();
  const int h = grid->height();
  for (int pass = 0; pass < passes; ++pass) {
    const Grid before = *grid;
    for (int r = 0; r < h; ++r) {
      for (int c = 0; c < w; ++c) {
        const Cell self = before.at(c, r);
        if (self == Cell::kFree) continue;
        int occ = 0, unknown = 0;
        bool near_free = false;
        for (int dr = -1; dr <= 1; ++dr) {
          for (int dc = -1; dc <= 1; ++dc) {
            if (!before.Contains(c + dc, r + dr)) continue;
            const Cell n = before.at(c + dc, r + dr);
            near_free |= n == Cell::kFree;
            occ += n == Cell::kOccupied;
            unknown += n == Cell::kUnknown;
          }
        }
        if (near_free) continue;
        if (self == Cell::kOccupied && unknown >= 6) grid->set(c, r, Cell::kUnknown);
        if (self == Cell::kUnknown && occ >= 6) grid->set(c, r, Cell::kOccupied);
      }
    }
  }
}

}  // namespace

SmoothingParams DefaultSmoothingParams(int t) {
  SmoothingParams p;
  p.open_radius = std::max(1, t);
  p.close_radius = std::max(1, t);
  p.speck_cells = 4;
  p.wall_back_passes = 1;
  return p;
}

Grid ProposeSmoothing(const Grid& grid, int t, const SmoothingParams& params) {
  Grid out = grid;
  if (params.speck_cells > 0) DropSpecks(grid, t, params.speck_cells, &out);
  SmoothFreeSpace(params, &out);
  SmoothWallBacks(params.wall_back_passes, &out);
  return out;
}

}  // namespace linemap::tolerance_internal
