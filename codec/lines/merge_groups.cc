// Step 4 of linemap's extractor: the merge's candidate filters and costs,
// the merge loop, and the distance budget it spends.
#include "codec/lines/merge_groups.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "codec/lines/edge_cells.h"
#include "codec/lines/group_tiles.h"
#include "codec/lines/line_fit.h"
#include "codec/lines/merge_queue.h"
#include "codec/lines/segment_index.h"

namespace linemap::lines_internal {
namespace {

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

}  // namespace

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
      // Both tests, without a branch between them (most pairs pass both).
      kept += static_cast<unsigned>(EndsWithinGap(shape_a, shape_b, gap)) &
              static_cast<unsigned>(DirectionsCompatible(shape_a, shape_b));
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

}  // namespace linemap::lines_internal
