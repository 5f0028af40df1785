// linemap's wall-line extractor: fewer segments than RM-Line with a
// guaranteed L-infinity bound (issue 5).
//
// Pipeline. Invariant from step 3 on: every chained edge cell is owned by one
// group and lies within epsilon of the group's segment.
//  1. Speckle: 8-connected edge components with fewer than
//     min_component_cells cells are not chained; at the end those within
//     epsilon of a segment count as covered, the rest are left to the
//     furniture-blob layer and counted (LineExtraction::cells_left_to_blobs).
//  2. Chains: the other edge cells are traced into ordered 8-connected
//     chains, starting from contour ends (edge linking as in EDLines, Akinlar
//     & Topal 2011), going straight on where possible so that the two sides
//     of a two-cell wall become two chains, not one zig-zag.
//  3. Split: each chain is cut greedily into the longest pieces whose cells
//     lie within split_epsilon_cells of the piece's total-least-squares line
//     (the L-infinity polyline criterion of Imai & Iri 1986, with TLS lines
//     in place of chords; greedy is optimal when validity is hereditary,
//     which holds closely for TLS). Prefix moments make each trial fit O(1);
//     doubling then bisection finds each piece in O(n log n). At 0.1 cells
//     the pieces are (nearly) exact runs, e.g. single steps of a staircase.
//  4. Merge (split-and-merge, Pavlidis & Horowitz 1974): pieces whose ends
//     are within merge_gap_cells of the other segment are refitted together
//     (TLS over the union: Eigen on the 2x2 covariance) and merged, cheapest
//     first (equal queue keys in piece-id order), when every cell stays within
//     epsilon_cells AND the summed cell-to-segment distance grows by at most
//     max_added_cost_cells * epsilon_cells^2 (a wall ragged by +-k cells
//     merges in steps that move ~k cells by ~k each), or
//     stays within noise_merge_factor times the cells' summed local noise
//     (distance to the TLS line of a window of 2 * noise_window_cells + 1
//     chain cells; 0 where the window never turns back, as a staircase
//     does not): what a merge adds within that noise is not charged
//     (NoiseSlack), so a ragged wall becomes one segment while a clean
//     slanted wall keeps its steps. The cost cap is what keeps DisPL_ave
//     low: without it the L-infinity bound alone would merge the two sides
//     of a wall into a centre line.
//     Rate-distortion budget: making every merge that adds at most a price
//     per segment, cheapest first, greedily minimises summed distance +
//     price * segments, the Lagrangian form of "fewest segments for a given
//     summed distance" (Shoham & Gersho 1988 for bit allocation; Perez &
//     Vidal 1994 for polygonal approximation). Merges adding at most
//     free_merge_cost_cells (the price) are always made; dearer ones only
//     while the map's mean distance stays within target_mean_distance_cells
//     + (1 + distance_growth_factor) times that of the unmerged pieces. So on
//     a clean map a slanted wall keeps an exact segment per long step while
//     short steps and noisy walls merge.
//  5. Prune: a segment whose cells all lie within epsilon of other segments
//     (and cost at most prune_added_cost_cells more there) is dropped,
//     smallest first, handing its cells over.
//  6. Specks: a segment of at most speck_max_cells cells that holds whole
//     edge components, with no other segment within speck_min_gap_cells of
//     its cells, is a speck, not a wall: it is left to the furniture layer
//     (its cells become speckle) when that adds at most
//     speck_max_added_cells to the summed distance, cheapest first, while
//     the distance budget of step 4 allows. Clean maps have little budget
//     left, so their isolated specks keep their segments; noisy SLAM maps,
//     whose speckle already leaves a large mean distance, hand many over.
//  7. Polish: each line moves towards the least-absolute-distance line of its
//     cells (iteratively reweighted TLS), only while the bound holds.
//  8. Corners: wall ends that meet at a corner are extended to it.
// Parameters (LineExtractionOptions, all in cells; defaults chosen on
// ../shared/maps with tools/bench_lines): epsilon_cells 1 (the guaranteed
// bound), split_epsilon_cells 0.1 (pieces are exact runs; 0.3 in
// StraightWalls), merge_gap_cells 8 (below a doorway at 5 cm/cell),
// max_added_cost_cells 3 (times epsilon^2), free_merge_cost_cells 0.95
// (times epsilon^2; the price of a segment), target_mean_distance_cells 0.05
// (times epsilon) and distance_growth_factor 1 (no budget in StraightWalls),
// prune_added_cost_cells 1.5 (3 in StraightWalls; times epsilon^2),
// noise_merge_factor 1.5 with noise_window_cells 4, noise_min_mean_cells
// 0.35 and noise_min_cells 16 (a wall's own noise is forgiven, see
// NoiseSlack; off in StraightWalls), min_component_cells 2 (lone cells are
// speckle), speck_max_cells 3 with speck_min_gap_cells 2 and
// speck_max_added_cells 64 (off in StraightWalls), corner_join_cells 3.
// Time: linear in the edge cells apart from the merge queue (log factor) and
// the re-evaluation of a group against its neighbours after each merge. The
// merge's cost is mostly that candidate search (tile scans and O(1) filters
// per pair); see MergeGroups and MergeQueue for how it is kept small.
#include "codec/lines/linemap_extractor.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <numbers>
#include <span>
#include <utility>

#include "codec/lines/line_fit.h"
#include "codec/lines/segment_index.h"

namespace linemap::lines_internal {
namespace {

// 4-neighbours first, then diagonals.
constexpr int kDcol[8] = {1, 0, -1, 0, 1, -1, -1, 1};
constexpr int kDrow[8] = {0, 1, 0, -1, 1, 1, -1, -1};

// Fits computed from prefix sums and from PointMoments may differ by
// rounding; the bound is guaranteed up to this many cells.
constexpr double kRoundingSlack = 1e-9;

// Angle between two of the 8 directions of kDcol/kDrow, in 45-degree steps (0..4).
int TurnSteps(int a, int b) {
  // Each direction's angle from +x in 45-degree steps (counter-clockwise in
  // (col, row)).
  constexpr int kOctant[8] = {0, 2, 4, 6, 1, 3, 5, 7};
  const int diff = (kOctant[a] - kOctant[b] + 8) % 8;
  return std::min(diff, 8 - diff);
}

// std::max and std::min for doubles as value selects: the same results
// (including the sign of zero and NaNs), but compiled to maxsd/minsd
// rather than to branches, which the merge's data-dependent tests
// mispredict.
double MaxOf(double a, double b) { return b > a ? b : a; }
double MinOf(double a, double b) { return b < a ? b : a; }

struct CellXY {
  int col;
  int row;
};

CellXY CellOfIndex(std::uint32_t index, int width) {
  return {static_cast<int>(index % static_cast<std::uint32_t>(width)),
          static_cast<int>(index / static_cast<std::uint32_t>(width))};
}

// The edge cells' indices in raster order: later passes visit only these.
std::vector<std::uint32_t> EdgeCellList(const EdgeMap& edges) {
  std::vector<std::uint32_t> list;
  list.reserve(edges.edge_count);
  const std::uint8_t* flags = edges.is_edge.data();
  const std::size_t n = edges.is_edge.size();
  std::size_t i = 0;
  for (; i + 8 <= n; i += 8) {
    std::uint64_t word;  // most of a map is not edge: skip 8 cells at a time
    std::memcpy(&word, flags + i, sizeof(word));
    if (word == 0) continue;
    for (std::size_t k = i; k < i + 8; ++k) {
      if (flags[k]) list.push_back(static_cast<std::uint32_t>(k));
    }
  }
  for (; i < n; ++i) {
    if (flags[i]) list.push_back(static_cast<std::uint32_t>(i));
  }
  return list;
}

// Flags (1) in `large` the cells of the 8-connected edge components with at
// least `min_cells` cells; `large` is width*height and all zero on entry.
void FlagLargeComponents(const EdgeMap& edges, const std::vector<std::uint32_t>& edge_cells,
                         int min_cells, std::vector<std::uint8_t>* large) {
  constexpr std::uint8_t kSeen = 2;
  std::vector<std::uint32_t> component;
  for (std::uint32_t seed : edge_cells) {
    if ((*large)[seed]) continue;
    component.clear();
    component.push_back(seed);
    (*large)[seed] = kSeen;
    for (std::size_t head = 0; head < component.size(); ++head) {
      const CellXY c = CellOfIndex(component[head], edges.width);
      for (int k = 0; k < 8; ++k) {
        const int col = c.col + kDcol[k], row = c.row + kDrow[k];
        if (col < 0 || row < 0 || col >= edges.width || row >= edges.height) continue;
        const std::size_t n = static_cast<std::size_t>(row) * edges.width + col;
        if (edges.is_edge[n] && !(*large)[n]) {
          (*large)[n] = kSeen;
          component.push_back(static_cast<std::uint32_t>(n));
        }
      }
    }
    const bool keep = static_cast<int>(component.size()) >= min_cells;
    for (std::uint32_t index : component) (*large)[index] = keep ? 1 : kSeen;
  }
  for (std::uint32_t index : edge_cells) {
    if ((*large)[index] == kSeen) (*large)[index] = 0;
  }
}

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

// A candidate wall: its cells, their moments and the fitted segment.
// The fields a merge's lower bound reads for every candidate pair come
// first, near each other.
struct Group {
  PointMoments moments;
  double cost = 0;          // sum of the cells' distances to `segment` (cells)
  double noise = 0;         // sum of the cells' local residuals (ChainMoments::LocalResidual)
  double max_residual = 0;  // largest distance of a cell to `line`
  FittedLine line;
  LineSegment segment;
  std::vector<CellXY> cells;  // (col, row): no division in the hot loops
  bool alive = true;
};

// Distances of cells to a line, and the extent of their projections.
struct LineSweep {
  double cost = 0;   // summed distance
  double worst = 0;  // largest distance
  double t_min = 0, t_max = 0;
  bool any = false;
};

// Adds `cells` to `sweep`; false as soon as a cell is farther than epsilon
// or the summed distance passes max_cost.
bool SweepCells(const FittedLine& line, const std::vector<CellXY>& cells, double epsilon,
                double max_cost, LineSweep* sweep) {
  const Eigen::Vector2d& c = line.centroid;
  const Eigen::Vector2d& u = line.direction;
  for (const CellXY& cell : cells) {
    const double dx = cell.col - c.x(), dy = cell.row - c.y();
    const double d = std::abs(-u.y() * dx + u.x() * dy);
    sweep->cost += d;
    if (d > epsilon + kRoundingSlack || sweep->cost > max_cost) return false;
    sweep->worst = MaxOf(sweep->worst, d);
    const double t = u.x() * dx + u.y() * dy;
    sweep->t_min = sweep->any ? MinOf(sweep->t_min, t) : t;
    sweep->t_max = sweep->any ? MaxOf(sweep->t_max, t) : t;
    sweep->any = true;
  }
  return true;
}

void SetLine(Group* group, const FittedLine& line, const LineSweep& sweep) {
  const Eigen::Vector2d& c = line.centroid;
  const Eigen::Vector2d& u = line.direction;
  group->line = line;
  group->max_residual = sweep.worst;
  group->cost = sweep.cost;
  group->segment = {c.x() + sweep.t_min * u.x(), c.y() + sweep.t_min * u.y(),
                    c.x() + sweep.t_max * u.x(), c.y() + sweep.t_max * u.y()};
}

// Fits `line` and `segment` of a group from its cells; false when some cell
// is farther than epsilon from the line.
bool RefitGroup(Group* group, double epsilon) {
  const FittedLine line = group->moments.Fit();
  if (line.mean_squared_residual > epsilon * epsilon + kRoundingSlack) return false;
  LineSweep sweep;
  if (!SweepCells(line, group->cells, epsilon, std::numeric_limits<double>::infinity(), &sweep)) {
    return false;
  }
  SetLine(group, line, sweep);
  return true;
}

// Buckets of group ids by the tiles their segments pass through; entries go
// stale when groups merge and are re-checked by the reader.
class GroupTiles {
 public:
  GroupTiles(int width, int height, int tile) : tile_(tile) {
    tiles_x_ = std::max(1, (width + tile - 1) / tile);
    tiles_y_ = std::max(1, (height + tile - 1) / tile);
    buckets_.resize(static_cast<std::size_t>(tiles_x_) * tiles_y_);
  }

  void Add(std::uint32_t id, const LineSegment& s) {
    ForEachTile(s, [&](int tile) {
      Bucket& bucket = buckets_[tile];
      if (bucket.size == bucket.capacity) Grow(&bucket);
      arena_[bucket.begin + bucket.size++] = id;
    });
  }

  // Add() for groups 0, 1, ... in order, their buckets laid out in tile
  // order, each non-empty one with room for a few merged groups (an empty
  // one grows at its first Add()).
  void AddAll(const std::vector<Group>& groups) {
    for (const Group& group : groups) {
      ForEachTile(group.segment, [&](int tile) { ++buckets_[tile].capacity; });
    }
    std::uint32_t begin = 0;
    for (Bucket& bucket : buckets_) {
      bucket.begin = begin;
      if (bucket.capacity > 0) bucket.capacity += kBucketSlack;
      begin += bucket.capacity;
    }
    arena_.resize(begin);
    for (std::uint32_t id = 0; id < groups.size(); ++id) Add(id, groups[id].segment);
  }

  // Calls visit(id) for the live groups (`alive`, one flag per group id;
  // compact, so the scan touches no Group) registered in the tiles within
  // `radius` of either end of `s` (an id may repeat across tiles; tiles
  // near both ends are scanned once). Dead and repeated entries are dropped
  // from the buckets on the way, so merged groups do not pile up. `visit`
  // must not call Add(): a bucket that grows moves in the arena under the
  // scan.
  template <typename Visit>
  void ForEachNearEnds(const LineSegment& s, double radius, const std::vector<std::uint8_t>& alive,
                       Visit visit) {
    if (mark_.size() < alive.size()) mark_.resize(alive.size(), 0);
    const TileRange first = RangeNear(s.x1, s.y1, radius);
    const TileRange second = RangeNear(s.x2, s.y2, radius);
    for (int ty = first.y0; ty <= first.y1; ++ty) {
      for (int tx = first.x0; tx <= first.x1; ++tx) ScanBucket(tx, ty, alive, visit);
    }
    for (int ty = second.y0; ty <= second.y1; ++ty) {
      for (int tx = second.x0; tx <= second.x1; ++tx) {
        if (!first.Contains(tx, ty)) ScanBucket(tx, ty, alive, visit);
      }
    }
  }

 private:
  struct TileRange {
    int x0, x1, y0, y1;
    bool Contains(int tx, int ty) const { return tx >= x0 && tx <= x1 && ty >= y0 && ty <= y1; }
  };
  TileRange RangeNear(double x, double y, double radius) const {
    return {
        Clamp((x - radius + 0.5) / tile_, tiles_x_), Clamp((x + radius + 0.5) / tile_, tiles_x_),
        Clamp((y - radius + 0.5) / tile_, tiles_y_), Clamp((y + radius + 0.5) / tile_, tiles_y_)};
  }
  template <typename Visit>
  void ScanBucket(int tx, int ty, const std::vector<std::uint8_t>& alive, Visit& visit) {
    Bucket& bucket = buckets_[static_cast<std::size_t>(ty) * tiles_x_ + tx];
    std::uint32_t* ids = arena_.data() + bucket.begin;
    ++stamp_;
    std::uint32_t kept = 0;
    for (std::uint32_t i = 0; i < bucket.size; ++i) {
      const std::uint32_t id = ids[i];
      if (!alive[id] || mark_[id] == stamp_) continue;
      mark_[id] = stamp_;
      ids[kept++] = id;
      visit(id);
    }
    bucket.size = kept;
  }
  // Calls visit(tile) for the tiles of points every half tile along s (each
  // tile once per run of equal tiles).
  template <typename Visit>
  void ForEachTile(const LineSegment& s, Visit visit) const {
    const double length = std::sqrt((s.x2 - s.x1) * (s.x2 - s.x1) + (s.y2 - s.y1) * (s.y2 - s.y1));
    const int steps = 1 + static_cast<int>(length / (0.5 * tile_));
    int last = -1;
    for (int k = 0; k <= steps; ++k) {
      const double t = static_cast<double>(k) / steps;
      const int tile = TileIndex(s.x1 + t * (s.x2 - s.x1), s.y1 + t * (s.y2 - s.y1));
      if (tile != last) visit(tile);
      last = tile;
    }
  }
  // A tile's group ids: arena_[begin, begin + size), room for `capacity`
  // (one arena rather than a vector per tile).
  struct Bucket {
    std::uint32_t begin = 0, size = 0, capacity = 0;
  };
  static constexpr std::uint32_t kBucketSlack = 4;
  // Moves a full bucket to the arena's end with twice the room.
  void Grow(Bucket* bucket) {
    const std::uint32_t capacity = std::max<std::uint32_t>(kBucketSlack, 2 * bucket->capacity);
    const std::uint32_t begin = static_cast<std::uint32_t>(arena_.size());
    arena_.resize(arena_.size() + capacity);
    std::copy_n(arena_.begin() + bucket->begin, bucket->size, arena_.begin() + begin);
    bucket->begin = begin;
    bucket->capacity = capacity;
  }
  // floor(t) clamped to [0, tiles - 1] (truncation is floor for t >= 0).
  static int Clamp(double t, int tiles) {
    if (!(t > 0)) return 0;
    if (t >= tiles - 1) return tiles - 1;
    return static_cast<int>(t);
  }
  int TileIndex(double x, double y) const {
    return Clamp((y + 0.5) / tile_, tiles_y_) * tiles_x_ + Clamp((x + 0.5) / tile_, tiles_x_);
  }

  int tile_;
  int tiles_x_ = 1, tiles_y_ = 1;
  std::vector<Bucket> buckets_;
  std::vector<std::uint32_t> arena_;
  std::vector<std::uint32_t> mark_;  // per group: the last bucket scan that kept it
  std::uint32_t stamp_ = 0;
};

// A group's segment and what the merge's candidate filters derive from it,
// computed once per group rather than once per pair.
struct SegmentShape {
  LineSegment s;
  double dx = 0, dy = 0;  // s.x2 - s.x1, s.y2 - s.y1
  double length_sq = 0;
  // sin of the largest angle a line within epsilon of both ends may make
  // with the group's line (see DirectionsCompatible); >= 1: any angle.
  double max_sine = 1;
  Eigen::Vector2d direction = Eigen::Vector2d::UnitX();  // the group's line's
};

SegmentShape ShapeOf(const Group& g, double epsilon) {
  SegmentShape shape;
  shape.s = g.segment;
  shape.dx = g.segment.x2 - g.segment.x1;
  shape.dy = g.segment.y2 - g.segment.y1;
  shape.length_sq = shape.dx * shape.dx + shape.dy * shape.dy;
  const double reach = 2 * (epsilon + g.max_residual);
  shape.max_sine = shape.length_sq <= reach * reach ? 1.0 : reach / std::sqrt(shape.length_sq);
  shape.direction = g.line.direction;
  return shape;
}

// Selects rather than branches (the candidate filters run on many pairs
// with data-dependent outcomes): the same value as clamping t to [0, 1] for
// a segment of positive length, 0 for a point.
double SquaredDistanceToSegment(double x, double y, const SegmentShape& shape) {
  const LineSegment& s = shape.s;
  const double along = ((x - s.x1) * shape.dx + (y - s.y1) * shape.dy) / shape.length_sq;
  const double t = shape.length_sq > 0 ? MinOf(MaxOf(along, 0.0), 1.0) : 0.0;
  const double ex = x - (s.x1 + t * shape.dx), ey = y - (s.y1 + t * shape.dy);
  return ex * ex + ey * ey;
}

// What a merge may cost; see MergeGroups.
struct MergeLimits {
  double epsilon = 1;          // the bound, cells
  double max_added = 3;        // summed distance a merge may add at most, cells
  double noise_factor = 0;     // merged cost may reach this times the summed local noise
  double noise_min_mean = 0;   // ... when the merged cells' mean noise is at least this
  double noise_min_cells = 0;  // ... and they are at least this many
  double free_added = 3;       // merges adding at most this (cells) are always made
  // Dearer merges are made only while the chained cells' summed distance to
  // their segments stays at most this (cells).
  double total_budget = std::numeric_limits<double>::infinity();
};

// A necessary condition for a merge, in O(1): a line within epsilon of both
// extreme cells of a group (length l along its line, residual r) makes an
// angle theta with that line such that l * sin(theta) <= 2 (epsilon + r);
// so the two groups' directions may differ by at most the sum of the two
// such angles (SegmentShape::max_sine).
bool DirectionsCompatible(const SegmentShape& shape_a, const SegmentShape& shape_b) {
  const double sa = shape_a.max_sine, sb = shape_b.max_sine;
  // angle <= A + B  <=>  cos(angle) >= cos(A + B) = cos A cos B - sin A sin B
  // (evaluated whatever sa and sb, so that the result is a select).
  const double cosine = std::abs(shape_a.direction.dot(shape_b.direction));
  const double limit = std::sqrt(MaxOf(0.0, (1 - sa * sa) * (1 - sb * sb))) - sa * sb - 1e-12;
  return (sa >= 1) | (sb >= 1) | (cosine >= limit);
}

// A segment's bounding box (kept apart from SegmentShape: the first filter
// reads only this, for many more pairs).
struct Box {
  double x_min = 0, x_max = 0, y_min = 0, y_max = 0;
};
Box BoxOf(const LineSegment& s) {
  return {MinOf(s.x1, s.x2), MaxOf(s.x1, s.x2), MinOf(s.y1, s.y2), MaxOf(s.y1, s.y2)};
}

// False when the segments' bounding boxes, one grown by `gap`, are apart:
// then no end of one is within `gap` of the other (a cheap first test).
bool BoxesWithinGap(const Box& a, const Box& b, double gap) {
  return (a.x_min - gap <= b.x_max) & (b.x_min <= a.x_max + gap) & (a.y_min - gap <= b.y_max) &
         (b.y_min <= a.y_max + gap);
}

// True when an end of one segment is within `gap` of the other segment.
// (BoxesWithinGap is the cheap first test.)
bool EndsWithinGap(const SegmentShape& a, const SegmentShape& b, double gap) {
  const double gap_sq = gap * gap;
  return SquaredDistanceToSegment(a.s.x1, a.s.y1, b) <= gap_sq ||
         SquaredDistanceToSegment(a.s.x2, a.s.y2, b) <= gap_sq ||
         SquaredDistanceToSegment(b.s.x1, b.s.y1, a) <= gap_sq ||
         SquaredDistanceToSegment(b.s.x2, b.s.y2, a) <= gap_sq;
}

// The part of a merge's added distance (`added`, exact or a lower bound)
// that is charged as a merge's cost: what it adds beyond what the parts'
// local noise allows (NoiseSlack: noise_factor times their summed noise,
// less their cost; only for groups of noise_min_cells cells or more whose
// mean noise is at least noise_min_mean). A wall ragged by its own noise
// merges for free up to that noise; a clean staircase, whose noise is 0
// (ChainMoments::LocalResidual), pays for every step it loses. Equal to
// `added` when noise_factor is 0.
double NoiseSlack(const Group& a, const Group& b, const MergeLimits& limits) {
  // The moments count the cells (cells.size(), without reading the vector).
  const double cells = static_cast<double>(a.moments.count() + b.moments.count());
  const double noise = a.noise + b.noise;
  if (cells < limits.noise_min_cells || noise < limits.noise_min_mean * cells) return 0;
  return MaxOf(0.0, limits.noise_factor * noise - a.cost - b.cost);
}
double ChargedCost(double added, double slack) { return added - MinOf(slack, MaxOf(added, 0.0)); }
double ChargedCost(const Group& a, const Group& b, double added, const MergeLimits& limits) {
  return ChargedCost(added, NoiseSlack(a, b, limits));
}

// The summed distance a merged group may reach: its parts' cost plus
// max_added or, when larger, the noise slack (a merge may raise the mean
// distance up to the walls' own noise).
double MergeBudget(const Group& a, const Group& b, const MergeLimits& limits) {
  return a.cost + b.cost + MaxOf(limits.max_added, NoiseSlack(a, b, limits));
}

// The merged moments of a and b (O(1)); their TLS line is the merge's line.
PointMoments MergedMoments(const Group& a, const Group& b) {
  PointMoments moments = a.moments;
  moments.Merge(b.moments);
  return moments;
}

// A lower bound, in O(1), on what merging a and b adds to the summed
// distance, or infinity when the merge surely breaks the bound or the
// budget (MergeBudget with noise slack `slack`). The merged cells' squared distances to their TLS
// line sum to S = n * (smallest eigenvalue of their covariance); with every distance at most
// epsilon, the summed distance is at least S / epsilon, and at least sqrt(S).
double MergeLowerBound(const Group& a, const Group& b, const MergeLimits& limits, double slack) {
  const PointMoments moments = MergedMoments(a, b);
  const double mean_sq = SmallestEigenvalue(moments.Covariance());
  const double epsilon = limits.epsilon;
  if (mean_sq > epsilon * epsilon) return std::numeric_limits<double>::infinity();
  const double sum_sq = mean_sq * static_cast<double>(moments.count());
  const double cost = MaxOf(sum_sq / epsilon, std::sqrt(sum_sq));
  if (cost > a.cost + b.cost + MaxOf(limits.max_added, slack) + kRoundingSlack) {
    return std::numeric_limits<double>::infinity();
  }
  return cost - a.cost - b.cost;
}

// Fits the union of a and b and sweeps its cells; false when a cell breaks
// the bound or the summed distance passes MergeBudget or, besides, grows by
// more than `max_added` (cells: the map's budget left).
bool TryMerge(const Group& a, const Group& b, const MergeLimits& limits, double max_added,
              FittedLine* line, LineSweep* sweep) {
  const double epsilon = limits.epsilon;
  const PointMoments moments = MergedMoments(a, b);
  if (SmallestEigenvalue(moments.Covariance()) > epsilon * epsilon) return false;
  *line = moments.Fit();
  *sweep = LineSweep();
  const double max_cost = MinOf(MergeBudget(a, b, limits), a.cost + b.cost + max_added);
  return SweepCells(*line, a.cells, epsilon, max_cost, sweep) &&
         SweepCells(*line, b.cells, epsilon, max_cost, sweep);
}

// Moves b's cells into a (the larger vector is kept, so a wall built up
// piece by piece is copied O(log n) times per cell, not O(n)) and gives a
// the merged line.
void AbsorbGroup(Group* a, Group* b, const FittedLine& line, const LineSweep& sweep) {
  a->moments.Merge(b->moments);
  a->noise += b->noise;
  if (a->cells.size() < b->cells.size()) a->cells.swap(b->cells);
  a->cells.insert(a->cells.end(), b->cells.begin(), b->cells.end());
  SetLine(a, line, sweep);
  b->alive = false;
  b->cells = {};
}

// A merge candidate: groups a and b under `added`, a lower bound of its
// charged cost or the exact one; live while b's version is `version_b` (a's
// candidates are dropped whenever a changes).
struct Candidate {
  double added;
  std::uint32_t a, b;
  std::uint32_t version_b;
};

// Candidates ordered by (added, a, b), a total order, so that the merges
// made do not depend on how the queue stores ties. Two levels: each group
// keeps the candidates it queued in a short list, and a binary heap of
// groups is keyed by each list's cheapest entry. A merge drops its groups'
// lists in O(1) instead of leaving them stale in one large heap; stale
// entries of the other lists are dropped when they reach their list's top.
class MergeQueue {
 public:
  // `version`: per group, bumped whenever the group changes or dies.
  explicit MergeQueue(const std::vector<std::uint32_t>* version)
      : version_(version),
        lists_(version->size()),
        best_(version->size(), 0),
        position_(version->size(), kAbsent) {
    arena_.reserve(16 * version->size());  // room for 16 candidates per group
  }

  // Queues c; until Build() only into c.a's list.
  void Push(const Candidate& c) {
    List& list = lists_[c.a];
    if (list.size == list.capacity) Grow(&list);
    Entry* entries = &arena_[list.begin];
    entries[list.size++] = {c.added, c.b, c.version_b};
    if (!built_) return;
    if (list.size == 1 || Less(entries[list.size - 1], entries[best_[c.a]])) {
      best_[c.a] = list.size - 1;
      if (position_[c.a] == kAbsent) {
        position_[c.a] = static_cast<std::int32_t>(heap_.size());
        heap_.push_back({c.added, c.a});
      }
      heap_[position_[c.a]].key = c.added;
      SiftUp(static_cast<std::size_t>(position_[c.a]));
    }
  }

  // Heapifies the groups queued so far.
  void Build() {
    for (std::uint32_t g = 0; g < lists_.size(); ++g) {
      if (!FindBest(g)) continue;
      position_[g] = static_cast<std::int32_t>(heap_.size());
      heap_.push_back({Best(g).added, g});
    }
    for (std::size_t i = heap_.size() / 2; i-- > 0;) SiftDown(i);
    built_ = true;
  }

  // The cheapest live candidate, dropping stale ones; false when none is
  // left.
  bool Top(Candidate* top) {
    while (!heap_.empty()) {
      const std::uint32_t g = heap_[0].group;
      const Entry& e = Best(g);
      if (Live(e)) {
        *top = {e.added, g, e.b, e.version_b};
        return true;
      }
      RemoveBest(g);
    }
    return false;
  }

  // Removes the candidate Top() returned.
  void Pop() { RemoveBest(heap_[0].group); }

  // Drops every candidate queued by g.
  void Clear(std::uint32_t g) {
    lists_[g].size = 0;  // keeps its room in the arena
    if (position_[g] != kAbsent) Erase(g);
  }

 private:
  struct Entry {
    double added;
    std::uint32_t b;
    std::uint32_t version_b;
  };
  // A group in the heap under its cheapest entry's `added` (kept here so
  // that sifting reads only the heap).
  struct HeapEntry {
    double key;
    std::uint32_t group;
  };
  // A group's candidates: arena_[begin, begin + size), with room for
  // `capacity` (one arena instead of a vector per group: fewer allocations).
  struct List {
    std::uint32_t begin = 0, size = 0, capacity = 0;
  };
  static constexpr std::int32_t kAbsent = -1;

  // Moves a full list to the arena's end with twice the room.
  void Grow(List* list) {
    const std::uint32_t capacity = std::max<std::uint32_t>(8, 2 * list->capacity);
    const std::uint32_t begin = static_cast<std::uint32_t>(arena_.size());
    arena_.resize(arena_.size() + capacity);
    std::copy_n(arena_.begin() + list->begin, list->size, arena_.begin() + begin);
    list->begin = begin;
    list->capacity = capacity;
  }
  const Entry& Best(std::uint32_t g) const { return arena_[lists_[g].begin + best_[g]]; }

  bool Live(const Entry& e) const { return (*version_)[e.b] == e.version_b; }
  static bool Less(const Entry& x, const Entry& y) {
    return x.added < y.added || (x.added == y.added && x.b < y.b);
  }
  // Heap order: by the best entry, then (a, b).
  static bool Before(const HeapEntry& x, const HeapEntry& y) {
    // Branch-free: sifting compares are data dependent.
    return (x.key < y.key) | ((x.key == y.key) & (x.group < y.group));
  }
  // Drops g's stale entries and finds its cheapest; false when none is left.
  bool FindBest(std::uint32_t g) {
    List& list = lists_[g];
    Entry* entries = &arena_[list.begin];
    std::uint32_t kept = 0;
    for (std::uint32_t i = 0; i < list.size; ++i) {
      const Entry e = entries[i];
      if (!Live(e)) continue;
      if (kept == 0 || Less(e, entries[best_[g]])) best_[g] = kept;
      entries[kept++] = e;
    }
    list.size = kept;
    return kept > 0;
  }
  // Swap-removes the best entry of g (the heap's top) and repositions g.
  void RemoveBest(std::uint32_t g) {
    List& list = lists_[g];
    arena_[list.begin + best_[g]] = arena_[list.begin + list.size - 1];
    --list.size;
    if (!FindBest(g)) {
      Erase(g);
      return;
    }
    const std::size_t i = static_cast<std::size_t>(position_[g]);
    heap_[i].key = Best(g).added;
    SiftDown(i);  // its key only grew
  }
  void Erase(std::uint32_t g) {
    const std::size_t i = static_cast<std::size_t>(position_[g]);
    position_[g] = kAbsent;
    const HeapEntry last = heap_.back();
    heap_.pop_back();
    if (i == heap_.size()) return;
    Place(i, last);
    SiftDown(i);
    SiftUp(static_cast<std::size_t>(position_[last.group]));
  }
  void Place(std::size_t i, const HeapEntry& entry) {
    heap_[i] = entry;
    position_[entry.group] = static_cast<std::int32_t>(i);
  }
  void SiftUp(std::size_t i) {
    const HeapEntry entry = heap_[i];
    while (i > 0) {
      const std::size_t parent = (i - 1) / 2;
      if (!Before(entry, heap_[parent])) break;
      Place(i, heap_[parent]);
      i = parent;
    }
    Place(i, entry);
  }
  void SiftDown(std::size_t i) {
    const HeapEntry entry = heap_[i];
    for (;;) {
      std::size_t child = 2 * i + 1;
      if (child >= heap_.size()) break;
      if (child + 1 < heap_.size() && Before(heap_[child + 1], heap_[child])) ++child;
      if (!Before(heap_[child], entry)) break;
      Place(i, heap_[child]);
      i = child;
    }
    Place(i, entry);
  }

  const std::vector<std::uint32_t>* version_;
  std::vector<List> lists_;  // per group: the candidates it queued
  std::vector<Entry> arena_;
  std::vector<std::uint32_t> best_;     // per group: index of its cheapest entry
  std::vector<std::int32_t> position_;  // per group: index in heap_, or kAbsent
  std::vector<HeapEntry> heap_;         // groups with candidates
  bool built_ = false;
};

// Step 4: merge groups, cheapest merge first (agglomerative), while the
// bound holds and each merge adds at most max_added_cost to the summed
// distance beyond the noise slack; a merge charged more than
// limits.free_added (ChargedCost: what it adds beyond the walls' own noise)
// is made only while *total_cost (the pieces' summed distance plus the
// charges of the merges made) stays within limits.total_budget. Queue keys
// are charged costs. Pairs are candidates when an end of one is within
// `gap` of the other segment. Lazy greedy: a pair is queued under an
// O(1) lower bound of its added cost (MergeLowerBound) and swept over its
// cells only when it reaches the top; it is merged then if its exact cost is
// still the cheapest, else requeued under the exact cost. Pairs that a merge
// of one of their groups makes stale are thus never swept. Equal keys in the
// queue go to the lower ids (MergeQueue's total order), and a swept pair
// whose exact cost equals the next key is merged at once: the merges made
// depend on neither how the queue stores its candidates nor the platform's
// heap.
void MergeGroups(std::vector<Group>* groups, int width, int height, const MergeLimits& limits,
                 double gap, double* total_cost) {
  const double epsilon = limits.epsilon;
  std::vector<std::uint32_t> version(groups->size(), 0);
  MergeQueue queue(&version);
  GroupTiles tiles(width, height, 8);
  tiles.AddAll(*groups);
  std::vector<std::uint8_t> alive(groups->size());
  for (std::uint32_t id = 0; id < groups->size(); ++id) alive[id] = (*groups)[id].alive;
  std::vector<SegmentShape> shapes(groups->size());
  std::vector<Box> boxes(groups->size());
  for (std::uint32_t id = 0; id < groups->size(); ++id) {
    shapes[id] = ShapeOf((*groups)[id], epsilon);
    boxes[id] = BoxOf((*groups)[id].segment);
  }
  std::vector<std::uint32_t> seen_stamp(groups->size(), 0);
  std::vector<std::uint32_t> batch(groups->size());  // candidate ids (each at most once)
  std::uint32_t stamp = 0;
  // True when a merge adding `added` (or, for a lower bound, more) is
  // neither free nor within the budget left.
  auto over_budget = [&](double added) {
    return added > limits.free_added + kRoundingSlack && *total_cost + added > limits.total_budget;
  };
  // Queues every possible merge of g with a group near one of its ends.
  auto push_candidates = [&](std::uint32_t g, bool only_higher_ids) {
    ++stamp;
    const LineSegment s = (*groups)[g].segment;
    const Group& a = (*groups)[g];
    const SegmentShape& shape_a = shapes[g];
    const Box& box_a = boxes[g];
    // The filters run in passes over a batch that keep the survivors
    // (selects, not branches: their outcomes are data dependent).
    std::size_t n = 0;
    tiles.ForEachNearEnds(s, gap, alive, [&](std::uint32_t h) {
      const bool take = (h != g) & (seen_stamp[h] != stamp) & (!only_higher_ids | (h > g));
      seen_stamp[h] = stamp;
      batch[n] = h;
      n += take;
    });
    std::size_t kept = 0;
    for (std::size_t i = 0; i < n; ++i) {
      batch[kept] = batch[i];
      kept += BoxesWithinGap(box_a, boxes[batch[i]], gap);
    }
    n = kept;
    kept = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const SegmentShape& shape_b = shapes[batch[i]];
      batch[kept] = batch[i];
      kept += EndsWithinGap(shape_a, shape_b, gap) & DirectionsCompatible(shape_a, shape_b);
    }
    for (std::size_t i = 0; i < kept; ++i) {
      const std::uint32_t h = batch[i];
      const Group& b = (*groups)[h];
      const double slack = NoiseSlack(a, b, limits);
      const double lower = MergeLowerBound(a, b, limits, slack);
      if (lower == std::numeric_limits<double>::infinity()) continue;
      const double bound = ChargedCost(lower, slack);
      if (over_budget(bound)) continue;
      queue.Push({bound, g, h, version[h]});
    }
  };
  for (std::uint32_t g = 0; g < groups->size(); ++g) push_candidates(g, true);
  queue.Build();
  FittedLine line;
  LineSweep sweep;
  Candidate c;
  while (queue.Top(&c)) {
    // The top has the smallest bound: once it is over the budget, so is
    // every queued merge, and none of them can be free any more.
    if (over_budget(c.added)) break;
    queue.Pop();
    Group& a = (*groups)[c.a];
    Group& b = (*groups)[c.b];
    // A merge over the budget left is not made: stop its sweep there.
    const double allowed =
        std::max(limits.free_added + kRoundingSlack, limits.total_budget - *total_cost) +
        NoiseSlack(a, b, limits);
    if (!TryMerge(a, b, limits, allowed, &line, &sweep)) continue;
    c.added = ChargedCost(a, b, sweep.cost - a.cost - b.cost, limits);
    Candidate next;
    if (queue.Top(&next) && c.added > next.added) {
      queue.Push(c);  // no longer the cheapest: wait for its turn
      continue;
    }
    if (over_budget(c.added)) continue;  // free merges may still follow
    *total_cost += c.added;
    AbsorbGroup(&a, &b, line, sweep);
    alive[c.b] = 0;
    ++version[c.b];
    ++version[c.a];
    queue.Clear(c.a);
    queue.Clear(c.b);
    tiles.Add(c.a, a.segment);
    shapes[c.a] = ShapeOf(a, epsilon);
    boxes[c.a] = BoxOf(a.segment);
    push_candidates(c.a, false);
  }
}

// The summed distance (cells) the chained cells may reach through merges
// dearer than free_merge_cost_cells (see target_mean_distance_cells in
// lines.h): with D0 the mean distance of all edge cells to the unmerged
// pieces `groups` (chained cells to their own piece, speckle cells to the
// nearest piece) and N the number of edge cells, the merges may raise the
// mean to at most
// target * epsilon + (1 + distance_growth_factor) * D0; the speckle cells'
// distances are taken as fixed. *chained_cost gets the pieces' summed
// distance. Infinity when the options set no budget.
double DistanceBudget(const std::vector<Group>& groups, const std::vector<std::uint32_t>& speckle,
                      int width, int height, double epsilon, const LineExtractionOptions& options,
                      double* chained_cost) {
  double cells = static_cast<double>(speckle.size());
  *chained_cost = 0;
  for (const Group& group : groups) {
    *chained_cost += group.cost;
    cells += static_cast<double>(group.cells.size());
  }
  const double target = options.target_mean_distance_cells * epsilon;
  const double growth = options.distance_growth_factor;
  if (!(target > 0 || growth > 0)) return std::numeric_limits<double>::infinity();
  double speckle_cost = 0;
  if (growth > 0 && !speckle.empty() && !groups.empty()) {
    std::vector<LineSegment> pieces;
    pieces.reserve(groups.size());
    for (const Group& group : groups) pieces.push_back(group.segment);
    SegmentIndex index(&pieces, width, height);
    for (std::uint32_t i : speckle) {
      const CellXY c = CellOfIndex(i, width);
      speckle_cost += index.NearestDistance(c.col, c.row);
    }
  }
  return *chained_cost + growth * (*chained_cost + speckle_cost) + target * cells;
}

// The segments of the live groups, and the group of each.
struct LiveSegments {
  std::vector<LineSegment> segments;
  std::vector<std::uint32_t> group_of;
};
LiveSegments CollectLiveSegments(const std::vector<Group>& groups) {
  LiveSegments live;
  for (std::uint32_t id = 0; id < groups.size(); ++id) {
    if (!groups[id].alive) continue;
    live.segments.push_back(groups[id].segment);
    live.group_of.push_back(id);
  }
  return live;
}

// Step 5: drop groups whose cells are all within epsilon of other segments.
void PruneCoveredGroups(std::vector<Group>* groups, int width, int height, double epsilon,
                        double max_added_cost) {
  const LiveSegments live = CollectLiveSegments(*groups);
  const std::vector<LineSegment>& segments = live.segments;
  const std::vector<std::uint32_t>& group_of = live.group_of;
  SegmentIndex index(&segments, width, height);
  std::vector<std::uint8_t> skip(segments.size(), 0);
  // Smallest first, ties in segment order: (cells, segment) pairs sorted.
  std::vector<std::pair<std::size_t, std::uint32_t>> by_size(segments.size());
  for (std::uint32_t s = 0; s < segments.size(); ++s) {
    by_size[s] = {(*groups)[group_of[s]].cells.size(), s};
  }
  std::sort(by_size.begin(), by_size.end());
  std::vector<std::uint32_t> order(segments.size());
  for (std::size_t i = 0; i < by_size.size(); ++i) order[i] = by_size[i].second;
  std::vector<std::uint32_t> targets;
  std::vector<double> distances;
  for (std::uint32_t s : order) {
    Group& group = (*groups)[group_of[s]];
    skip[s] = 1;
    targets.clear();
    distances.clear();
    bool covered = true;
    double added_cost = -group.cost;
    for (const CellXY& c : group.cells) {
      std::uint32_t nearest = 0;
      const double d = index.NearestDistance(c.col, c.row, &skip, &nearest);
      added_cost += d;
      if (d > epsilon || added_cost > max_added_cost) {
        covered = false;
        break;
      }
      targets.push_back(nearest);
      distances.push_back(d);
    }
    if (!covered || added_cost > max_added_cost) {
      skip[s] = 0;
      continue;
    }
    for (std::size_t i = 0; i < targets.size(); ++i) {
      Group& target = (*groups)[group_of[targets[i]]];
      target.cells.push_back(group.cells[i]);
      target.cost += distances[i];
    }
    group.alive = false;
    group.cells.clear();
  }
}

// True when `cells` are whole 8-connected components of the edge map: no
// edge cell outside them touches one of them.
bool HoldsWholeComponents(const EdgeMap& edges, const std::vector<CellXY>& cells) {
  for (const CellXY& c : cells) {
    for (int k = 0; k < 8; ++k) {
      const int col = c.col + kDcol[k], row = c.row + kDrow[k];
      if (col < 0 || row < 0 || col >= edges.width || row >= edges.height) continue;
      if (!edges.is_edge[static_cast<std::size_t>(row) * edges.width + col]) continue;
      const bool inside = std::any_of(cells.begin(), cells.end(), [&](const CellXY& other) {
        return other.col == col && other.row == row;
      });
      if (!inside) return false;
    }
  }
  return true;
}

// Step 6: specks. Segments of at most `max_cells` cells that hold whole
// edge components and whose cells are all at least `min_gap` from every
// other segment are left to the furniture layer when that adds at most
// `max_added` to the summed distance (the cells' distances to the nearest
// remaining segment, less their distance to their own), in order of that
// cost when the step starts (recomputed as specks go), while *total_cost
// stays within `budget`. Returns the cells handed over (raster indices);
// their groups die.
std::vector<std::uint32_t> LeaveSpecksToFurniture(const EdgeMap& edges, std::vector<Group>* groups,
                                                  std::size_t max_cells, double min_gap,
                                                  double max_added, double budget,
                                                  double* total_cost) {
  std::vector<std::uint32_t> handed_over;
  if (max_cells == 0) return handed_over;
  const int width = edges.width, height = edges.height;
  const LiveSegments live = CollectLiveSegments(*groups);
  const std::vector<LineSegment>& segments = live.segments;
  const std::vector<std::uint32_t>& group_of = live.group_of;
  SegmentIndex index(&segments, width, height);
  std::vector<std::uint8_t> gone(segments.size(), 0);
  // What leaving segment s's cells to the furniture layer adds to the
  // summed distance; infinity when another segment is within min_gap.
  auto added_cost = [&](std::uint32_t s) {
    const Group& group = (*groups)[group_of[s]];
    gone[s] = 1;
    double added = -group.cost;
    for (const CellXY& c : group.cells) {
      const double d = index.NearestDistance(c.col, c.row, &gone);
      if (d < min_gap) {
        added = std::numeric_limits<double>::infinity();
        break;
      }
      added += d;
    }
    gone[s] = 0;
    return added;
  };
  std::vector<std::pair<double, std::uint32_t>> specks;  // (added cost, segment)
  for (std::uint32_t s = 0; s < segments.size(); ++s) {
    const Group& group = (*groups)[group_of[s]];
    if (group.cells.size() > max_cells || !HoldsWholeComponents(edges, group.cells)) continue;
    const double added = added_cost(s);
    if (added <= max_added) specks.push_back({added, s});
  }
  std::stable_sort(specks.begin(), specks.end(),
                   [](const auto& x, const auto& y) { return x.first < y.first; });
  for (const auto& [first_cost, s] : specks) {
    const double added = added_cost(s);  // higher if a nearer speck went
    if (!(added <= max_added) || *total_cost + added > budget) continue;
    *total_cost += added;
    gone[s] = 1;
    Group& group = (*groups)[group_of[s]];
    for (const CellXY& c : group.cells) {
      handed_over.push_back(static_cast<std::uint32_t>(c.row) * static_cast<std::uint32_t>(width) +
                            static_cast<std::uint32_t>(c.col));
    }
    group.alive = false;
    group.cells = {};
  }
  return handed_over;
}

// Buffers reused across PolishGroupL1 calls.
struct PolishScratch {
  std::vector<double> xs, ys, w;
};

// Step 7: moves each group's line towards the least-absolute-distance line
// of its cells (what DisPL_ave measures) by iteratively reweighted total
// least squares (weights 1 / max(|r|, 0.1 cell), Eigen on the weighted 2x2
// covariance), keeping a new line only while it lowers the summed distance
// and keeps every cell within epsilon. The segment spans all cells.
void PolishGroupL1(Group* group, double epsilon, PolishScratch* scratch) {
  const std::size_t n = group->cells.size();
  if (n < 3) return;
  std::vector<double>& xs = scratch->xs;
  std::vector<double>& ys = scratch->ys;
  std::vector<double>& w = scratch->w;
  xs.resize(n);
  ys.resize(n);
  w.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const CellXY& c = group->cells[i];
    xs[i] = c.col;
    ys[i] = c.row;
  }
  auto evaluate = [&](const FittedLine& line, double* sum, double* worst) {
    *sum = 0;
    *worst = 0;
    const double nx = -line.direction.y(), ny = line.direction.x();
    for (std::size_t i = 0; i < n; ++i) {
      const double d =
          std::abs((xs[i] - line.centroid.x()) * nx + (ys[i] - line.centroid.y()) * ny);
      *sum += d;
      *worst = std::max(*worst, d);
    }
  };
  FittedLine best = group->line;
  double best_sum = 0, worst = 0;
  evaluate(best, &best_sum, &worst);
  if (worst > epsilon + kRoundingSlack) return;  // cells handed over off the line's end
  for (int iteration = 0; iteration < 8; ++iteration) {
    const double nx = -best.direction.y(), ny = best.direction.x();
    double sw = 0, sx = 0, sy = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const double d =
          std::abs((xs[i] - best.centroid.x()) * nx + (ys[i] - best.centroid.y()) * ny);
      w[i] = 1.0 / std::max(d, 0.1);
      sw += w[i];
      sx += w[i] * xs[i];
      sy += w[i] * ys[i];
    }
    const Eigen::Vector2d mean(sx / sw, sy / sw);
    Eigen::Matrix2d cov = Eigen::Matrix2d::Zero();
    for (std::size_t i = 0; i < n; ++i) {
      const double dx = xs[i] - mean.x(), dy = ys[i] - mean.y();
      cov(0, 0) += w[i] * dx * dx;
      cov(0, 1) += w[i] * dx * dy;
      cov(1, 1) += w[i] * dy * dy;
    }
    cov(1, 0) = cov(0, 1);
    const FittedLine candidate = FitFromCovariance(mean, cov / sw);
    double sum = 0;
    evaluate(candidate, &sum, &worst);
    if (worst > epsilon + kRoundingSlack || sum >= best_sum - 1e-9) break;
    best = candidate;
    best_sum = sum;
  }
  group->line = best;
  group->cost = best_sum;
  group->segment = SegmentFromProjections(best, xs.data(), ys.data(), n);
}

// Step 8: corners. Two segments whose ends are within `reach` cells of each
// other and which meet at more than 20 degrees are both extended to the
// intersection of their lines when that point lies beyond both ends and
// within `reach` of each, so that decoded walls close at corners. Segments
// only grow, so no cell gets farther from its segment.
void JoinCorners(std::vector<LineSegment>* segments, int width, int height, double reach) {
  constexpr int kTile = 8;
  const int tiles_x = std::max(1, (width + kTile - 1) / kTile);
  const int tiles_y = std::max(1, (height + kTile - 1) / kTile);
  auto tile_of = [&](double x, double y) {
    const int tx = std::clamp(static_cast<int>(std::floor((x + 0.5) / kTile)), 0, tiles_x - 1);
    const int ty = std::clamp(static_cast<int>(std::floor((y + 0.5) / kTile)), 0, tiles_y - 1);
    return std::pair<int, int>(tx, ty);
  };
  // Ends: 2 * id + (0 for (x1, y1), 1 for (x2, y2)), bucketed by tile in
  // increasing order (a counting sort: tile t's ends are
  // ends[tile_begin[t], tile_begin[t + 1])).
  auto end_point = [&](std::uint32_t end) {
    const LineSegment& s = (*segments)[end / 2];
    return (end % 2 == 0) ? Eigen::Vector2d(s.x1, s.y1) : Eigen::Vector2d(s.x2, s.y2);
  };
  const std::uint32_t end_count = static_cast<std::uint32_t>(2 * segments->size());
  std::vector<std::uint32_t> tile_of_end(end_count);
  std::vector<std::uint32_t> tile_begin(static_cast<std::size_t>(tiles_x) * tiles_y + 1, 0);
  for (std::uint32_t end = 0; end < end_count; ++end) {
    const Eigen::Vector2d p = end_point(end);
    const auto [tx, ty] = tile_of(p.x(), p.y());
    tile_of_end[end] = static_cast<std::uint32_t>(ty) * tiles_x + tx;
    ++tile_begin[tile_of_end[end] + 1];
  }
  for (std::size_t t = 1; t < tile_begin.size(); ++t) tile_begin[t] += tile_begin[t - 1];
  std::vector<std::uint32_t> ends(end_count);
  {
    std::vector<std::uint32_t> fill(tile_begin.begin(), tile_begin.end() - 1);
    for (std::uint32_t end = 0; end < end_count; ++end) ends[fill[tile_of_end[end]]++] = end;
  }
  std::vector<std::uint8_t> joined(2 * segments->size(), 0);
  const double min_sine = std::sin(20.0 * std::numbers::pi / 180.0);
  for (std::uint32_t end = 0; end < 2 * segments->size(); ++end) {
    if (joined[end]) continue;
    const Eigen::Vector2d p = end_point(end);
    const auto [tx0, ty0] = tile_of(p.x() - reach, p.y() - reach);
    const auto [tx1, ty1] = tile_of(p.x() + reach, p.y() + reach);
    for (int ty = ty0; ty <= ty1 && !joined[end]; ++ty) {
      for (int tx = tx0; tx <= tx1 && !joined[end]; ++tx) {
        const std::size_t tile = static_cast<std::size_t>(ty) * tiles_x + tx;
        for (std::uint32_t k = tile_begin[tile]; k < tile_begin[tile + 1]; ++k) {
          const std::uint32_t other = ends[k];
          if (other / 2 == end / 2 || joined[other]) continue;
          const Eigen::Vector2d q = end_point(other);
          if ((p - q).norm() > reach) continue;
          // Directions pointing outwards from each end.
          const Eigen::Vector2d u = p - end_point(end ^ 1u);
          const Eigen::Vector2d v = q - end_point(other ^ 1u);
          if (u.norm() <= 0 || v.norm() <= 0) continue;
          const Eigen::Vector2d du = u.normalized(), dv = v.normalized();
          const double cross = du.x() * dv.y() - du.y() * dv.x();
          if (std::abs(cross) < min_sine) continue;
          // p + a * du = q + b * dv.
          const Eigen::Vector2d w = q - p;
          const double a = (w.x() * dv.y() - w.y() * dv.x()) / cross;
          const double b = (w.x() * du.y() - w.y() * du.x()) / cross;
          if (a < 0 || b < 0 || a > reach || b > reach) continue;
          const Eigen::Vector2d corner = p + a * du;
          for (std::uint32_t e : {end, other}) {
            LineSegment& s = (*segments)[e / 2];
            (e % 2 == 0 ? s.x1 : s.x2) = corner.x();
            (e % 2 == 0 ? s.y1 : s.y2) = corner.y();
            joined[e] = 1;
          }
          break;
        }
      }
    }
  }
}

}  // namespace

namespace {

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
                       std::vector<std::uint8_t>& open) {
  const int width = edges.width, height = edges.height;
  auto untraced_neighbours = [&](int col, int row) {
    int count = 0;
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
      int best = -1, best_k = -1, best_score = 1 << 30;
      for (int k = 0; k < 8; ++k) {
        const int col = c.col + kDcol[k], row = c.row + kDrow[k];
        if (col < 0 || row < 0 || col >= width || row >= height) continue;
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

}  // namespace

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

namespace {

// SplitChain over the chain of `moments`, into *pieces (cleared first).
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

}  // namespace

std::vector<int> SplitChain(const std::vector<std::uint32_t>& chain, int width,
                            double epsilon_cells) {
  std::vector<int> pieces;
  SplitChainMoments(ChainMoments(chain, width), epsilon_cells, &pieces);
  return pieces;
}

StatusOr<LinemapLines> ExtractLinemapLines(const EdgeMap& edges,
                                           const LineExtractionOptions& options) {
  const double epsilon = options.epsilon_cells;
  if (!(epsilon > 0)) return InvalidArgumentError("epsilon must be positive");
  if (!(options.merge_gap_cells >= 0)) return InvalidArgumentError("merge gap must be >= 0");
  if (options.speck_max_cells < 0 || !(options.speck_min_gap_cells >= 0) ||
      !(options.speck_max_added_cells >= 0)) {
    return InvalidArgumentError("speck options must be >= 0");
  }
  const int width = edges.width, height = edges.height;
  const std::vector<std::uint32_t> edge_cells = EdgeCellList(edges);
  // First the cells to chain (1), then, cleared by the tracing, scratch.
  std::vector<std::uint8_t> open(edges.is_edge.size(), 0);
  FlagLargeComponents(edges, edge_cells, std::max(1, options.min_component_cells), &open);
  std::vector<std::uint32_t> speckle;
  for (std::uint32_t i : edge_cells) {
    if (!open[i]) speckle.push_back(i);
  }

  const double split_epsilon = std::min(epsilon, options.split_epsilon_cells);
  MergeLimits limits{epsilon,
                     options.max_added_cost_cells * epsilon * epsilon,
                     options.noise_merge_factor,
                     options.noise_min_mean_cells,
                     static_cast<double>(options.noise_min_cells),
                     options.free_merge_cost_cells * epsilon * epsilon};
  std::vector<Group> groups;
  const FlatChains chains = TraceChains(edges, edge_cells, open);
  ChainMoments chain_moments;
  std::vector<int> pieces;
  for (std::size_t k = 0; k < chains.size(); ++k) {
    const std::span<const std::uint32_t> chain = chains[k];
    chain_moments.Assign(chain, width);
    SplitChainMoments(chain_moments, split_epsilon, &pieces);
    int begin = 0;
    for (int length : pieces) {
      Group group;
      group.cells.reserve(length);
      for (int i = begin; i < begin + length; ++i) {
        const CellXY c = CellOfIndex(chain[i], width);
        group.cells.push_back(c);
        group.moments.Add(c.col, c.row);
        if (limits.noise_factor > 0) {
          group.noise += chain_moments.LocalResidual(i, options.noise_window_cells);
        }
      }
      // SplitChain checked the same line (up to rounding).
      if (!RefitGroup(&group, epsilon)) {
        return InternalError("a chain piece broke the epsilon bound");
      }
      groups.push_back(std::move(group));
      begin += length;
    }
  }
  double total_cost = 0;
  limits.total_budget =
      DistanceBudget(groups, speckle, width, height, epsilon, options, &total_cost);
  MergeGroups(&groups, width, height, limits, options.merge_gap_cells, &total_cost);
  PruneCoveredGroups(
      &groups, width, height, epsilon,
      std::min(limits.max_added, options.prune_added_cost_cells * epsilon * epsilon));
  const std::vector<std::uint32_t> specks = LeaveSpecksToFurniture(
      edges, &groups, static_cast<std::size_t>(options.speck_max_cells),
      options.speck_min_gap_cells, options.speck_max_added_cells, limits.total_budget, &total_cost);
  speckle.insert(speckle.end(), specks.begin(), specks.end());
  PolishScratch polish_scratch;
  for (Group& group : groups) {
    if (group.alive) PolishGroupL1(&group, epsilon, &polish_scratch);
  }

  LinemapLines result;
  for (const Group& group : groups) {
    if (group.alive) result.segments.push_back(group.segment);
  }
  JoinCorners(&result.segments, width, height, options.corner_join_cells);
  // Speckle not within epsilon of a wall is left to the furniture layer.
  result.left_to_blobs.assign(edges.is_edge.size(), 0);
  SegmentIndex index(&result.segments, width, height);
  for (std::uint32_t i : speckle) {
    const CellXY c = CellOfIndex(i, width);
    if (index.NearestDistance(c.col, c.row) > epsilon) {
      result.left_to_blobs[i] = 1;
      ++result.cells_left_to_blobs;
    }
  }
  return result;
}

}  // namespace linemap::lines_internal
