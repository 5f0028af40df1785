// Steps 5 and 6 of linemap's extractor (see linemap_extractor.cc): after the
// merge, groups whose cells other segments already cover are dropped, and
// isolated specks are left to the furniture layer.
#ifndef LINEMAP_CODEC_LINES_PRUNE_AND_SPECKS_H_
#define LINEMAP_CODEC_LINES_PRUNE_AND_SPECKS_H_

#include <cstddef>
#include <cstdint>
#include <vector>

#include "codec/lines/line_groups.h"
#include "linemap/lines.h"

namespace linemap::lines_internal {

// Step 5: drop groups whose cells are all within epsilon of other segments.
void PruneCoveredGroups(std::vector<Group>* groups, int width, int height, double epsilon,
                        double max_added_cost);

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
                                                  double* total_cost);

}  // namespace linemap::lines_internal

#endif  // LINEMAP_CODEC_LINES_PRUNE_AND_SPECKS_H_
