// Helpers of the small cell types (include/linemap/cells.h).
#include "linemap/cells.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace linemap {

bool RunsClockwise(const std::vector<CellIndex>& ring) {
  // Each term is a difference of two products of indices below 2^31, so it
  // fits in 64 bits; the sum over a ring of up to the chain limit of points
  // (2^26) needs 128. (__int128: a GCC and Clang extension.)
  __extension__ using Int128 = __int128;
  Int128 twice_area = 0;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const CellIndex& p = ring[i];
    const CellIndex& q = ring[(i + 1) % ring.size()];
    twice_area += std::int64_t{p.col} * q.row - std::int64_t{q.col} * p.row;
  }
  return twice_area < 0;
}

}  // namespace linemap
