// A generated office-like map for the scaling table: an unknown margin, a
// building of rooms with 2-cell walls and doors, furniture blocks and sensor
// speckle, from a fixed seed (the same cells on every platform).
#ifndef LINEMAP_TOOLS_BENCH_SYNTHETIC_H_
#define LINEMAP_TOOLS_BENCH_SYNTHETIC_H_

#include <cstdint>

#include "linemap/grid.h"

namespace linemap::bench {

// A `size` x `size` map (size >= 64), 0.05 m/cell, rooms of 96 cells: a
// bigger map has more rooms, each drawn anew (not a repeated tile, whose
// repeats a compressor would find).
Grid GenerateOfficeMap(int size, std::uint32_t seed = 1);

// A `width` x `height` map: the lower-left corner of
// GenerateOfficeMap(max(width, height), seed), so that a map of nav2 users'
// largest reported size (20,768 x 13,612) is an office like the squares.
Grid GenerateOfficeMapOfSize(int width, int height, std::uint32_t seed = 1);

}  // namespace linemap::bench

#endif  // LINEMAP_TOOLS_BENCH_SYNTHETIC_H_
