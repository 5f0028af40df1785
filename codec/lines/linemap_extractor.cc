// linemap's wall-line extractor (LineMethod::kLinemap): fewer segments than
// RM-Line (rmline.cc) with a guaranteed L-infinity bound, every chained edge
// cell within epsilon_cells of its segment.
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
// Files: step 1 and the pipeline are here; steps 2-3 in edge_chains.cc, 4 in
// merge_groups.cc (with group_tiles.h and merge_queue.h), 5-6 in
// prune_and_specks.cc, 7-8 in polish_and_corners.cc. line_groups.h holds the
// group and the fit of its segment, edge_cells.h the cells' coordinates.
#include "codec/lines/linemap_extractor.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <span>
#include <utility>
#include <vector>

#include "codec/lines/edge_cells.h"
#include "codec/lines/edge_chains.h"
#include "codec/lines/line_groups.h"
#include "codec/lines/merge_groups.h"
#include "codec/lines/polish_and_corners.h"
#include "codec/lines/prune_and_specks.h"
#include "codec/lines/segment_index.h"
#include "format/large_vector.h"

namespace linemap::lines_internal {
namespace {

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

// Whether one of the 8 neighbours of edge cell `index` is an edge cell.
bool HasEdgeNeighbour(const EdgeMap& edges, std::uint32_t index) {
  const CellXY c = CellOfIndex(index, edges.width);
  for (int k = 0; k < 8; ++k) {
    const int col = c.col + kDcol[k], row = c.row + kDrow[k];
    if (col < 0 || row < 0 || col >= edges.width || row >= edges.height) continue;
    if (edges.is_edge[static_cast<std::size_t>(row) * edges.width + col]) return true;
  }
  return false;
}

// Flags (1) in `large` the cells of the 8-connected edge components with at
// least `min_cells` cells; `large` is width*height and all zero on entry.
void FlagLargeComponents(const EdgeMap& edges, const std::vector<std::uint32_t>& edge_cells,
                         int min_cells, std::vector<std::uint8_t>* large) {
  if (min_cells <= 2) {
    // Every component is large, or every one but the lone cells (the
    // default): a cell's component has two cells or more exactly when one
    // of its 8 neighbours is an edge cell, so no component is walked (the
    // walk was 1 % of an encode).
    for (std::uint32_t index : edge_cells) {
      (*large)[index] = min_cells <= 1 || HasEdgeNeighbour(edges, index);
    }
    return;
  }
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

}  // namespace

StatusOr<std::vector<LineSegment>> ExtractLinemapSegments(const EdgeMap& edges,
                                                          const LineExtractionOptions& options,
                                                          std::vector<std::uint32_t>* speckle_out) {
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
  std::vector<std::uint8_t> open = LargeVector<std::uint8_t>(edges.is_edge.size(), 0);
  FlagLargeComponents(edges, edge_cells, std::max(1, options.min_component_cells), &open);
  std::vector<std::uint32_t>& speckle = *speckle_out;
  speckle.clear();
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
  // At most that many pieces: each has two cells or more but a chain's
  // last. Reserved rather than grown: a group is some 200 bytes, and the
  // moves into each larger array (fresh memory, first touched there) were
  // 1-3 % of the extraction's time; the pages past the groups made are
  // never touched.
  groups.reserve(chains.cells.size() / 2 + chains.size());
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
        const CellXY c = chain_moments.Cell(i);
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

  std::vector<LineSegment> segments;
  for (const Group& group : groups) {
    if (group.alive) segments.push_back(group.segment);
  }
  JoinCorners(&segments, width, height, options.corner_join_cells);
  return segments;
}

StatusOr<LinemapLines> ExtractLinemapLines(const EdgeMap& edges,
                                           const LineExtractionOptions& options) {
  std::vector<std::uint32_t> speckle;
  LinemapLines result;
  LINEMAP_ASSIGN_OR_RETURN(result.segments, ExtractLinemapSegments(edges, options, &speckle));
  // Step 8: speckle not within epsilon of a wall is left to the furniture
  // layer.
  const double epsilon = options.epsilon_cells;
  const int width = edges.width, height = edges.height;
  AssignLarge<std::uint8_t>(&result.left_to_blobs, edges.is_edge.size(), 0);
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
