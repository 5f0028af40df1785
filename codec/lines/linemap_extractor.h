// linemap's own wall-line extractor (LineMethod::kLinemap). Exposed for
// tests; the public entry point is ExtractLines() in linemap/lines.h.
#ifndef LINEMAP_CODEC_LINES_LINEMAP_EXTRACTOR_H_
#define LINEMAP_CODEC_LINES_LINEMAP_EXTRACTOR_H_

#include <cstdint>
#include <vector>

#include "linemap/lines.h"
#include "linemap/status.h"

namespace linemap::lines_internal {

struct LinemapLines {
  std::vector<LineSegment> segments;
  std::vector<std::uint8_t> left_to_blobs;  // width*height flags
  std::size_t cells_left_to_blobs = 0;
};

// Runs steps 1 to 8 of linemap_extractor.cc over `edges`.
StatusOr<LinemapLines> ExtractLinemapLines(const EdgeMap& edges,
                                           const LineExtractionOptions& options);

// Steps 1 to 7 alone: the segments, and into *speckle the edge cells left
// unchained that step 8 measures (the encoder's walls need the segments
// only).
StatusOr<std::vector<LineSegment>> ExtractLinemapSegments(const EdgeMap& edges,
                                                          const LineExtractionOptions& options,
                                                          std::vector<std::uint32_t>* speckle);

}  // namespace linemap::lines_internal

#endif  // LINEMAP_CODEC_LINES_LINEMAP_EXTRACTOR_H_
