// Context-modelled coding of per-cell planes with the binary range coder
// (format/range_coder.h), in the manner of JBIG's template coding
// (ITU-T T.82, section 6.7): each cell's bit is coded with a probability
// chosen by its already-coded neighbours and by the canvas decoded so far.
// The templates and contexts are normative: spec/format.md sections
// "FREE", "OCCP" and "RESD".
#ifndef LINEMAP_CODEC_CODEC_PLANE_CODER_H_
#define LINEMAP_CODEC_CODEC_PLANE_CODER_H_

#include <cstdint>
#include <vector>

#include "linemap/grid.h"
#include "linemap/status.h"

namespace linemap {

// Target of the FREE plane, per cell.
enum class FreeTarget : std::uint8_t { kNotFree = 0, kFree = 1, kDontCare = 2 };

// Codes which cells are free. `canvas` is the grid decoded before this chunk
// (width*height, grid-row order); don't-care cells take the more probable
// value under the model. Returns the range-coder bytes and, in *decided, the
// bits actually coded (1 = free).
std::vector<std::uint8_t> EncodeFreePlane(const std::vector<FreeTarget>& target,
                                          const std::vector<Cell>& canvas, int width, int height,
                                          std::vector<std::uint8_t>* decided);
// Sets each canvas cell free (bit 1) or, when it was free, unknown (bit 0).
Status DecodeFreePlane(const std::uint8_t* data, std::size_t size, int width, int height,
                       std::vector<Cell>* canvas);

// Codes which not-yet-occupied canvas cells become occupied (`target` 1).
std::vector<std::uint8_t> EncodeOccupiedPlane(const std::vector<std::uint8_t>& target,
                                              const std::vector<Cell>& canvas, int width,
                                              int height);
Status DecodeOccupiedPlane(const std::uint8_t* data, std::size_t size, int width, int height,
                           std::vector<Cell>* canvas);

// Codes `truth` exactly, given the lossy canvas as prediction.
std::vector<std::uint8_t> EncodeResidualPlane(const std::vector<Cell>& truth,
                                              const std::vector<Cell>& canvas, int width,
                                              int height);
Status DecodeResidualPlane(const std::uint8_t* data, std::size_t size, int width, int height,
                           std::vector<Cell>* canvas);

}  // namespace linemap

#endif  // LINEMAP_CODEC_CODEC_PLANE_CODER_H_
