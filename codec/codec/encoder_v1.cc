// The 1.0 .lmap encoder (spec/format.md section 11.7, "Encoding 1.0 files"):
// the lossy mode, kept behind EncodeOptions::format_v1 until the tolerance
// mode replaces it.
//
// Lossy layers, in decoding order:
//   SEGS  wall segments on the integer lattice: the extractor's lines
//         (ExtractLines, lines.h) rounded to cell centres, kept when at least
//         min_segment_cells long and on the walls (FollowsWalls; by default
//         never over a free cell: a line crossing free cells is split into
//         its runs between them). Occupied cells within one cell of a
//         segment are then dropped: the segment recalls them within one cell.
//   OCCP  the remaining occupied cells, minus isolated occupied specks, with
//         notches filled and spurs into the unknown left out (SmoothWalls).
//   FREE  the free cells, with free specks dropped; with
//         EncodeOptions::simplify_free_space also small enclosed holes
//         filled (only when all their free neighbours are one region, so no
//         two regions are ever joined) and the boundary smoothed
//         (SmoothFreeBoundary). Without it the free space a planner sees is
//         kept: every change above turns an obstacle into another obstacle.
// The lossy encoder tries the tunings of kLossyTunings, boldest first, with
// and without segments, and keeps for each the first that meets the goals
// (EncodeLossy).
// Lossless mode codes the layers exactly (kExactLayers), or the lossy
// layers plus RESD, the exact grid coded against the lossy one (kResidual).
// ROOM and BLOB chunks are defined by the format; this encoder does not
// write them yet (the planes proved cheaper, see spec/format.md).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <future>
#include <limits>
#include <optional>
#include <string>
#include <system_error>
#include <utility>

#include "codec/codec/chunk_coding.h"
#include "codec/codec/compare_internal.h"
#include "codec/codec/draco_segments.h"
#include "codec/codec/encoder_v1.h"
#include "codec/codec/layer_extraction.h"
#include "codec/codec/plane_coder.h"
#include "codec/codec/raster.h"
#include "codec/codec/start_task.h"
#include "format/container.h"
#include "format/file_io.h"
#include "linemap/codec.h"
#include "linemap/labeling.h"

namespace linemap {
namespace {

// How far a lossy encoding may move away from the map. The encoder tries
// the tunings of kLossyTunings from the boldest, checks each decoded result
// against the goals (kGoal*) and keeps the smallest file that meets them.
struct LossyTuning {
  // Free 4-connected regions smaller than this are dropped (cells; 3).
  std::size_t min_free_region_cells;
  // Enclosed holes in the free space up to this size are filled (cells; 8),
  // at most hole_budget of the free cells in all (share; 0.01).
  std::size_t max_hole_cells;
  double hole_budget;
  // Largest share of occupied cells that may be dropped as isolated specks
  // (share; 0.01).
  double speck_budget;
  // Passes of the free/unknown boundary smoothing (SmoothFreeBoundary; 0..3)
  // and the largest share of the free cells each direction of change may
  // touch in all (share; 0.015).
  int smoothing_passes;
  double smoothing_budget;
  // Passes of the wall smoothing (SmoothWalls; 0..2): unknown cells in wall
  // notches become occupied and lone wall spurs into the unknown go.
  int wall_passes;
};
constexpr LossyTuning kLossyTunings[] = {
    {24, 48, 0.012, 0.016, 3, 0.018, 2},
    {12, 24, 0.010, 0.012, 2, 0.012, 1},
    {6, 12, 0.008, 0.010, 1, 0.008, 1},
    {3, 8, 0.010, 0.010, 0, 0.0, 0},
};
// The goals a lossy file must meet, with a margin below issue 6's limits
// (recall / precision within one cell >= 0.98, free IoU >= 0.95, unknown
// turned free <= 2% of the free cells, no leaks).
constexpr double kGoalRecall = 0.982;
constexpr double kGoalPrecision = 0.982;
constexpr double kGoalFreeIou = 0.952;
constexpr double kGoalUnknownTurnedFree = 0.019;
// Share of a stored segment's cells that must be occupied cells.
constexpr double kMinOnWallShare = 0.75;
// How much larger (share) a lossy file with wall segments may be than the
// smallest one without, and still be chosen (0.10: walls as lines are worth
// a tenth of the file; tiny maps, where they cost more, go without).
constexpr double kSegmentOverhead = 0.10;

// 4-connected components of the cells where `member` is 1 (two-pass
// labelling, linear and cache-friendly).
Labeling LabelMembers(int width, int height, std::vector<std::uint8_t> member) {
  BinaryMask mask(width, height);
  mask.bits = std::move(member);
  return LabelComponents(mask, Connectivity::kFour);
}

bool TouchesBorder(const ComponentStats& component, int width, int height) {
  return component.box.min_col == 0 || component.box.min_row == 0 ||
         component.box.max_col == width - 1 || component.box.max_row == height - 1;
}

// Occupied cells to reproduce: all but isolated specks, within the budget.
std::vector<std::uint8_t> OccupiedTarget(const Grid& grid, double speck_budget) {
  const int w = grid.width();
  const int h = grid.height();
  const std::vector<Cell>& cells = grid.cells();
  std::vector<std::uint8_t> target(cells.size(), 0);
  std::size_t occupied = 0;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    target[i] = cells[i] == Cell::kOccupied;
    occupied += target[i];
  }
  std::size_t budget = static_cast<std::size_t>(speck_budget * static_cast<double>(occupied));
  for (int r = 0; r < h && budget > 0; ++r) {
    for (int c = 0; c < w && budget > 0; ++c) {
      if (!target[grid.Index(c, r)]) continue;
      bool alone = true;
      for (int dr = -1; dr <= 1 && alone; ++dr) {
        for (int dc = -1; dc <= 1; ++dc) {
          if ((dr || dc) && grid.Contains(c + dc, r + dr) &&
              cells[grid.Index(c + dc, r + dr)] == Cell::kOccupied) {
            alone = false;
            break;
          }
        }
      }
      if (alone) {
        target[grid.Index(c, r)] = 0;
        --budget;
      }
    }
  }
  return target;
}

// Smooths the free/unknown boundary, which scans leave ragged and which
// costs most of the FREE plane: an inner cell (not occupied) with at least
// 5 of its 8 neighbours on the other side flips, in raster order and in
// place, within tuning.smoothing_budget of `free_cells` per direction. A
// cell turns free only when every free neighbour belongs to one region
// (`region`, updated as cells turn free), so no two regions are joined.
void SmoothFreeBoundary(int w, int h, const std::vector<std::uint8_t>& occupied,
                        const LossyTuning& tuning, std::size_t free_cells,
                        std::vector<std::uint32_t>* region, std::vector<std::uint8_t>* target) {
  const auto budget =
      static_cast<std::size_t>(tuning.smoothing_budget * static_cast<double>(free_cells));
  std::size_t added = 0, removed = 0;
  std::vector<std::uint8_t>& t = *target;
  std::vector<std::uint32_t>& id = *region;
  for (int pass = 0; pass < tuning.smoothing_passes; ++pass) {
    for (int r = 1; r + 1 < h; ++r) {
      for (int c = 1; c + 1 < w; ++c) {
        const std::size_t i = static_cast<std::size_t>(r) * w + c;
        if (occupied[i]) continue;
        // A flip needs 5 of the 8 neighbours on the other side, so at least
        // one of the four edge neighbours: most cells are settled here.
        const std::uint8_t side = t[i];
        if (t[i - 1] == side && t[i + 1] == side && t[i - w] == side && t[i + w] == side) {
          continue;
        }
        int free = 0, open = 0;
        std::uint32_t only = 0;
        bool one_region = true;
        for (int dr = -1; dr <= 1; ++dr) {
          for (int dc = -1; dc <= 1; ++dc) {
            if (!dr && !dc) continue;
            const std::size_t j = i + static_cast<std::ptrdiff_t>(dr) * w + dc;
            if (t[j]) {
              ++free;
              if (only != 0 && only != id[j]) one_region = false;
              only = id[j];
            } else if (!occupied[j]) {
              ++open;
            }
          }
        }
        if (t[i] && open >= 5 && removed < budget) {
          t[i] = 0;
          id[i] = 0;
          ++removed;
        } else if (!t[i] && free >= 5 && one_region && only != 0 && added < budget) {
          t[i] = 1;
          id[i] = only;
          ++added;
        }
      }
    }
  }
}

// True when no cell of `o` is set in the rows above, at and below cells
// i..i+7, nor one column either side: then SmoothWalls changes none of the
// eight (most of a map; tested eight bytes at a time).
inline bool NoOccupiedAround8(const std::uint8_t* o, std::size_t i, int w) {
  std::uint64_t any = 0;
  for (const std::size_t row_start : {i - w - 1, i - 1, i + w - 1}) {
    std::uint64_t left, right;  // columns -1..6 and 1..8 of the block
    std::memcpy(&left, o + row_start, 8);
    std::memcpy(&right, o + row_start + 2, 8);
    any |= left | right;
  }
  return any == 0;
}

// Smooths the walls where it costs no measure: an unknown cell of the map
// with at least 5 occupied neighbours (a notch) becomes occupied (precision
// holds: it touches a wall), and an occupied cell that touches no free cell,
// has at most 2 occupied neighbours, none of them dropped, and at least one
// kept, goes (recall holds: a kept neighbour is within one cell).
void SmoothWalls(const Grid& grid, int passes, std::vector<std::uint8_t>* occupied) {
  const int w = grid.width();
  const int h = grid.height();
  const std::vector<Cell>& cells = grid.cells();
  std::vector<std::uint8_t>& o = *occupied;
  std::vector<std::uint8_t> dropped(o.size(), 0);
  for (int pass = 0; pass < passes; ++pass) {
    for (int r = 1; r + 1 < h; ++r) {
      for (int c = 1; c + 1 < w; ++c) {
        const std::size_t i = static_cast<std::size_t>(r) * w + c;
        if (c + 8 < w && NoOccupiedAround8(o.data(), i, w)) {
          c += 7;  // nothing can change in these 8 cells
          continue;
        }
        // Only unknown cells (which need 5 occupied neighbours, so at least
        // one edge neighbour) and occupied cells of the map can change; an
        // occupied cell with 3 or 4 occupied edge neighbours has more than 2
        // occupied neighbours and stays (the inside of solid walls).
        if (!o[i] && cells[i] != Cell::kUnknown) continue;  // most cells: free
        const int edge_occupied = o[i - 1] + o[i + 1] + o[i - w] + o[i + w];
        if (!o[i] && edge_occupied == 0) continue;
        if (o[i] && edge_occupied >= 3) continue;
        int occ = 0;
        bool touches_free = false, touches_dropped = false;
        for (int dr = -1; dr <= 1; ++dr) {
          for (int dc = -1; dc <= 1; ++dc) {
            if (!dr && !dc) continue;
            const std::size_t j = i + static_cast<std::ptrdiff_t>(dr) * w + dc;
            occ += o[j];
            touches_free = touches_free || cells[j] == Cell::kFree;
            touches_dropped = touches_dropped || dropped[j];
          }
        }
        if (!o[i] && cells[i] == Cell::kUnknown && !dropped[i] && occ >= 5) {
          o[i] = 1;
        } else if (o[i] && cells[i] == Cell::kOccupied && !touches_free && !touches_dropped &&
                   occ >= 1 && occ <= 2) {
          o[i] = 0;
          dropped[i] = 1;
        }
      }
    }
  }
}

// Free cells to reproduce: the free cells minus free specks, plus small
// enclosed holes whose free neighbours all belong to one free region (so a
// filled hole never joins two regions) and which hold no occupied cell that
// will be drawn.
std::vector<std::uint8_t> FreeTargetOf(const Grid& grid, const Labeling& free_regions,
                                       const std::vector<std::uint8_t>& occupied, bool exact,
                                       const LossyTuning& tuning) {
  const int w = grid.width();
  const int h = grid.height();
  const std::vector<Cell>& cells = grid.cells();
  // Holes and smoothing need each free cell's region; the rest does not.
  const bool reshapes = !exact && (tuning.max_hole_cells > 0 || tuning.smoothing_passes > 0);
  std::vector<std::uint8_t> target(cells.size(), 0);
  std::vector<std::uint32_t> region(reshapes ? cells.size() : 0, 0);  // label, 0 = none
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const std::int32_t label = free_regions.labels[i];
    if (!label) continue;
    if (!exact && free_regions.components[label - 1].cell_count < tuning.min_free_region_cells) {
      continue;
    }
    target[i] = 1;
    if (reshapes) region[i] = static_cast<std::uint32_t>(label);
  }
  if (!reshapes) return target;
  std::size_t free_cells = 0;
  for (std::uint8_t t : target) free_cells += t;
  std::size_t budget =
      static_cast<std::size_t>(tuning.hole_budget * static_cast<double>(free_cells));
  std::vector<std::uint8_t> member(cells.size());
  // Holes: components of neither free nor drawn cells. A hole may be filled
  // when it is small, off the border and all its free 4-neighbours belong to
  // one region (`joins`: that region, 0 = none yet, kJoinsMany = several).
  for (std::size_t i = 0; i < cells.size(); ++i) member[i] = target[i] == 0 && !occupied[i];
  const Labeling holes = LabelMembers(w, h, std::move(member));
  constexpr std::uint32_t kJoinsMany = ~0u;
  std::vector<std::uint32_t> joins(holes.components.size(), 0);
  for (int r = 0; r < h; ++r) {
    for (int c = 0; c < w; ++c) {
      const std::size_t i = static_cast<std::size_t>(r) * w + c;
      const std::int32_t hole = holes.labels[i];
      if (!hole || holes.components[hole - 1].cell_count > tuning.max_hole_cells) continue;
      std::uint32_t& join = joins[hole - 1];
      const std::size_t around[4] = {i - 1, i + 1, i - w, i + w};
      const bool inside[4] = {c > 0, c + 1 < w, r > 0, r + 1 < h};
      for (int k = 0; k < 4 && join != kJoinsMany; ++k) {
        const std::uint32_t id = inside[k] ? region[around[k]] : 0;
        if (id != 0) join = (join == 0 || join == id) ? id : kJoinsMany;
      }
    }
  }
  // Holes are taken in the raster order of their first cells until the
  // budget is spent; two holes are never 4-adjacent, so the choices are
  // independent.
  for (std::size_t k = 0; k < holes.components.size(); ++k) {
    const ComponentStats& hole = holes.components[k];
    if (TouchesBorder(hole, w, h) || hole.cell_count > tuning.max_hole_cells ||
        hole.cell_count > budget || joins[k] == 0 || joins[k] == kJoinsMany) {
      joins[k] = 0;
      continue;
    }
    budget -= hole.cell_count;
  }
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const std::int32_t hole = holes.labels[i];
    if (hole && joins[hole - 1]) {
      target[i] = 1;
      region[i] = joins[hole - 1];
    }
  }
  SmoothFreeBoundary(w, h, occupied, tuning, free_cells, &region, &target);
  return target;
}

// True when consecutive cells (and the last and first) are 8-neighbours and
// all lie in the grid: what the ROOM chunk can store.
bool IsStorableChain(const Grid& grid, const std::vector<CellIndex>& chain) {
  if (chain.size() < 2) return false;
  for (std::size_t i = 0; i < chain.size(); ++i) {
    const CellIndex p = chain[i];
    const CellIndex q = chain[(i + 1) % chain.size()];
    if (!grid.Contains(p.col, p.row)) return false;
    const int dc = std::abs(p.col - q.col);
    const int dr = std::abs(p.row - q.row);
    if (dc > 1 || dr > 1 || (dc == 0 && dr == 0)) return false;
  }
  return true;
}

// Room-border chains from the segmentation (segmentation.h).
StatusOr<std::vector<std::vector<CellIndex>>> RoomChains(const Grid& grid,
                                                         const EncodeOptions& options) {
  SegmentationOptions seg_options;
  if (options.robot_pose) {
    CellPoint robot;
    grid.WorldToCell(options.robot_pose->x, options.robot_pose->y, &robot.col, &robot.row);
    if (grid.Contains(static_cast<int>(std::nearbyint(robot.col)),
                      static_cast<int>(std::nearbyint(robot.row)))) {
      seg_options.robot = robot;
    }
  }
  LINEMAP_ASSIGN_OR_RETURN(Segmentation seg, SegmentMap(grid, seg_options));
  std::vector<std::vector<CellIndex>> chains;
  for (RoomBorder& room : seg.rooms) {
    if (IsStorableChain(grid, room.chain)) chains.push_back(std::move(room.chain));
  }
  return chains;
}

// True when the segment's cells stay on the walls: each within one cell of
// an occupied cell of the map, at least `min_on_wall_share` of them on an
// occupied cell the decoder will draw anyway, and (unless `may_cover_free`)
// none on a free cell of the map, so that the free space a planner sees is
// kept.
bool FollowsWalls(const Grid& grid, const std::vector<std::uint8_t>& occupied,
                  const LatticeSegment& s, double min_on_wall_share, bool may_cover_free) {
  std::size_t cells = 0, on_wall = 0;
  bool near = true;
  RasterizeSegment(s.a, s.b, [&](int c, int r) {
    ++cells;
    on_wall += occupied[grid.Index(c, r)];
    if (!may_cover_free && grid.at(c, r) == Cell::kFree) near = false;
    bool any = false;
    for (int dr = -1; dr <= 1 && !any; ++dr) {
      for (int dc = -1; dc <= 1 && !any; ++dc) {
        any = grid.Contains(c + dc, r + dr) && grid.at(c + dc, r + dr) == Cell::kOccupied;
      }
    }
    near = near && any;
  });
  return near && static_cast<double>(on_wall) >= min_on_wall_share * static_cast<double>(cells);
}

// The wall segments to store: the extractor's lines on the lattice, kept
// when they are long enough and follow the walls.
std::vector<LatticeSegment> WallSegments(const Grid& grid,
                                         const std::vector<std::uint8_t>& occupied,
                                         const std::vector<LineSegment>& lines,
                                         const EncodeOptions& options, bool exact) {
  std::vector<LatticeSegment> segments;
  const double on_wall_share = exact ? 1.0 : kMinOnWallShare;
  const auto keep = [&](const LatticeSegment& s) {
    const int cells = std::max(std::abs(s.a.col - s.b.col), std::abs(s.a.row - s.b.row)) + 1;
    if (cells < options.min_segment_cells) return false;
    if (!FollowsWalls(grid, occupied, s, on_wall_share, options.simplify_free_space)) return false;
    segments.push_back(s);
    return true;
  };
  for (const LineSegment& line : lines) {
    const LatticeSegment s = ToLattice(line, grid.width(), grid.height());
    if (keep(s) || options.simplify_free_space) continue;
    // A segment that crosses free cells: its runs of raster cells between
    // them, each as a segment of its own.
    std::vector<CellIndex> run;
    const auto flush = [&] {
      if (run.size() >= 2) keep(LatticeSegment{run.front(), run.back()});
      run.clear();
    };
    RasterizeSegment(s.a, s.b, [&](int c, int r) {
      if (grid.at(c, r) == Cell::kFree) {
        flush();
      } else {
        run.push_back({c, r});
      }
    });
    flush();
  }
  CanonicalizeSegments(&segments);
  segments.erase(std::unique(segments.begin(), segments.end()), segments.end());
  return segments;
}

// The SEGS payload: varints raw or deflated, or Draco, whichever is
// smallest (ties keep the earlier).
std::vector<std::uint8_t> SegmentPayload(const std::vector<LatticeSegment>& segments) {
  std::vector<std::uint8_t> best = WrapPayload(WriteSegments(segments), true);
  const std::vector<std::uint8_t> draco = EncodeSegmentsDraco(segments);
  if (!draco.empty() && draco.size() + 1 < best.size()) {
    best.assign(1, static_cast<std::uint8_t>(PayloadCoder::kDraco));
    best.insert(best.end(), draco.begin(), draco.end());
  }
  return best;
}

// After the segments are drawn (canvas occupied), the occupied cells within
// one cell of them are already recalled: dropping them saves coding a second
// wall layer. The segments' own cells become part of the target.
void DropCellsNearSegments(const Grid& grid, const std::vector<Cell>& canvas,
                           std::vector<std::uint8_t>* occupied) {
  const int w = grid.width();
  const int h = grid.height();
  std::vector<std::uint8_t>& o = *occupied;
  // From each drawn cell outwards (the drawn cells are few): its occupied
  // 8-neighbours that are not drawn themselves go.
  for (int r = 0; r < h; ++r) {
    for (int c = 0; c < w; ++c) {
      if (canvas[grid.Index(c, r)] != Cell::kOccupied) continue;
      for (int dr = -1; dr <= 1; ++dr) {
        for (int dc = -1; dc <= 1; ++dc) {
          if (!grid.Contains(c + dc, r + dr)) continue;
          const std::size_t j = grid.Index(c + dc, r + dr);
          if (canvas[j] != Cell::kOccupied) o[j] = 0;
        }
      }
      o[grid.Index(c, r)] = 1;
    }
  }
}

// A candidate file and the grid it decodes to (what the decoder rebuilds
// from the same layers; without RESD).
struct EncodedFile {
  std::vector<std::uint8_t> bytes;
  std::vector<Cell> decoded_cells;
};

// One complete file; segments come from `wall_lines` when it is given, and
// `free_regions` is LabelFree(grid). With `exact`, every occupied and free
// cell is reproduced as it is and segments may only cover occupied cells, so
// no residual is needed.
StatusOr<EncodedFile> EncodeFile(const Grid& grid, const Labeling& free_regions,
                                 const EncodeOptions& options, bool exact,
                                 const std::vector<LineSegment>* wall_lines,
                                 const LossyTuning& tuning) {
  const int w = grid.width();
  const int h = grid.height();
  ContainerWriter writer(1, 0);  // the 1.0 encoder (lossy mode) writes 1.0 files
  writer.AddChunk(kHeaderChunk, WriteHeader(HeaderFields{w, h, grid.meta, options.lossless}));
  const auto metadata = MetadataOf(options);
  if (!metadata.empty()) {
    writer.AddChunk(kMetadataChunk, WrapPayload(WriteMetadata(metadata), true));
  }

  std::vector<Cell> canvas(grid.size(), Cell::kUnknown);
  std::vector<std::uint8_t> occupied = OccupiedTarget(grid, exact ? 0.0 : tuning.speck_budget);
  if (!exact) SmoothWalls(grid, tuning.wall_passes, &occupied);

  if (options.store_room_chains) {
    LINEMAP_ASSIGN_OR_RETURN(std::vector<std::vector<CellIndex>> chains, RoomChains(grid, options));
    if (!chains.empty()) {
      writer.AddChunk(kRoomChunk, WrapPayload(WriteChains(chains), true));
      for (const auto& chain : chains) {
        FillChain(chain, [&](int c, int r) { canvas[grid.Index(c, r)] = Cell::kFree; });
      }
    }
  }

  std::vector<LatticeSegment> segments;
  if (wall_lines) segments = WallSegments(grid, occupied, *wall_lines, options, exact);
  if (!segments.empty()) {
    writer.AddChunk(kSegmentChunk, SegmentPayload(segments));
    for (const LatticeSegment& s : segments) {
      RasterizeSegment(s.a, s.b, [&](int c, int r) { canvas[grid.Index(c, r)] = Cell::kOccupied; });
    }
    if (!exact) DropCellsNearSegments(grid, canvas, &occupied);
  }
  writer.AddChunk(kOccupiedChunk, WrapPayload(EncodeOccupiedPlane(occupied, canvas, w, h), false));
  for (std::size_t i = 0; i < canvas.size(); ++i) {
    if (occupied[i]) canvas[i] = Cell::kOccupied;
  }
  const std::vector<std::uint8_t> free_target =
      FreeTargetOf(grid, free_regions, occupied, exact, tuning);
  writer.AddChunk(kFreeChunk, WrapPayload(EncodeFreePlane(free_target, canvas, w, h), false));
  for (std::size_t i = 0; i < canvas.size(); ++i) {
    if (canvas[i] != Cell::kOccupied) canvas[i] = free_target[i] ? Cell::kFree : Cell::kUnknown;
  }
  if (options.lossless && canvas != grid.cells()) {
    writer.AddChunk(kResidualChunk,
                    WrapPayload(EncodeResidualPlane(grid.cells(), canvas, w, h), false));
  }
  return EncodedFile{writer.Finish(), std::move(canvas)};
}

// True when `decoded_cells` meet the lossy goals against `grid`.
bool MeetsLossyGoals(const Grid& grid, const Labeling& free_regions,
                     const std::vector<Cell>& decoded_cells) {
  Grid decoded(grid.width(), grid.height(), Cell::kUnknown);
  decoded.mutable_cells() = decoded_cells;
  const GridComparison m = codec_internal::CompareGrids(grid, &free_regions, decoded);
  const bool has_occupied =
      std::find(grid.cells().begin(), grid.cells().end(), Cell::kOccupied) != grid.cells().end();
  const bool has_free = !free_regions.components.empty();
  return m.leaks == 0 && m.unknown_turned_free_share <= kGoalUnknownTurnedFree &&
         (!has_occupied ||
          (m.obstacle_recall_1 >= kGoalRecall && m.obstacle_precision_1 >= kGoalPrecision)) &&
         (!has_free || m.free_iou >= kGoalFreeIou);
}

// The file decodes to the cells the goals were checked on: a last check
// that encoder and decoder agree, so the goals hold for the file itself.
// The limits are the file's own (it was just made from a grid in memory):
// the caller's grid may be larger than the decoder's defaults allow.
Status CheckDecodesTo(const EncodedFile& file) {
  constexpr std::uint64_t kNoLimit = std::numeric_limits<std::uint64_t>::max();
  DecodeLimits own;
  own.max_cells = std::max<std::uint64_t>(own.max_cells, file.decoded_cells.size());
  own.max_chunk_bytes = kNoLimit;
  own.max_inflated_bytes = kNoLimit;
  own.max_segments = kNoLimit;
  own.max_chain_length = kNoLimit;
  LINEMAP_ASSIGN_OR_RETURN(Grid decoded, DecodeLmap(file.bytes, own));
  if (decoded.cells() != file.decoded_cells) {
    return InternalError("lossy encoder and decoder disagree on the decoded grid");
  }
  return Status::Ok();
}

// The lossy file. Files with wall segments and without are searched apart,
// each from the boldest tuning to the first that meets the goals; without
// segments the exactly coded layers also compete, so that file is never
// larger than the lossless one without segments. The file with segments is
// kept when it is at most kSegmentOverhead larger than the one without (the
// walls as lines are what lossy files are for: export, DisPL, planning
// overlays). The goals are checked on the cells each candidate decodes to,
// computed while encoding; the chosen file is decoded once to confirm them.
StatusOr<std::vector<std::uint8_t>> EncodeLossy(const Grid& grid, const EncodeOptions& options) {
  const LossyTuning& mildest = kLossyTunings[std::size(kLossyTunings) - 1];
  const Labeling free_regions = codec_internal::LabelFree(grid);
  const bool two_threads = options.max_threads != 1;
  // The exact file runs beside the line extraction; each tuning's file with
  // segments runs beside the one without. Every task reads only shared
  // constants and writes its own result.
  std::future<StatusOr<EncodedFile>> plain_task = StartTask(
      two_threads, [&] { return EncodeFile(grid, free_regions, options, true, nullptr, mildest); });
  std::vector<LineSegment> lines;
  if (options.store_segments) {
    LINEMAP_ASSIGN_OR_RETURN(lines, ExtractWallLines(grid, options));
  }
  LINEMAP_ASSIGN_OR_RETURN(EncodedFile plain, plain_task.get());
  std::optional<EncodedFile> with_segments;
  bool plain_met = false;
  bool segments_met = !options.store_segments;  // nothing to search
  for (LossyTuning tuning : kLossyTunings) {
    if (plain_met && segments_met) break;
    if (!options.simplify_free_space) {
      tuning.max_hole_cells = 0;
      tuning.smoothing_passes = 0;
    }
    // A candidate and whether it meets the goals.
    const auto candidate = [&](bool segments) -> StatusOr<std::pair<EncodedFile, bool>> {
      LINEMAP_ASSIGN_OR_RETURN(EncodedFile file, EncodeFile(grid, free_regions, options, false,
                                                            segments ? &lines : nullptr, tuning));
      const bool meets = MeetsLossyGoals(grid, free_regions, file.decoded_cells);
      return std::make_pair(std::move(file), meets);
    };
    std::future<StatusOr<std::pair<EncodedFile, bool>>> segments_task;
    if (!segments_met) {
      segments_task = StartTask(two_threads, [&] { return candidate(true); });
    }
    if (!plain_met) {
      LINEMAP_ASSIGN_OR_RETURN(auto without, candidate(false));
      plain_met = without.second;
      if (without.second && without.first.bytes.size() < plain.bytes.size()) {
        plain = std::move(without.first);
      }
    }
    if (segments_task.valid()) {
      LINEMAP_ASSIGN_OR_RETURN(auto with, segments_task.get());
      segments_met = with.second;
      if (with.second) with_segments = std::move(with.first);
    }
  }
  const bool segments_pay =
      with_segments && static_cast<double>(with_segments->bytes.size()) <=
                           (1.0 + kSegmentOverhead) * static_cast<double>(plain.bytes.size());
  const EncodedFile& best = segments_pay ? *with_segments : plain;
  LINEMAP_RETURN_IF_ERROR(CheckDecodesTo(best));
  return best.bytes;
}

}  // namespace

// The caller (EncodeLmap) has checked the grid and the options.
StatusOr<std::vector<std::uint8_t>> EncodeLmapV1(const Grid& grid, const EncodeOptions& options) {
  const LossyTuning& mildest = kLossyTunings[std::size(kLossyTunings) - 1];
  if (!options.lossless) return EncodeLossy(grid, options);
  const bool exact = options.lossless_method == LosslessMethod::kExactLayers;
  const Labeling free_regions = codec_internal::LabelFree(grid);
  // The file without segments is coded beside the line extraction.
  const bool beside = options.max_threads != 1 && options.store_segments;
  std::future<StatusOr<EncodedFile>> plain_task = StartTask(
      beside, [&] { return EncodeFile(grid, free_regions, options, exact, nullptr, mildest); });
  std::optional<EncodedFile> with_lines;
  if (options.store_segments) {
    // Lossless files need no geometry: keep segments only when they pay.
    LINEMAP_ASSIGN_OR_RETURN(std::vector<LineSegment> lines, ExtractWallLines(grid, options));
    LINEMAP_ASSIGN_OR_RETURN(with_lines,
                             EncodeFile(grid, free_regions, options, exact, &lines, mildest));
  }
  LINEMAP_ASSIGN_OR_RETURN(EncodedFile file, plain_task.get());
  if (with_lines && with_lines->bytes.size() < file.bytes.size()) file = std::move(*with_lines);
  return std::move(file.bytes);
}

}  // namespace linemap
