// Context-modelled coding of per-cell planes with the binary range coder
// (format/range_coder.h), in the manner of JBIG's template coding
// (ITU-T T.82, section 6.7): each cell's bit is coded with a probability
// chosen by its already-coded neighbours and by the canvas decoded so far.
// The templates and contexts are normative: spec/format.md sections
// "FREE", "OCCP" and "RESD". These are the planes of 1.0 files, which are
// decoded but no longer written; OCCP and FREE keep their encoders as
// bench_tiles' baseline.
#ifndef LINEMAP_CODEC_CELLS_PLANE_CODER_H_
#define LINEMAP_CODEC_CELLS_PLANE_CODER_H_

#include <cstdint>
#include <vector>

#include "linemap/grid.h"
#include "linemap/status.h"

namespace linemap {

// OCCP: codes which cells that the canvas (width*height, grid-row order)
// does not already hold as occupied become occupied (`target` 1).
std::vector<std::uint8_t> EncodeOccupiedPlane(const std::vector<std::uint8_t>& target,
                                              const std::vector<Cell>& canvas, int width,
                                              int height);
Status DecodeOccupiedPlane(const std::uint8_t* data, std::size_t size, int width, int height,
                           std::vector<Cell>* canvas);

// FREE: codes, for every cell the canvas does not hold as occupied, whether
// it is free (`target` 1); the decoder makes it free or unknown.
std::vector<std::uint8_t> EncodeFreePlane(const std::vector<std::uint8_t>& target,
                                          const std::vector<Cell>& canvas, int width, int height);
Status DecodeFreePlane(const std::uint8_t* data, std::size_t size, int width, int height,
                       std::vector<Cell>* canvas);

// RESD: makes `canvas` the exact grid, the canvas before it being the
// prediction.
Status DecodeResidualPlane(const std::uint8_t* data, std::size_t size, int width, int height,
                           std::vector<Cell>* canvas);

}  // namespace linemap

#endif  // LINEMAP_CODEC_CELLS_PLANE_CODER_H_
