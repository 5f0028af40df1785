// The .lmap columns of `linemap bench` (issue 6's codec): lossy and lossless
// sizes, encode / decode time and peak memory, and the eval figures of the
// lossy decode. Kept apart so the rest of the bench does not depend on the
// codec's API.
#ifndef LINEMAP_TOOLS_BENCH_LMAP_FIGURES_H_
#define LINEMAP_TOOLS_BENCH_LMAP_FIGURES_H_

#include "linemap/grid.h"
#include "linemap/status.h"
#include "tools/bench/results.h"

namespace linemap::bench {

struct LmapMeasure {
  int repeats = 5;         // timed encode and decode runs
  bool memory = true;      // peak memory of encode and decode (forks)
  bool everything = true;  // also lossless size, eval figures and geometry
};

// Adds the kLmap* and kEval* figures of `grid` to `result` (lossy = the
// codec's default options, as `linemap encode` writes). Fails with
// kUnsupported (and adds nothing) while the codec is not in this tree.
Status AddLmapFigures(const Grid& grid, const LmapMeasure& what, MapResult* result);

}  // namespace linemap::bench

#endif  // LINEMAP_TOOLS_BENCH_LMAP_FIGURES_H_
