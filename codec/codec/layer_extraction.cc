// Vector layers from a grid (codec/codec/layer_extraction.h).
#include "codec/codec/layer_extraction.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <future>
#include <system_error>
#include <unordered_map>

#include "codec/codec/cell_tiles.h"
#include "codec/codec/layer_coding.h"
#include "codec/codec/layer_order.h"
#include "codec/codec/raster.h"
#include "codec/codec/start_task.h"
#include "codec/codec/wall_cover.h"
#include "linemap/segmentation.h"

namespace linemap {
namespace {

std::optional<CellPoint> RobotCell(const Grid& grid, const EncodeOptions& options) {
  if (!options.robot_pose) return std::nullopt;
  CellPoint robot;
  grid.WorldToCell(options.robot_pose->x, options.robot_pose->y, &robot.col, &robot.row);
  if (!grid.Contains(static_cast<int>(std::nearbyint(robot.col)),
                     static_cast<int>(std::nearbyint(robot.row)))) {
    return std::nullopt;
  }
  return robot;
}

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

double PointSegmentDistance(CellIndex p, CellIndex a, CellIndex b) {
  const double dx = b.col - a.col, dy = b.row - a.row;
  const double px = p.col - a.col, py = p.row - a.row;
  const double len2 = dx * dx + dy * dy;
  const double t = len2 > 0 ? std::clamp((px * dx + py * dy) / len2, 0.0, 1.0) : 0.0;
  return std::hypot(px - t * dx, py - t * dy);
}

// Edge cells this near a segment (cells) count as near it when segments are
// moved or dropped: eval's one cell, and the cells just beyond, whose
// distance to the nearest wall DisPL_ave averages too.
constexpr double kNearCells = 1.5;

// The edge cells of the grid (occupied, with a free 4-neighbour): what
// `linemap eval` measures the walls against (MeasureLayerFidelity).
class EdgeCells {
 public:
  // One pass over the map's rows through plain pointers; the columns off
  // the map's sides are tested apart, so the loop over the others has no
  // branch (most cells are not occupied and decide nothing).
  explicit EdgeCells(const Grid& grid) : grid_(grid), edge_(grid.cells().size(), 0) {
    const int w = grid.width(), h = grid.height();
    const std::vector<Cell> outside(static_cast<std::size_t>(w), Cell::kUnknown);  // never free
    for (int r = 0; r < h; ++r) {
      const Cell* row = grid.cells().data() + grid.Index(0, r);
      const Cell* up = r > 0 ? row - w : outside.data();
      const Cell* down = r + 1 < h ? row + w : outside.data();
      std::uint8_t* out = edge_.data() + grid.Index(0, r);
      const auto edge = [&](int c, bool left_free, bool right_free) {
        const bool free_beside =
            left_free | right_free | (up[c] == Cell::kFree) | (down[c] == Cell::kFree);
        return static_cast<std::uint8_t>(((row[c] == Cell::kOccupied) & free_beside) ? kEdge : 0);
      };
      for (int c = 1; c + 1 < w; ++c) {
        out[c] = edge(c, row[c - 1] == Cell::kFree, row[c + 1] == Cell::kFree);
      }
      out[0] = edge(0, false, w > 1 && row[1] == Cell::kFree);
      if (w > 1) out[w - 1] = edge(w - 1, row[w - 2] == Cell::kFree, false);
    }
  }

  // The edge cells within kNearCells (Euclidean, to the segment) of the
  // segment with their distances, by cell index. They lie within two cells
  // of the segment's rasterisation.
  std::vector<std::pair<std::size_t, double>> Near(const LatticeSegment& s) const {
    // Each candidate once (neighbourhoods of consecutive raster cells
    // overlap in 20 of their 25 cells): marked in the edge bytes while the
    // call runs, rather than sorted.
    std::vector<std::size_t> candidates;
    RasterizeSegment(s.a, s.b, [&](int c, int r) {
      for (int dr = -2; dr <= 2; ++dr) {
        for (int dc = -2; dc <= 2; ++dc) {
          const int x = c + dc, y = r + dr;
          if (!grid_.Contains(x, y)) continue;
          const std::size_t i = grid_.Index(x, y);
          if (edge_[i] == kEdge) {
            edge_[i] = kEdgeSeen;
            candidates.push_back(i);
          }
        }
      }
    });
    std::vector<std::pair<std::size_t, double>> cells;
    const auto width = static_cast<std::size_t>(grid_.width());
    for (std::size_t i : candidates) {
      edge_[i] = kEdge;
      const CellIndex p{static_cast<int>(i % width), static_cast<int>(i / width)};
      const double d = PointSegmentDistance(p, s.a, s.b);
      if (d <= kNearCells) cells.push_back({i, d});
    }
    return cells;
  }

 private:
  static constexpr std::uint8_t kEdge = 1, kEdgeSeen = 2;
  const Grid& grid_;
  // 0, kEdge, or kEdgeSeen for an edge cell already listed by the running
  // Near() (which restores kEdge before it returns).
  mutable std::vector<std::uint8_t> edge_;
};

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

void StraightenSegments(const Grid& grid, const EdgeCells& edges,
                        std::vector<LatticeSegment>* segments) {
  for (LatticeSegment& s : *segments) {
    const int dc = s.b.col - s.a.col, dr = s.b.row - s.a.row;
    if (dc == 0 || dr == 0) continue;
    const bool col_main = std::abs(dc) >= std::abs(dr);
    const int minor = col_main ? dr : dc;
    if (std::abs(minor) > 2) continue;
    const std::vector<std::pair<std::size_t, double>> near = edges.Near(s);
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

// Drops, fewest near edge cells first, each segment such that every edge
// cell near it has another kept segment no more than kMoveSlack farther
// than the nearest of all the segments was (and within one cell when that
// one was): a broken, doubled or overlapping wall piece costs some 20 bits
// in WALL and adds little to what eval measures. Measured with
// StraightenSegments (above); dropping every segment whose edge cells
// within one cell others hold saved 3,200 WALL bytes but cost 750 CELL
// bytes and doubled DisPL_ave on some maps (nav2/depot 0.13 -> 0.29).
void DropRedundantSegments(const EdgeCells& edges, std::vector<LatticeSegment>* segments) {
  // Every (edge cell, segment near it) pair, grouped by cell: flat arrays,
  // not hash maps, since a large map has millions of pairs.
  std::vector<NearPair> pairs;
  std::vector<std::size_t> first(segments->size() + 1,
                                 0);  // segment i: pairs [first[i], first[i+1])
  for (std::size_t i = 0; i < segments->size(); ++i) {
    for (const auto& [c, d] : edges.Near((*segments)[i])) pairs.push_back({c, i, d});
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
  StraightenSegments(grid, EdgeCells(grid), &segments);
  return segments;
}

// Room and furniture borders are stored as polygons (spec/format.md 5.3):
// a room's traced border follows every cell step of its walls, and coded
// step by step it costs more than the cells it would spare the tile coder;
// its Douglas-Peucker polygon (vertices on the chain, every chain cell
// within kRoomTolerance of it) keeps the border within a few cells at a few
// vertices per wall. Measured on 8 maps of ../shared/maps (total bytes of
// the default files): tolerance 1 cell 67,157, 2 cells 64,936, 3 cells
// 64,148; 2 keeps a room's outline within 10 cm at 5 cm per cell.
constexpr double kRoomTolerance = 2.0;  // cells
// Furniture is simplified within one cell, or half a cell where that
// would leave some of the object's cells outside (FurniturePolygon).
constexpr double kPolygonTolerance = 1.0;  // cells

std::vector<CellIndex> SimplifyClosedChain(const std::vector<CellIndex>& chain,
                                           double tolerance = kPolygonTolerance) {
  const std::size_t n = chain.size();
  if (n <= 3) return chain;
  std::size_t far = 0;
  double far_d = -1;
  for (std::size_t i = 1; i < n; ++i) {
    const double d = std::hypot(chain[i].col - chain[0].col, chain[i].row - chain[0].row);
    if (d > far_d) {
      far_d = d;
      far = i;
    }
  }
  std::vector<bool> keep(n, false);
  keep[0] = keep[far] = true;
  // Spans (a, b) of chain indices, b == n meaning index 0 again.
  std::vector<std::pair<std::size_t, std::size_t>> spans = {{0, far}, {far, n}};
  while (!spans.empty()) {
    const auto [a, b] = spans.back();
    spans.pop_back();
    std::size_t worst = 0;
    double worst_d = tolerance;
    for (std::size_t i = a + 1; i < b; ++i) {
      const double d = PointSegmentDistance(chain[i], chain[a], chain[b % n]);
      if (d > worst_d) {
        worst_d = d;
        worst = i;
      }
    }
    if (worst == 0) continue;
    keep[worst] = true;
    spans.push_back({a, worst});
    spans.push_back({worst, b});
  }
  std::vector<CellIndex> polygon;
  for (std::size_t i = 0; i < n; ++i) {
    if (keep[i]) polygon.push_back(chain[i]);
  }
  return polygon;
}

// True when the fill of `chain` (FillChain, spec 8.2) holds every cell.
bool FillHolds(const std::vector<CellIndex>& chain, const std::vector<CellIndex>& cells) {
  const BoundingBox box = BoxOfCells(chain);
  const int w = box.max_col - box.min_col + 1;
  std::vector<std::uint8_t> in(static_cast<std::size_t>(w) * (box.max_row - box.min_row + 1), 0);
  FillChain(chain, [&](int c, int r) {
    in[static_cast<std::size_t>(r - box.min_row) * w + (c - box.min_col)] = 1;
  });
  for (const CellIndex& c : cells) {
    if (c.col < box.min_col || c.col > box.max_col || c.row < box.min_row || c.row > box.max_row ||
        !in[static_cast<std::size_t>(c.row - box.min_row) * w + (c.col - box.min_col)]) {
      return false;
    }
  }
  return true;
}

// A furniture outline's polygon: the simplest (tolerance 1, then 1/2, then
// every cell) whose outline still encloses all the object's cells, so a
// thin object (a shelf two cells deep) keeps its area.
std::vector<CellIndex> FurniturePolygon(const FurnitureBlob& blob) {
  for (const double tolerance : {kPolygonTolerance, 0.5}) {
    std::vector<CellIndex> polygon = SimplifyClosedChain(blob.outline, tolerance);
    if (FillHolds(ChainOfPolygon(polygon), blob.cells)) return polygon;
  }
  return blob.outline;
}

// Rooms and furniture from SegmentMap(); chains the file cannot store (an
// open or broken chain) are left out rather than failing the save.
Status RoomAndFurnitureLayers(const Grid& grid, const EncodeOptions& options,
                              VectorLayers* layers) {
  SegmentationOptions seg_options;
  seg_options.robot = RobotCell(grid, options);
  LINEMAP_ASSIGN_OR_RETURN(Segmentation seg, SegmentMap(grid, seg_options));
  for (RoomBorder& room : seg.rooms) {
    if (!IsStorableChain(room.chain, grid.width(), grid.height())) continue;
    // Within a tolerance T the rooms' outlines may stray as far as their
    // cells plus one: T = 3 files 4 % smaller over the 25 maps of
    // ../shared/maps (T + 2 saved 1 % more; furniture within T instead of
    // one cell saved nothing, its polygons must enclose its cells).
    const double tolerance =
        std::max(kRoomTolerance, static_cast<double>(options.tolerance_cells + 1));
    std::vector<CellIndex> polygon = SimplifyClosedChain(room.chain, tolerance);
    std::vector<CellIndex> chain = ChainOfPolygon(polygon);
    layers->rooms.push_back(
        {static_cast<std::uint32_t>(room.id), room.kind, std::move(polygon), std::move(chain)});
  }
  // The file lists rooms by increasing id (the paper's method numbers
  // none), renumbered 1, 2, ... if two share one.
  std::stable_sort(layers->rooms.begin(), layers->rooms.end(),
                   [](const RoomOutline& a, const RoomOutline& b) { return a.id < b.id; });
  bool increasing = true;
  for (std::size_t i = 1; i < layers->rooms.size(); ++i) {
    increasing = increasing && layers->rooms[i].id > layers->rooms[i - 1].id;
  }
  std::unordered_map<std::uint32_t, std::int32_t> stored_id;  // segmentation's id -> file's
  for (std::size_t k = 0; k < layers->rooms.size(); ++k) {
    const std::uint32_t id = layers->rooms[k].id;
    if (!increasing) layers->rooms[k].id = static_cast<std::uint32_t>(k + 1);
    stored_id.emplace(id, static_cast<std::int32_t>(layers->rooms[k].id));
  }
  for (FurnitureBlob& blob : seg.blobs) {
    if (!IsStorableChain(blob.outline, grid.width(), grid.height())) continue;
    std::vector<CellIndex> polygon = FurniturePolygon(blob);
    std::vector<CellIndex> outline = ChainOfPolygon(polygon);
    // Room ids start at 1; 0 is no room, and so is a room the file cannot
    // store (an object naming it would name another room of a block after).
    const auto room =
        blob.room > 0 ? stored_id.find(static_cast<std::uint32_t>(blob.room)) : stored_id.end();
    layers->furniture.push_back({static_cast<std::uint32_t>(layers->furniture.size()),
                                 room == stored_id.end() ? -1 : room->second, std::move(polygon),
                                 std::move(outline)});
  }
  OrderFurnitureForCoding(&layers->furniture);
  return Status::Ok();
}

}  // namespace

LatticeSegment ToLattice(const LineSegment& line, int width, int height) {
  auto clamp = [](double v, int hi) {
    const double r = std::nearbyint(v);
    return static_cast<int>(std::clamp(r, 0.0, static_cast<double>(hi)));
  };
  return LatticeSegment{{clamp(line.x1, width - 1), clamp(line.y1, height - 1)},
                        {clamp(line.x2, width - 1), clamp(line.y2, height - 1)}};
}

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
  line_options.robot = RobotCell(grid, options);
  LINEMAP_ASSIGN_OR_RETURN(LineExtraction lines, ExtractLines(grid, line_options));
  return std::move(lines.segments);
}

namespace {

// JoinSegments without the canonical order: a map's blocks are ordered
// once, all together (ExtractVectorLayers), not each on its own first.
std::vector<WallPolyline> JoinSegmentsUnordered(const std::vector<LatticeSegment>& segments) {
  const auto key = [](CellIndex c) {
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(c.row)) << 32) |
           static_cast<std::uint32_t>(c.col);
  };
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> at_end;
  for (std::size_t i = 0; i < segments.size(); ++i) {
    at_end[key(segments[i].a)].push_back(i);
    if (!(segments[i].a == segments[i].b)) at_end[key(segments[i].b)].push_back(i);
  }
  std::vector<bool> used(segments.size(), false);
  // The other end of an unused segment at `p`, marking it used.
  const auto next_from = [&](CellIndex p, CellIndex* out) {
    for (std::size_t i : at_end[key(p)]) {
      if (used[i]) continue;
      used[i] = true;
      *out = segments[i].a == p ? segments[i].b : segments[i].a;
      return true;
    }
    return false;
  };
  std::vector<WallPolyline> walls;
  for (std::size_t i = 0; i < segments.size(); ++i) {
    if (used[i]) continue;
    used[i] = true;
    std::vector<CellIndex> forward = {segments[i].a, segments[i].b};
    CellIndex q;
    while (next_from(forward.back(), &q)) forward.push_back(q);
    std::vector<CellIndex> backward;
    while (next_from(backward.empty() ? forward.front() : backward.back(), &q)) {
      backward.push_back(q);
    }
    std::reverse(backward.begin(), backward.end());
    backward.insert(backward.end(), forward.begin(), forward.end());
    walls.push_back({std::move(backward)});
  }
  return walls;
}

}  // namespace

std::vector<WallPolyline> JoinSegments(const std::vector<LatticeSegment>& segments) {
  std::vector<WallPolyline> walls = JoinSegmentsUnordered(segments);
  CanonicalizeWalls(&walls);
  return walls;
}

namespace {

// Walls for the edge cells that no wall holds within one cell and no
// furniture outline encloses (wall_cover.h). On the 25 maps of
// ../shared/maps they are nearly all lone occupied cells in free space (scan
// specks): covering them raised the share of edge cells within one cell of
// a wall or in furniture from 0.34-1.00 (10 maps at 0.99 or more) to
// 0.9994-1.0000 on every map and lowered DisPL_ave on every map (willow-2010
// 210 -> 2.8 cm, willow-full-0.05 10.5 -> 0.8 cm), for 3.1 % more bytes in
// the 25 default files (190,249 -> 196,194).
void AddCoveringSegments(const Grid& grid, const std::vector<FurnitureObject>& furniture,
                         std::vector<LatticeSegment>* segments) {
  std::vector<std::uint8_t> in_furniture(grid.size(), 0);
  for (const FurnitureObject& object : furniture) {
    FillChain(object.outline, [&](int c, int r) { in_furniture[grid.Index(c, r)] = 1; });
  }
  const std::vector<LatticeSegment> cover = CoveringSegments(grid, *segments, &in_furniture);
  segments->insert(segments->end(), cover.begin(), cover.end());
}

// Drops the segments shorter than `min_cells` (Chebyshev length) that
// share neither end with another segment. Within a tolerance T, a lone
// piece shorter than 2T + 1 cells is clutter at the file's scale (a chair,
// a scan artefact), which the cells keep within T; segments joined to
// others stay, so no polyline is cut, and so do those with an end on the
// border of `grid` (on a map over 2048 cells a side that is a block's, and
// the piece may go on in the next block). Over the 25 maps of ../shared/maps:
// T = 1 150,877 -> 145,772 bytes, T = 3 115,205 -> 108,436 (dropping
// every short segment, joined or not, saved 0.3 % more).
void DropShortLoneSegments(const Grid& grid, int min_cells, std::vector<LatticeSegment>* segments) {
  const auto key = [](CellIndex c) {
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(c.row)) << 32) |
           static_cast<std::uint32_t>(c.col);
  };
  std::vector<std::uint64_t> ends;
  ends.reserve(2 * segments->size());
  for (const LatticeSegment& s : *segments) {
    ends.push_back(key(s.a));
    if (!(s.a == s.b)) ends.push_back(key(s.b));
  }
  std::sort(ends.begin(), ends.end());
  const auto shared = [&](CellIndex c) {
    if (c.col == 0 || c.row == 0 || c.col == grid.width() - 1 || c.row == grid.height() - 1) {
      return true;
    }
    const auto [lo, hi] = std::equal_range(ends.begin(), ends.end(), key(c));
    return hi - lo > 1;
  };
  std::erase_if(*segments, [&](const LatticeSegment& s) {
    const int length = std::max(std::abs(s.a.col - s.b.col), std::abs(s.a.row - s.b.row));
    return length < min_cells && !shared(s.a) && !shared(s.b);
  });
}

// With `order_walls` false the walls are left unordered, zero-length steps
// and all (the caller canonicalises them).
StatusOr<VectorLayers> ExtractWholeMapLayers(const Grid& grid, const EncodeOptions& options,
                                             bool order_walls) {
  VectorLayers layers;
  auto walls_task =
      StartTask(options.max_threads != 1, [&] { return WallSegments(grid, options); });
  const Status rooms = RoomAndFurnitureLayers(grid, options, &layers);
  StatusOr<std::vector<LatticeSegment>> segments = walls_task.get();
  LINEMAP_RETURN_IF_ERROR(rooms);
  if (!segments.ok()) return segments.status();
  // The edge cells are found anew rather than kept from the walls task: a
  // large map's segmentation peaks while that task runs.
  DropRedundantSegments(EdgeCells(grid), &*segments);
  // Within a tolerance the cells keep the scan specks within T cells, and
  // the walls are the map's walls without them: 7,300 of 158,000 bytes at
  // T = 1 over the 25 maps.
  if (options.tolerance_cells == 0) {
    AddCoveringSegments(grid, layers.furniture, &*segments);
  } else {
    DropShortLoneSegments(grid, 2 * options.tolerance_cells + 1, &*segments);
  }
  layers.walls = order_walls ? JoinSegments(*segments) : JoinSegmentsUnordered(*segments);
  return layers;
}

void Shift(std::vector<CellIndex>* points, int dc, int dr) {
  for (CellIndex& p : *points) p = {p.col + dc, p.row + dr};
}

// The map's cells of the block whose first cell is (x0, y0), at most
// kLayerBlockCells a side.
Grid BlockOf(const Grid& grid, int x0, int y0) {
  const int w = std::min(kLayerBlockCells, grid.width() - x0);
  const int h = std::min(kLayerBlockCells, grid.height() - y0);
  Grid block(w, h);
  block.meta = grid.meta;
  for (int r = 0; r < h; ++r) {
    std::copy_n(grid.cells().begin() + static_cast<std::ptrdiff_t>(grid.Index(x0, y0 + r)), w,
                block.mutable_cells().begin() + static_cast<std::ptrdiff_t>(r) * w);
  }
  return block;
}

// Drops the rooms' chains and the objects' outlines, storage included
// (`chain = {}` would keep it: on the 282-Mcell office map 106 MB of
// chains stayed allocated that way); their polygons stay, which is all the
// encoder needs.
void DropChains(VectorLayers* layers) {
  for (RoomOutline& room : layers->rooms) std::vector<CellIndex>().swap(room.chain);
  for (FurnitureObject& object : layers->furniture) {
    std::vector<CellIndex>().swap(object.outline);
  }
}

// Whether every point of `points` lies in the box [x0, x1) x [y0, y1).
bool PointsWithin(const std::vector<CellIndex>& points, int x0, int y0, int x1, int y1) {
  return std::all_of(points.begin(), points.end(), [&](const CellIndex& p) {
    return p.col >= x0 && p.col < x1 && p.row >= y0 && p.row < y1;
  });
}

// Whether every item of `layers` lies in the block's box (polygons and
// walls are drawn inside their points' box, so their hints do too).
bool LayersWithin(const VectorLayers& layers, int x0, int y0, int x1, int y1) {
  for (const WallPolyline& wall : layers.walls) {
    if (!PointsWithin(wall.points, x0, y0, x1, y1)) return false;
  }
  for (const RoomOutline& room : layers.rooms) {
    if (!PointsWithin(room.polygon, x0, y0, x1, y1)) return false;
  }
  for (const FurnitureObject& object : layers.furniture) {
    if (!PointsWithin(object.polygon, x0, y0, x1, y1)) return false;
  }
  return true;
}

}  // namespace

StatusOr<VectorLayers> ExtractBlockLayers(const Grid& block, int x0, int y0,
                                          const EncodeOptions& options, bool with_chains) {
  EncodeOptions block_options = options;
  block_options.robot_pose.reset();  // it names one block's free space only
  LINEMAP_ASSIGN_OR_RETURN(VectorLayers layers, ExtractWholeMapLayers(block, block_options, false));
  DropRepeatedWallPoints(&layers.walls);
  if (!with_chains) DropChains(&layers);
  if (!LayersWithin(layers, 0, 0, block.width(), block.height())) {
    return InternalError("a layer item leaves its block at (" + std::to_string(x0) + ", " +
                         std::to_string(y0) + ")");
  }
  for (RoomOutline& room : layers.rooms) {
    Shift(&room.polygon, x0, y0);
    Shift(&room.chain, x0, y0);
  }
  for (FurnitureObject& object : layers.furniture) {
    Shift(&object.polygon, x0, y0);
    Shift(&object.outline, x0, y0);
  }
  for (WallPolyline& wall : layers.walls) Shift(&wall.points, x0, y0);
  return layers;
}

void AppendBlockLayers(VectorLayers block, VectorLayers* all) {
  std::uint32_t first_id = all->rooms.empty() ? 1 : all->rooms.back().id + 1;
  const std::uint32_t base = first_id;
  for (RoomOutline& room : block.rooms) {
    room.id += base;
    first_id = room.id + 1;
    all->rooms.push_back(std::move(room));
  }
  for (FurnitureObject& object : block.furniture) {
    if (object.room_id >= 0) object.room_id += static_cast<std::int32_t>(base);
    all->furniture.push_back(std::move(object));
  }
  std::move(block.walls.begin(), block.walls.end(), std::back_inserter(all->walls));
}

StatusOr<VectorLayers> ExtractVectorLayers(const Grid& grid, const EncodeOptions& options,
                                           bool with_chains) {
  if (grid.empty()) return VectorLayers{};
  if (grid.width() <= kLayerBlockCells && grid.height() <= kLayerBlockCells) {
    return ExtractWholeMapLayers(grid, options, true);
  }
  // A map larger than a block: the line extractor and the segmentation need
  // tens of bytes per cell, so they run block by block, and walls, rooms and
  // furniture end at the block borders. The blocks are extracted
  // kMaxBlocksAtOnce at a time (one with options.max_threads 1), each
  // block's walls and rooms one after the other on its thread: two blocks
  // at a time hold about what one block held with its walls and rooms on
  // two threads, and keep both cores busy (on the 282-Mcell office map the
  // walls task ended long before the rooms).
  // They are appended in block order, so the result does not depend on the
  // threads.
  const int blocks_x = (grid.width() + kLayerBlockCells - 1) / kLayerBlockCells;
  const int blocks_y = (grid.height() + kLayerBlockCells - 1) / kLayerBlockCells;
  const std::uint64_t blocks = static_cast<std::uint64_t>(blocks_x) * blocks_y;
  EncodeOptions block_options = options;
  block_options.max_threads = 1;
  std::vector<StatusOr<VectorLayers>> block_layers(blocks, VectorLayers{});
  const int threads = options.max_threads == 1 ? 1 : kMaxBlocksAtOnce;
  ForEachIndexParallel(blocks, threads, [&](std::uint64_t k) {
    const int x0 = static_cast<int>(k % blocks_x) * kLayerBlockCells;
    const int y0 = static_cast<int>(k / blocks_x) * kLayerBlockCells;
    block_layers[k] = ExtractBlockLayers(BlockOf(grid, x0, y0), x0, y0, block_options, with_chains);
  });
  VectorLayers all;
  for (StatusOr<VectorLayers>& layers : block_layers) {
    if (!layers.ok()) return layers.status();
    AppendBlockLayers(std::move(*layers), &all);
  }
  CanonicalizeWalls(&all.walls);
  OrderFurnitureForCoding(&all.furniture);  // which makes each object's outline anew
  if (!with_chains) DropChains(&all);
  return all;
}

std::vector<std::pair<std::string, std::string>> MetadataOf(const EncodeOptions& options) {
  std::vector<std::pair<std::string, std::string>> entries;
  if (!options.creator.empty()) entries.emplace_back("creator", options.creator);
  if (!options.time.empty()) entries.emplace_back("time", options.time);
  if (!options.frame_id.empty()) entries.emplace_back("frame_id", options.frame_id);
  if (options.robot_pose) {
    char text[96];
    std::snprintf(text, sizeof(text), "%.17g %.17g %.17g", options.robot_pose->x,
                  options.robot_pose->y, options.robot_pose->yaw);
    entries.emplace_back("robot_pose", text);
  }
  return entries;
}

}  // namespace linemap
