// The window options of `linemap decode`: --window X0,Y0,X1,Y1 (map-frame
// metres) and --window-cells C0,R0,C1,R1 (cell indices), turned into the
// CellWindow that LoadLmapRegion decodes.
#ifndef LINEMAP_TOOLS_LINEMAP_DECODE_WINDOW_H_
#define LINEMAP_TOOLS_LINEMAP_DECODE_WINDOW_H_

#include <optional>
#include <string>

#include "linemap/codec.h"
#include "linemap/grid.h"
#include "linemap/lmap_vectors.h"
#include "linemap/status.h"
#include "tools/linemap/cli.h"

namespace linemap::cli {

// Box [x0, x1] x [y0, y1] in map-frame metres.
struct MetreBox {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

// The cells whose centres lie in the box, centres on its edge included
// (within 1e-9 cell, so that a box edge typed in decimal on a centre keeps
// it). With a yaw in the origin the box's corners are taken into the grid
// and the window is the cell rectangle around them. Invalid argument when
// the box is inverted or holds no centre, or when its window reaches past
// the width x height map; the message names both.
StatusOr<CellWindow> WindowFromMetres(const MetreBox& box, const MapMetadata& meta, int width,
                                      int height);

// --window / --window-cells from the arguments (nullopt when neither is
// given). Reads the map's size and metadata from `lmap_path` (its header
// alone) only for --window.
StatusOr<std::optional<CellWindow>> WindowFromArgs(const ParsedArgs& args,
                                                   const std::string& lmap_path,
                                                   const DecodeLimits& limits);

// --room-at X,Y (map-frame metres): the cell of the map `header` describes
// that holds the point (CellHoldingPoint); a point off the map is an invalid
// argument naming it and `lmap_path`.
StatusOr<CellIndex> RoomCellFromArgs(const ParsedArgs& args, const LmapHeader& header,
                                     const std::string& lmap_path);

}  // namespace linemap::cli

#endif  // LINEMAP_TOOLS_LINEMAP_DECODE_WINDOW_H_
