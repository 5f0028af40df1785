// Wall line segments from an occupancy grid: RM-Line (Liu & Zhang, Appl. Sci.
// 2022, 12, 9754) and linemap's own extractor, with the paper's measures.
//
// All geometry is in cell units (the centre of cell (col, row) is the point
// (col, row)); see grid.h for the conversion to map-frame metres.
//
// CONTRACT (fixed by the lead; extend, do not rename): the codec and the CLI
// call ExtractLines() and MeasureLineFidelity().
#ifndef LINEMAP_LINES_H_
#define LINEMAP_LINES_H_

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "linemap/grid.h"
#include "linemap/status.h"

namespace linemap {

struct LineSegment {
  double x1 = 0, y1 = 0;  // cell units
  double x2 = 0, y2 = 0;
};

// A point in cell units (col, row), e.g. the robot position.
struct CellPoint {
  double col = 0;
  double row = 0;
};

enum class LineMethod {
  kRmLine,   // the paper's method, as written
  kLinemap,  // linemap's own extractor (the default)
};

// The paper's edge map (section 2.1): obstacle cells 4-adjacent to the free
// cells flooded from the robot position (or from every free cell when no
// position is given).
struct EdgeMap {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> is_edge;  // width * height, grid-row order, 1 = edge point
  std::size_t edge_count = 0;
};

// `robot` in cell units; without it every free component is flooded.
EdgeMap ComputeEdgeMap(const Grid& grid, std::optional<CellPoint> robot = std::nullopt);

struct LineExtractionOptions {
  LineMethod method = LineMethod::kLinemap;
  std::optional<CellPoint> robot;  // cell units; see ComputeEdgeMap
  // RM-Line parameters (the paper gives no values; see codec/lines/rmline.cc).
  double rmline_dtheta_deg = 1.0;  // ray angle step, degrees, (0, 180]
  double rmline_ds_cells = 0.5;    // scoring point spacing, cells, (0, 1]
  // linemap extractor: every edge cell lies within epsilon of a segment
  // (cells, >= 0.5), except the cells left to the furniture layer.
  double epsilon_cells = 1.0;
  // linemap extractor: pieces whose facing ends are at most this far apart
  // (cells) may merge into one segment when the bound still holds. Below a
  // doorway's width (16-18 cells at 5 cm) so that doors stay open.
  double merge_gap_cells = 8.0;
  // linemap extractor: edge components (8-connected) with fewer cells than
  // this, and not within epsilon of a segment, are left to the furniture
  // layer instead of getting their own segment (speckle; 2 = lone cells).
  int min_component_cells = 2;
  // linemap extractor: specks. A segment fitted to at most speck_max_cells
  // cells, which are whole edge components (8-connected) and all lie at
  // least speck_min_gap_cells from every other segment, is a speck (SLAM
  // noise, a chair leg), not a wall: its cells are left to the furniture
  // layer (and counted there) when that adds at most
  // speck_max_added_cells to the summed distance of the edge cells to their
  // nearest segment, cheapest first, while the distance budget of
  // target_mean_distance_cells allows. Clean maps have little budget left
  // after the merges and keep their specks; noisy SLAM maps hand many over
  // (rosnav1/willow-full-0.05: 1185 -> 894 lines, DisPL_ave 2.09 -> 3.49
  // cells). Suggested 3 cells (2 hands over too few specks on that map, 4
  // nearly costs strands/bham its DisPL_ave lead), a gap of 2 cells (1.5-4
  // give the same passes on ../shared/maps) and 64 cells (32-128 at a gap of
  // 2 give the same passes; no cap spends the whole budget, which costs
  // mrpt/map1 its lead). speck_max_cells 0 = off (StraightWalls()).
  int speck_max_cells = 3;
  double speck_min_gap_cells = 2.0;
  double speck_max_added_cells = 64.0;
  // linemap extractor: a merge (or the removal of a covered segment) is made
  // only if it adds at most this much to the summed distance of the cells to
  // their segment (cells). It trades one segment against DisPL_ave: merging
  // the two sides of a two-cell wall adds half a cell per cell and is refused
  // for walls longer than this.
  // Scaled by epsilon_cells^2 (the value is the cap at epsilon 1): on a wall
  // ragged by +-epsilon, each merge step moves ~epsilon cells by ~epsilon.
  // Merges adding more than free_merge_cost_cells are further limited by the
  // map's distance budget (target_mean_distance_cells).
  double max_added_cost_cells = 3.0;
  // linemap extractor: the price of one segment in summed distance (cells,
  // scaled by epsilon_cells^2 like max_added_cost_cells). Merges that add at
  // most this are always made (cheapest first), so a segment is kept where
  // it saves more than this much distance: a staircase wall with steps of q
  // cells keeps one exact segment per step when merging two steps costs more
  // (about q / 2), and becomes one slanted segment otherwise. Suggested
  // 0.95: just under one cell, so that absorbing a lone cell one cell off a
  // wall is not free (on ../shared/maps, 0.85-0.97 give the same passes;
  // 1.0 loses nav2/tb3_sandbox).
  double free_merge_cost_cells = 0.95;
  // linemap extractor: the map's distance budget for the dearer merges
  // (those adding more than free_merge_cost_cells, up to
  // max_added_cost_cells). They are made, cheapest first, only while the
  // edge cells' mean distance to the nearest segment (DisPL_ave, with the
  // unchained cells' distances as they are to the unmerged pieces) stays at
  // most target_mean_distance_cells + (1 + distance_growth_factor) times
  // that of the unmerged pieces (the chains cut at split_epsilon_cells).
  // Cells, scaled by epsilon_cells; suggested 0.05 (one cell in twenty off
  // by one cell on average). Clean maps, whose pieces fit their cells almost
  // exactly, stop near target_mean_distance_cells; maps with much speckle or
  // ragged walls, whose pieces already leave a large mean distance, merge
  // further. 0 (with distance_growth_factor 0) = no budget: every merge up
  // to max_added_cost_cells is made (StraightWalls()).
  double target_mean_distance_cells = 0.05;
  // linemap extractor: see target_mean_distance_cells (dimensionless;
  // suggested 1: the merges may at most double the unmerged pieces' mean
  // distance, plus the target; StraightWalls() sets 0).
  double distance_growth_factor = 1.0;
  // linemap extractor: a segment whose cells all lie within epsilon of other
  // segments is dropped (its cells handed over) when that adds at most this
  // to the summed distance (cells, scaled by epsilon_cells^2, and at most
  // max_added_cost_cells; not counted against the distance budget).
  // Suggested 1.5, between free_merge_cost_cells and max_added_cost_cells: a
  // lone cell one cell beside a wall goes, a staircase step of several cells
  // one cell off its neighbours stays (on ../shared/maps 1-1.6 give the same
  // passes, 2 and 3 drop so many steps that two clean maps fail).
  // StraightWalls() sets 3 (= max_added_cost_cells).
  double prune_added_cost_cells = 1.5;
  // linemap extractor: a wall's own noise is forgiven. A cell's local noise
  // is its distance to the TLS line of the 2 * noise_window_cells + 1 chain
  // cells around it, and 0 where those cells never turn back along either
  // axis (a staircase: a digitised straight wall or curve is exact, not
  // noisy). A merge may raise the merged cells' summed distance up to this
  // factor times their summed noise without paying for it (neither against
  // max_added_cost_cells nor against the distance budget), when the merged
  // group has at least noise_min_cells cells of mean noise at least
  // noise_min_mean_cells: so a wall ragged by +-1 cell becomes one segment
  // while the steps of a clean slanted wall, and small noisy objects, keep
  // their segments (dimensionless; suggested 1.5; on ../shared/maps 1.2-2
  // give the same passes, and noise windows of 3-5 cells; 0 = off,
  // StraightWalls()).
  double noise_merge_factor = 1.5;
  // linemap extractor: half-width of the local-noise window (chain cells;
  // suggested 4).
  int noise_window_cells = 4;
  // linemap extractor: see noise_merge_factor (cells; suggested 0.35: a wall
  // ragged by +-1 cell has a mean noise of about 0.5, a clean wall with a
  // few noisy corners far less; 0.3-0.4 give the same passes).
  double noise_min_mean_cells = 0.35;
  // linemap extractor: see noise_merge_factor (cells; suggested 16: shorter
  // noisy groups are objects whose outline matters, not ragged walls; 24
  // gives the same passes, 10 loses one clean map).
  int noise_min_cells = 16;
  // linemap extractor: chains are first cut into pieces within this distance
  // of their line (cells; capped at epsilon_cells), then merged under
  // epsilon_cells and max_added_cost_cells. Below 0.5 the pieces are digital
  // straight segments, so the two sides of a wall never start merged.
  // Default 0.1: (nearly) exact runs of cells, e.g. one step of a
  // staircase, so that the merge decides every step of a slanted wall by its
  // cost. StraightWalls() sets 0.3: pieces that spread a staircase by up to
  // 0.3 cells, so that a slanted wall becomes one slanted segment.
  double split_epsilon_cells = 0.1;
  // linemap extractor: segment ends at most this far apart (cells) that meet
  // at more than 20 degrees are extended to their common corner (0 = off).
  double corner_join_cells = 3.0;
};

struct LineExtraction {
  std::vector<LineSegment> segments;
  EdgeMap edges;  // the edge map the lines were extracted from
  // linemap extractor only: edge cells deliberately left to the furniture
  // layer (not within epsilon of any segment), as width*height flags
  // (empty for RM-Line), and their number.
  std::vector<std::uint8_t> left_to_blobs;
  std::size_t cells_left_to_blobs = 0;
};

StatusOr<LineExtraction> ExtractLines(const Grid& grid, const LineExtractionOptions& options);

// `options` with the linemap extractor set to draw each straight wall as one
// segment: pieces that spread a staircase by up to 0.3 cells
// (split_epsilon_cells), no distance budget, the prune at
// max_added_cost_cells, no noise forgiveness and no specks left to the
// furniture layer. Fewer lines (on
// ../shared/maps a median 336 against the defaults' 463), but a higher
// DisPL_ave (0.96 cm against 0.60 at the median), most on clean
// maps, where the defaults follow the pixel steps of slanted walls as the
// paper's measure rewards (Pareto-better than RM-Line on 16 of 25 maps
// against 22). The .lmap encoder uses it for its wall layer. `linemap lines
// --straight-walls`.
LineExtractionOptions StraightWalls(LineExtractionOptions options);

// A robot position typed in map-frame metres (x, y) as the CellPoint the
// extractors and SegmentMap take: the centre of the cell holding it
// (CellHoldingPoint), so that a point typed on a cell's lower or left edge
// (0.025 m at 0.05 m/cell, 0.49999999999999994 cells in doubles) is in that
// cell, as --room-at and --window take it. Off the map (or not finite) a
// position they refuse as off the map: the unrounded one, or, for a point
// typed on the map's upper or right edge (which belongs to no cell), that
// edge.
CellPoint RobotCellPoint(const Grid& grid, double x, double y);

// The paper's measures (section 3.1, Eq. 5) over the edge cells.
struct LineFidelity {
  std::size_t edge_cells = 0;
  double displ_ave_cells = 0;  // DisPL_ave: mean distance from edge cell centre to nearest segment
  double displ_max_cells = 0;  // the largest such distance
  double share_within_1 = 0;   // share of edge cells within 1 cell of a segment
};

LineFidelity MeasureLineFidelity(const EdgeMap& edges, const std::vector<LineSegment>& segments);

}  // namespace linemap

#endif  // LINEMAP_LINES_H_
