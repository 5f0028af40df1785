// The distance-transform room segmentation of Bormann et al. ("Room
// Segmentation: Survey, Implementation, and Analysis", ICRA 2016;
// ipa_room_segmentation's DistanceSegmentation), as a comparator for
// bench_rooms: the free space's distance map is thresholded at every level;
// the level whose 4-connected components include the most with an area in
// [min_area_m2, max_area_m2] wins, and those components grow back over the
// free space by a breadth-first wavefront. Written from the paper's
// description, not from its code.
#ifndef LINEMAP_TOOLS_BENCH_ROOMS_DISTANCE_BASELINE_H_
#define LINEMAP_TOOLS_BENCH_ROOMS_DISTANCE_BASELINE_H_

#include <cstdint>
#include <vector>

#include "linemap/grid.h"

namespace linemap::bench_rooms {

// Room id of every cell (0: none), ids 1..n.
std::vector<std::int32_t> DistanceBaseline(const Grid& grid, double min_area_m2 = 1.0,
                                           double max_area_m2 = 160.0);

}  // namespace linemap::bench_rooms

#endif  // LINEMAP_TOOLS_BENCH_ROOMS_DISTANCE_BASELINE_H_
