// The parts of the tolerance checks that SimplifyWithinTolerance() and
// CheckTolerance() share: distance transforms, free-space topology and the
// plan comparison. Cells are addressed by Grid::Index (row-major).
#ifndef LINEMAP_CODEC_TOLERANCE_TOLERANCE_INTERNAL_H_
#define LINEMAP_CODEC_TOLERANCE_TOLERANCE_INTERNAL_H_

#include <cstddef>
#include <cstdint>
#include <vector>

#include "linemap/grid.h"

namespace linemap::tolerance_internal {

// Distance used for "no such cell in the map".
inline constexpr std::int32_t kFar = INT32_MAX / 2;

// Calls f(j) for each 4-neighbour j of cell i (row-major index) of a
// width x height grid, in the order +col, -col, +row, -row.
template <typename F>
void ForEachNeighbour(std::size_t width, std::size_t height, std::size_t i, F f) {
  const std::size_t c = i % width;
  if (c + 1 < width) f(i + 1);
  if (c > 0) f(i - 1);
  if (i + width < width * height) f(i + width);
  if (i >= width) f(i - width);
}

// 1 where grid's cell equals `value`.
std::vector<std::uint8_t> CellMask(const Grid& grid, Cell value);

// Chebyshev distance (cells) from every cell to the nearest cell where
// `mask` is non-zero; kFar everywhere when the mask is empty. Two raster
// passes with the 8-neighbour chamfer, which is exact for this metric.
std::vector<std::int32_t> ChebyshevDistance(int width, int height,
                                            const std::vector<std::uint8_t>& mask);

// 1 where a cell of `mask` is non-zero within Chebyshev distance `radius`
// (>= 0), that is ChebyshevDistance(...) <= radius: a running count over
// the square of 2 radius + 1 cells a side, by rows then by columns, about
// a third of the cost of the full distances where only that threshold is
// asked.
std::vector<std::uint8_t> WithinDistance(int width, int height,
                                         const std::vector<std::uint8_t>& mask, int radius);

// Free-space topology of `decoded` against `original` (4-connected free
// regions). `leaks` as CompareGrids counts them (original regions of
// kLeakRegionCells+ cells joined by a decoded component); `splits`: original
// regions of kLeakRegionCells+ cells whose cells free in the decode lie in
// several decoded components. `split_culprits` (when asked for): cells
// free in the original and not in the decode whose return joins every
// split-off piece to the main piece of its region again, the fewest a
// breadth-first search finds for each piece.
struct TopologyFaults {
  std::size_t leaks = 0;
  std::size_t splits = 0;
  std::vector<std::size_t> split_culprits;
};
TopologyFaults FindTopologyFaults(const Grid& original, const Grid& decoded, bool want_culprits);

// Cells to give back (free in `original`, not in `decoded`) so that every
// cell of `lost` (free in the original, more than t cells from every
// decoded free cell; raster order) is within t of a decoded free cell or
// one given back. Each lost cell not yet within t of one gives back the
// cell within t of it that serves the most lost cells not yet served,
// preferring one 4-adjacent to free space on a tie (a cell alone would
// split its region); so a wall the blocks thickened by a cell gets one
// cell in every 2t + 1 back, not every cell.
std::vector<std::size_t> FreeCover(const Grid& original, const Grid& decoded,
                                   const std::vector<std::size_t>& lost, int t);

// The plan guarantee between nearby cells, which the sampled starts of
// PlanCulprits rarely try: from every cell free in both maps beside a cell
// free in one only, the plans of up to `radius` steps on either map must
// be on the other with the same length. Where one is not, the cells
// on its plan that are not free on the other map (of the shortest plans,
// one with the fewest); a blocked passage between two rooms that no sampled
// start plans through is found this way. With `checked` (a decode this
// check found nothing on, or whose culprits were all mended since), only
// the cells near a cell that differs from it are searched from: the plans
// of the others are as they were. The searches run on up to `threads`
// threads (0: one per core); the result does not depend on them.
std::vector<std::size_t> LocalDetourCulprits(const Grid& original, const Grid& decoded, int radius,
                                             const Grid* checked = nullptr, int threads = 1);

// The detours LocalDetourCulprits cannot see: a wall grown along a stretch
// of free space longer than its `radius` steps, which a plan that runs along
// the wall and leaves on the same side walks round (2 steps per cell grown;
// 3 % of a plan under 67 steps per cell grown) although every plan of up to
// `radius` steps keeps its length. For each component (8-connected) of
// cells free on the original only that is longer than `radius` - 8 cells in
// either axis: the plans on the original of up to `max_steps` steps from
// every cell beside it, inside its box and 8 cells around, must be on the
// decode within 3 % (PlansAgree); where one is not, the cells of its plan
// not free on the decode (as LocalDetourCulprits gives them), each once.
// `max_steps`: a growth of T cells adds at most 2T steps to a plan along
// it, within 3 % of plans longer than 200 T / 3 steps, so the plans up to
// that length are the ones to check. With `checked` (a decode this check
// found nothing on, or whose culprits were all mended since), only the
// stretches with a cell that differs from it in their box and 8 cells
// around are searched from.
std::vector<std::size_t> StretchDetourCulprits(const Grid& original, const Grid& decoded,
                                               int radius, int max_steps,
                                               const Grid* checked = nullptr);

// The plans LocalDetourCulprits checks (from each cell beside a change, on
// each map, to every cell free on the other within `radius` steps), and
// those not of the same length on the other map.
struct LocalPlanCount {
  std::size_t plans = 0;
  std::size_t disagreements = 0;
};
LocalPlanCount CountLocalPlans(const Grid& original, const Grid& decoded, int radius);

// Plans compared from sampled start cells to every goal cell free in both
// grids (deterministic: the same grids give the same pairs). `paths` (when
// asked for): the cells of both plans of the worst disagreeing pair of each
// start.
struct PlanFaults {
  std::size_t pairs = 0;
  std::size_t disagreements = 0;
  std::vector<std::size_t> paths;
};
PlanFaults ComparePlans(const Grid& original, const Grid& decoded, bool want_paths);

// Whether plans of `la` and `lb` steps (-1: none) agree (linemap/tolerance.h 4).
bool PlansAgree(std::int32_t la, std::int32_t lb);

// The changed cells that make plans disagree, for every goal of every
// sampled start of ComparePlans (the same pairs): the cells of the
// original's plan that are not free in `decoded` where the decoded plan is
// longer or missing, and the cells of the decoded plan that are not free in
// the original where it is shorter or new. Giving them back their original
// value makes those plans agree (the original plan is there again, the
// shortcut gone), so a fitting loop settles in a few rounds. A start's two
// searches run side by side when `threads` allows (0: one per core); the
// result does not depend on it.
std::vector<std::size_t> PlanCulprits(const Grid& original, const Grid& decoded, int threads = 1);

}  // namespace linemap::tolerance_internal

#endif  // LINEMAP_CODEC_TOLERANCE_TOLERANCE_INTERNAL_H_
