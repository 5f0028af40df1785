// linemap's own wall-line extractor (LineMethod::kLinemap). Exposed for
// tests; the public entry point is ExtractLines() in linemap/lines.h.
#ifndef LINEMAP_CODEC_LINES_LINEMAP_EXTRACTOR_H_
#define LINEMAP_CODEC_LINES_LINEMAP_EXTRACTOR_H_

#include <cstdint>
#include <vector>

#include "linemap/lines.h"
#include "linemap/status.h"

namespace linemap::lines_internal {

// Orders the edge cells flagged in `include` (width*height; 1 = take) into
// chains: each cell is 8-adjacent to the next. Every included cell is in
// exactly one chain. Chains start at contour ends where there are any.
std::vector<std::vector<std::uint32_t>> TraceEdgeChains(const EdgeMap& edges,
                                                        const std::vector<std::uint8_t>& include);

// Splits a chain into consecutive pieces, each within epsilon (cells) of its
// own total-least-squares line: greedy longest piece first, found by
// doubling then bisection. Returns the piece lengths in chain order.
std::vector<int> SplitChain(const std::vector<std::uint32_t>& chain, int width,
                            double epsilon_cells);

struct LinemapLines {
  std::vector<LineSegment> segments;
  std::vector<std::uint8_t> left_to_blobs;  // width*height flags
  std::size_t cells_left_to_blobs = 0;
};

StatusOr<LinemapLines> ExtractLinemapLines(const EdgeMap& edges,
                                           const LineExtractionOptions& options);

}  // namespace linemap::lines_internal

#endif  // LINEMAP_CODEC_LINES_LINEMAP_EXTRACTOR_H_
