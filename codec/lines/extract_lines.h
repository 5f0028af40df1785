// What the encoder asks of ExtractLines() (linemap/lines.h).
#ifndef LINEMAP_CODEC_LINES_EXTRACT_LINES_H_
#define LINEMAP_CODEC_LINES_EXTRACT_LINES_H_

#include <vector>

#include "linemap/grid.h"
#include "linemap/lines.h"
#include "linemap/status.h"

namespace linemap {

// ExtractLines(grid, options).segments, with the same errors, without what
// only the result's other fields need: the edge map is not kept, and
// linemap's extractor leaves out its last step, which sorts the speckle
// into covered cells and cells left to blobs (a map-sized array and a
// nearest-segment search per speck cell that the walls of a file do not
// read).
StatusOr<std::vector<LineSegment>> ExtractLineSegments(const Grid& grid,
                                                       const LineExtractionOptions& options);

}  // namespace linemap

#endif  // LINEMAP_CODEC_LINES_EXTRACT_LINES_H_
