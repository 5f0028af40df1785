// netpbm's `pnmtopng -compression 9`, run as a subprocess on map_saver's
// PGM of a grid: the PNG-9 anchor the size goals name.
#ifndef LINEMAP_TOOLS_BENCH_NETPBM_H_
#define LINEMAP_TOOLS_BENCH_NETPBM_H_

#include <cstdint>

#include "linemap/grid.h"
#include "linemap/status.h"

namespace linemap::bench {

// Bytes of the PNG `pnmtopng -compression 9` writes for the grid (an error
// when netpbm is missing or fails).
StatusOr<std::uint64_t> PnmtopngBytes(const Grid& grid);

}  // namespace linemap::bench

#endif  // LINEMAP_TOOLS_BENCH_NETPBM_H_
