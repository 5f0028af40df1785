// A generated office-like map for the scaling table: an unknown margin, a
// building of rooms with 2-cell walls and doors, furniture blocks and sensor
// speckle, from a fixed seed (the same cells on every platform).
#ifndef LINEMAP_TOOLS_BENCH_SYNTHETIC_H_
#define LINEMAP_TOOLS_BENCH_SYNTHETIC_H_

#include <cstdint>

#include "linemap/grid.h"

namespace linemap::bench {

// A `size` x `size` map (size >= 64), 0.05 m/cell.
Grid GenerateOfficeMap(int size, std::uint32_t seed = 1);

// `tile` repeated `nx` times across and `ny` times up.
Grid TileMap(const Grid& tile, int nx, int ny);

}  // namespace linemap::bench

#endif  // LINEMAP_TOOLS_BENCH_SYNTHETIC_H_
