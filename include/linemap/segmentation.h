// Room-border chains and furniture blobs (Kosteley et al., "Local navigation
// map processing algorithm...", sections 3.2 B and C): binary morphology,
// two-pass union-find labelling, and Lee-algorithm closure of room borders.
//
// CONTRACT (fixed by the lead; extend, do not rename): the codec calls
// SegmentMap() and stores rooms[i].chain and blobs[i].cells.
//
// How a ROS occupancy grid is read as the paper's room layout M_r:
//   free space (3)  the room's free component (4-connected free cells holding
//                   the robot; without a robot every free component of at
//                   least min_room_cells cells is a room);
//   furniture (2)   everything enclosed by that free space: the components of
//                   its complement (8-connected) that do not reach beyond the
//                   map edge, i.e. the point-in-polygon test the paper
//                   proposes, done on cells. Pillars and columns inside a
//                   room land here whatever their shape. The blobs are the
//                   occupied cells of these parts, grouped by an optional
//                   closing (furniture_closing) and 8-connectivity;
//   walls (1)       occupied cells 8-adjacent to the free space that are not
//                   furniture;
//   virgin (0)      the rest.
// The heavy border (section 3.2 C) is D \ E with D = M_H dilated by
// border_dilate (in order) and E = D eroded by border_erode (in order),
// M_H = cells marked 1..3. Its 8-connected components are counted, and the
// paper's mid-line rule (two or more entries along the horizontal mid-line
// of the box = room border) is applied to each (RoomBorder::ring_components).
// The rule alone would call a hollow pillar a room border and a U-shaped room
// furniture, so the room's border is decided topologically instead: it is
// the component holding D's outer boundary (its first cell in raster order).
// That component is opened with the -2 / -3 lines on a cut row and closed by
// the Lee wave and a backward pass that prefers steps next to room space,
// which cuts the surges. The chain is accepted when the polygon through its
// cell centres holds the robot (point in polygon, as the paper proposes) or,
// without a robot, at least half of the room's free cells; otherwise the
// next cut row around the mid-line is tried, and as a last resort the outer
// contour of D is used (RoomBorder::closed_by_lee = false).
#ifndef LINEMAP_SEGMENTATION_H_
#define LINEMAP_SEGMENTATION_H_

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "linemap/cells.h"
#include "linemap/grid.h"
#include "linemap/labeling.h"
#include "linemap/lines.h"
#include "linemap/morphology.h"
#include "linemap/status.h"

namespace linemap {

struct RoomBorder {
  // Closed chain of border cells in traversal order: each cell is 8-adjacent
  // to the next, and the last to the first.
  std::vector<CellIndex> chain;
  std::size_t free_cells = 0;           // cells of the room's free component
  std::size_t enclosed_free_cells = 0;  // of those, inside the chain or on it
  bool closed_by_lee = true;            // false: fallback outer contour of D
  int border_components = 0;            // 8-connected components of the heavy border
  int ring_components = 0;              // of those, room borders by the mid-line rule
};

struct FurnitureBlob {
  std::vector<CellIndex> cells;  // the blob's exact occupied cells, raster order
  std::size_t cell_count = 0;
  CellIndex first_cell;  // first cell in raster order (row-major from row 0)
  BoundingBox box;
  // Closed outer boundary chain of the blob (Moore tracing, 8-adjacent
  // steps). Where furniture_closing joined several pieces, it runs around
  // the joined shape, so it may pass over the closing's bridge cells.
  std::vector<CellIndex> outline;
};

struct SegmentationOptions {
  std::optional<CellPoint> robot;  // cell units
  // Without a robot, free components smaller than this are not rooms
  // (cells; default 400 = 1 m^2 at 0.05 m).
  std::size_t min_room_cells = 400;
  // Section 3.2 C: dilations applied to M_H in order (default: 5x5 full,
  // then the 3x3 cross) and erosions applied to the result (default: 5x5
  // full, twice). Larger elements close wider wall gaps and cut bigger
  // surges, at the price of a thicker border.
  std::vector<StructuringElement> border_dilate = {StructuringElement::Square(5),
                                                   StructuringElement::Cross3()};
  std::vector<StructuringElement> border_erode = {StructuringElement::Square(5),
                                                  StructuringElement::Square(5)};
  // Section 3.2 A: closing that joins nearby obstacle pieces of one piece of
  // furniture into one blob (default: the 3x3 cross; nullopt = no joining).
  // Blob cells stay the exact occupied cells.
  std::optional<StructuringElement> furniture_closing = StructuringElement::Cross3();
  // linemap's addition to the paper: the room's own interior cells (M_H
  // eroded by the 3x3 cross) are kept out of the heavy border, so the
  // shortest path can cut surges and gaps of at most two cells but never
  // across a narrow part of the room (a doorway, a corridor), which would
  // leave whole rooms outside the chain (default true; false = the paper).
  bool protect_room_interior = true;
  // Cut rows tried on each side of the mid-line before falling back
  // (default 16).
  int max_cut_rows = 16;
};

// Milliseconds of CPU time of the calling thread spent in each stage
// (numbered as the paper's Table 1); on an idle machine this is the wall
// time, on a busy one it leaves out the waiting for a core.
struct SegmentationTimings {
  double room_layout_ms = 0;  // free components, enclosure (our pre-processing)
  double morphology_ms = 0;   // stage 1: dilations, erosions, subtraction
  double furniture_ms = 0;    // stage 2: furniture components (closing, labelling, outlines)
  double border_ms = 0;       // stage 3: 8-connected border components, mid-line rule
  double lee_ms = 0;          // stage 4: Lee wave and backward pass
  double total_ms = 0;
};

struct Segmentation {
  std::vector<RoomBorder> rooms;  // largest free component first
  std::vector<FurnitureBlob> blobs;
  SegmentationTimings timings;
};

StatusOr<Segmentation> SegmentMap(const Grid& grid, const SegmentationOptions& options = {});

// Cells whose centre lies inside the polygon through the chain's cell
// centres (even-odd rule), plus the chain cells themselves.
BinaryMask FillChainPolygon(const std::vector<CellIndex>& chain, int width, int height);

}  // namespace linemap

#endif  // LINEMAP_SEGMENTATION_H_
