// Chamfer 3-4 distance transform of the room flood's clearance
// (room_flood.cc): 3 per side step, 4 per diagonal step, an error under
// 8 % of the Euclidean distance (Borgefors, "Distance transformations in
// digital images", CVGIP 34, 1986).
#ifndef LINEMAP_CODEC_SEGMENT_CHAMFER_H_
#define LINEMAP_CODEC_SEGMENT_CHAMFER_H_

#include <cstdint>
#include <vector>

namespace linemap::segment_internal {

inline constexpr int kChamferSide = 3;
inline constexpr int kChamferDiagonal = 4;
// A cell still to be reached ("infinitely" far); a reached cell holds at
// most 0xfffe.
inline constexpr std::uint16_t kChamferFar = 0xffff;

// Two-pass transform in place on a `pw` x `ph` grid whose frame (first and
// last rows and columns) is 0: every cell 0 stays 0, every cell
// kChamferFar becomes its chamfer distance to the nearest 0 (at most
// 0xfffe). The frame makes every cell reachable.
void ChamferInPlace(std::vector<std::uint16_t>* dist, int pw, int ph);

// The serial step of one row of a pass: row[c] = min over k <= c of
// t[k] + 3 (c - k) for c in [1, pw - 1) (`forward`; the frame cell before
// the row counts as 0), or the same from the right (k >= c). Values of `t`
// at most 0xfffe. In the header for the tests.
void ChamferScanRow(const std::uint16_t* t, std::uint16_t* row, int pw, bool forward);
// The same, one cell after the other: what ChamferScanRow runs where SSE2 is
// not available, and the reference its blocks must equal.
void ChamferScanRowSerial(const std::uint16_t* t, std::uint16_t* row, int pw, bool forward);

}  // namespace linemap::segment_internal

#endif  // LINEMAP_CODEC_SEGMENT_CHAMFER_H_
