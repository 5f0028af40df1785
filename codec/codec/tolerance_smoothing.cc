// Morphological smoothing of a trinary map, proposed to the tolerance
// checks. Erosion and dilation by a square are thresholds on a Chebyshev
// distance transform, so every radius costs the same two raster passes.
#include "codec/codec/tolerance_smoothing.h"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "codec/codec/tolerance_internal.h"
#include "linemap/labeling.h"

namespace linemap::tolerance_internal {
namespace {

// Groups of the 8 neighbours of a cell that have `member` set, connected
// within the 3x3 ring (the centre left out) by 4-adjacency (`eight` false)
// or 8-adjacency; with `touching_centre`, only groups holding a
// 4-neighbour of the centre count.
int RingGroups(const bool member[8], bool eight, bool touching_centre) {
  static constexpr int kDc[8] = {1, 1, 0, -1, -1, -1, 0, 1};
  static constexpr int kDr[8] = {0, 1, 1, 1, 0, -1, -1, -1};
  int group[8] = {0, 0, 0, 0, 0, 0, 0, 0};
  int groups = 0;
  for (int start = 0; start < 8; ++start) {
    if (!member[start] || group[start]) continue;
    ++groups;
    int stack[8];
    int top = 0;
    stack[top++] = start;
    group[start] = groups;
    bool touches = false;
    while (top > 0) {
      const int k = stack[--top];
      touches |= k % 2 == 0;  // even positions are the 4-neighbours
      for (int n = 0; n < 8; ++n) {
        if (!member[n] || group[n]) continue;
        const int dc = std::abs(kDc[n] - kDc[k]);
        const int dr = std::abs(kDr[n] - kDr[k]);
        if (dc + dr == 1 || (eight && dc == 1 && dr == 1)) {
          group[n] = groups;
          stack[top++] = n;
        }
      }
    }
    if (touching_centre && !touches) --groups;  // (its cells keep a stale id)
  }
  return groups;
}

// True when turning the non-free cell (c, r) free keeps the free space's
// topology (a simple point for 4-connected free space against 8-connected
// rest): it meets exactly one 4-connected group of free cells and the
// non-free cells around it stay one 8-connected group. Filling a thin
// unknown line between two parts of a room would open a shortcut that
// changes plans; these changes never do.
bool FillKeepsTopology(const Grid& g, int c, int r) {
  static constexpr int kDc[8] = {1, 1, 0, -1, -1, -1, 0, 1};
  static constexpr int kDr[8] = {0, 1, 1, 1, 0, -1, -1, -1};
  bool free[8], rest[8];
  for (int k = 0; k < 8; ++k) {
    free[k] = g.Contains(c + kDc[k], r + kDr[k]) && g.at(c + kDc[k], r + kDr[k]) == Cell::kFree;
    rest[k] = !free[k];
  }
  return RingGroups(free, false, true) == 1 && RingGroups(rest, true, false) == 1;
}

// True when all 8 neighbours of (c, r) are free: a one-cell speck inside
// free space. Filling it changes the topology but shortens a plan around it
// by two steps at most, which plans may (kPlanSlackSteps).
bool FreeAllAround(const Grid& g, int c, int r) {
  for (int dr = -1; dr <= 1; ++dr) {
    for (int dc = -1; dc <= 1; ++dc) {
      if ((dc || dr) && !(g.Contains(c + dc, r + dr) && g.at(c + dc, r + dr) == Cell::kFree)) {
        return false;
      }
    }
  }
  return true;
}

// True when turning (c, r) free shortens no plan by more than two steps:
// two free 4-neighbours on adjacent sides must have the corner between
// them free (a path through the cell then has an equally long one around
// it), and two on opposite sides a free side of three cells between them
// (a path around is two steps longer). A bump of unknown on a straight
// border passes; the tip of a thin spur, or a cell in a thin line between
// two parts of a room, does not.
bool FillKeepsPlans(const Grid& g, int c, int r) {
  auto free = [&](int dc, int dr) {
    return g.Contains(c + dc, r + dr) && g.at(c + dc, r + dr) == Cell::kFree;
  };
  const bool e = free(1, 0), n = free(0, 1), w = free(-1, 0), s = free(0, -1);
  if ((e && n && !free(1, 1)) || (n && w && !free(-1, 1)) || (w && s && !free(-1, -1)) ||
      (s && e && !free(1, -1))) {
    return false;
  }
  const bool row_n = free(-1, 1) && n && free(1, 1);
  const bool row_s = free(-1, -1) && s && free(1, -1);
  const bool col_e = free(1, -1) && e && free(1, 1);
  const bool col_w = free(-1, -1) && w && free(-1, 1);
  if (e && w && !row_n && !row_s) return false;
  if (n && s && !col_e && !col_w) return false;
  return true;
}

// Whether the non-free cell (c, r) may turn free, judged on the map before
// the current operation (`before`) and as it is now (`now`): both must keep
// the topology, so that a spur or island is worn down by a cell at its end
// at most and never eaten away cell by cell, and the plans through it must
// stay as long (FillKeepsPlans); or the cell was a one-cell speck inside
// free space before.
bool MayFill(const Grid& before, const Grid& now, int c, int r) {
  if (FreeAllAround(before, c, r)) return true;
  return FillKeepsTopology(before, c, r) && FillKeepsTopology(now, c, r) &&
         FillKeepsPlans(now, c, r);
}

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
        if (labels.at(c, r) == label && MayFill(original, *grid, c, r))
          grid->set(c, r, Cell::kFree);
      }
    }
  }
}

// Opens the free space of `grid`: thin free rays into unknown space become
// unknown, from the 4-connected pieces of them whose every cell is within t
// of the free space that stays. Cells are taken one at a time from a ray's
// tip inwards (a few passes), each only when that keeps the free space's
// topology and the plans between the cells that stay (a thin passage
// between two parts of a room is kept: removing it would lengthen plans).
void OpenFreeSpace(int t, int radius, Grid* grid) {
  const int w = grid->width();
  const int h = grid->height();
  const auto free = CellMask(*grid, Cell::kFree);
  const auto opened = Dilate(w, h, Erode(w, h, free, radius), radius);
  const auto near_occ = Dilate(w, h, CellMask(*grid, Cell::kOccupied), radius + 1);
  const auto to_opened = ChebyshevDistance(w, h, opened);
  BinaryMask removed(w, h);
  for (std::size_t i = 0; i < free.size(); ++i) removed.bits[i] = free[i] && !opened[i];
  const Labeling pieces = LabelComponents(removed, Connectivity::kFour);
  std::vector<std::uint8_t> keep(pieces.components.size() + 1, 0);
  for (std::size_t i = 0; i < free.size(); ++i) {
    const std::int32_t l = pieces.labels[i];
    if (l && (near_occ[i] || to_opened[i] > t)) keep[l] = 1;
  }
  bool changed = true;
  for (int pass = 0; pass < 2 * t + 2 && changed; ++pass) {
    changed = false;
    for (int r = 0; r < h; ++r) {
      for (int c = 0; c < w; ++c) {
        const std::int32_t l = pieces.at(c, r);
        if (!l || keep[l] || grid->at(c, r) != Cell::kFree) continue;
        if (!FillKeepsTopology(*grid, c, r) || !FillKeepsPlans(*grid, c, r)) continue;
        grid->set(c, r, Cell::kUnknown);
        changed = true;
      }
    }
  }
}

// Closes the free space of `grid`: unknown notches and specks inside free
// space become free, but only where the free cells around (within radius
// + 1) belong to one free region, so that no unknown gap between two rooms
// (or a room and a speck of free space) fills.
void CloseFreeSpace(const Grid& original, int radius, Grid* grid) {
  const int w = grid->width();
  const int h = grid->height();
  const auto free = CellMask(*grid, Cell::kFree);
  const auto closed = Erode(w, h, Dilate(w, h, free, radius), radius);
  BinaryMask free_mask(w, h);
  free_mask.bits = free;
  const Labeling regions = LabelComponents(free_mask, Connectivity::kFour);
  const int reach = radius + 1;
  std::vector<Cell>& cells = grid->mutable_cells();
  // Cells are filled one at a time, each checked against the cells filled
  // before it (simple points stay simple only when taken in turn) and
  // against the original map, so that a thin spur of unknown loses its tip
  // only and not its length cell by cell (each cell taken would shorten
  // the plans around it by two more steps), and so that the opening before
  // cannot make a fill look harmless.
  const Grid& before = original;
  for (int pass = 0; pass < 1; ++pass) {
    for (int r = 0; r < h; ++r) {
      for (int c = 0; c < w; ++c) {
        const std::size_t i = grid->Index(c, r);
        if (!closed[i] || cells[i] != Cell::kUnknown) continue;
        if (!MayFill(before, *grid, c, r)) continue;
        std::int32_t region = 0;
        bool one_region = true;
        for (int dr = -reach; dr <= reach && one_region; ++dr) {
          for (int dc = -reach; dc <= reach; ++dc) {
            const std::int32_t l = regions.get(c + dc, r + dr);
            if (!l) continue;
            if (region && l != region) {
              one_region = false;
              break;
            }
            region = l;
          }
        }
        if (one_region) cells[i] = Cell::kFree;
      }
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

// Every cell takes the value of its aligned block of side `b`: the map made
// b times coarser, drawn back at full resolution.
void QuantizeBlocks(int b, Grid* grid) {
  const int w = grid->width();
  const int h = grid->height();
  for (int r0 = 0; r0 < h; r0 += b) {
    for (int c0 = 0; c0 < w; c0 += b) {
      Cell v = Cell::kFree;
      for (int r = r0; r < std::min(h, r0 + b); ++r) {
        for (int c = c0; c < std::min(w, c0 + b); ++c) {
          const Cell x = grid->at(c, r);
          if (x == Cell::kOccupied || (x == Cell::kUnknown && v == Cell::kFree)) v = x;
        }
      }
      for (int r = r0; r < std::min(h, r0 + b); ++r) {
        for (int c = c0; c < std::min(w, c0 + b); ++c) grid->set(c, r, v);
      }
    }
  }
}

// The non-free cells of each aligned block of side `b` all become occupied
// when one of them is: the border between obstacles and unknown space
// follows the block lattice, which the tile coder codes cheaply.
void QuantizeNonFreeBlocks(int b, Grid* grid) {
  const int w = grid->width();
  const int h = grid->height();
  for (int r0 = 0; r0 < h; r0 += b) {
    for (int c0 = 0; c0 < w; c0 += b) {
      bool occupied = false;
      for (int r = r0; r < std::min(h, r0 + b); ++r) {
        for (int c = c0; c < std::min(w, c0 + b); ++c)
          occupied |= grid->at(c, r) == Cell::kOccupied;
      }
      if (!occupied) continue;
      for (int r = r0; r < std::min(h, r0 + b); ++r) {
        for (int c = c0; c < std::min(w, c0 + b); ++c) {
          if (grid->at(c, r) == Cell::kUnknown) grid->set(c, r, Cell::kOccupied);
        }
      }
    }
  }
}

}  // namespace

// Chosen on the tuning half of ../shared/maps (bench_tolerance): radii of 1
// smooth as much as larger ones once fills must keep plans, and the
// non-free blocks of side T + 1 (obstacles move by at most T) save the
// most: exact-file medians 0.950, 0.930, 0.923, 0.912 at T = 1..4 against
// 0.99..0.97 without them.
SmoothingParams DefaultSmoothingParams(int t) {
  SmoothingParams p;
  p.open_radius = 1;
  p.close_radius = 1;
  p.speck_cells = 4;
  p.wall_back_passes = 1;
  p.nonfree_block_cells = t + 1;
  return p;
}

Grid ProposeSmoothing(const Grid& grid, int t, const SmoothingParams& params) {
  Grid out = grid;
  if (params.block_cells > 1) QuantizeBlocks(params.block_cells, &out);
  if (params.speck_cells > 0) DropSpecks(grid, t, params.speck_cells, &out);
  if (params.open_radius > 0) OpenFreeSpace(t, params.open_radius, &out);
  if (params.close_radius > 0) CloseFreeSpace(grid, params.close_radius, &out);
  SmoothWallBacks(params.wall_back_passes, &out);
  if (params.nonfree_block_cells > 1) QuantizeNonFreeBlocks(params.nonfree_block_cells, &out);
  return out;
}

}  // namespace linemap::tolerance_internal
