// Pictures for people: per-map overlays of the extracted geometry on the map
// (as the papers' figures), and a summary plot of every exact method's size
// against PNG-9.
#ifndef LINEMAP_TOOLS_BENCH_SVG_H_
#define LINEMAP_TOOLS_BENCH_SVG_H_

#include <string>
#include <vector>

#include "linemap/grid.h"
#include "linemap/segmentation.h"
#include "linemap/status.h"
#include "tools/bench/results.h"

namespace linemap::bench {

// The SVG text: the map as an embedded PNG (faded), `segments` in red, room
// chains in blue, furniture outlines in green. Cell units, row 0 at the bottom.
std::string MapOverlaySvg(const Grid& grid, const std::vector<LineSegment>& segments,
                          const Segmentation* segmentation, const std::string& title);

// Writes DIR/<map name with '/' -> '__'>.svg: the layers of the default
// .lmap 2.0 file (walls, room chains, furniture outlines), else (when they
// could not be read) RM-Line's segments with the segmentation's room borders
// and furniture outlines.
Status WriteMapOverlaySvg(const std::string& dir, const Grid& grid, const MapResult& result);

// Size ratio to PNG-9 (log scale), a column per method (all exact), one
// point per map, the medians as large markers.
std::string SummaryPlotSvg(const std::vector<MapResult>& results);

std::string Base64(const std::string& bytes);

}  // namespace linemap::bench

#endif  // LINEMAP_TOOLS_BENCH_SVG_H_
