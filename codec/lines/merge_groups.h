// Step 4 of linemap's extractor (see linemap_extractor.cc): pieces are
// merged into walls, cheapest merge first, under the epsilon bound, a cap on
// the distance each merge adds and the map's distance budget.
#ifndef LINEMAP_CODEC_LINES_MERGE_GROUPS_H_
#define LINEMAP_CODEC_LINES_MERGE_GROUPS_H_

#include <cstdint>
#include <limits>
#include <vector>

#include "codec/lines/line_groups.h"
#include "linemap/lines.h"

namespace linemap::lines_internal {

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
                 double gap, double* total_cost);

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
                      double* chained_cost);

}  // namespace linemap::lines_internal

#endif  // LINEMAP_CODEC_LINES_MERGE_GROUPS_H_
