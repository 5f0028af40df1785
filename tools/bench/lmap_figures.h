// The .lmap columns of `linemap bench`: the default 2.0 file (exact, with
// walls, rooms and furniture) with its speed, memory, round-trip check and
// layer fidelity; the --raster-only 2.0 file; the --compact 2.3 files.
#ifndef LINEMAP_TOOLS_BENCH_LMAP_FIGURES_H_
#define LINEMAP_TOOLS_BENCH_LMAP_FIGURES_H_

#include <cstddef>
#include <functional>
#include <optional>
#include <string>

#include "linemap/grid.h"
#include "linemap/status.h"
#include "tools/bench/results.h"

namespace linemap::bench {

// A rival codec's encode and decode of the same map (libpng's), timed in
// blocks beside the default file's (TimeRunsInBlocks), their medians stored
// under its two keys.
struct RivalCodec {
  std::function<void()> encode;
  std::function<void()> decode;
  std::string encode_ms_key;
  std::string decode_ms_key;
};

struct LmapMeasure {
  int repeats = 5;                  // timed runs: the default file's encode and decode, the
                                    // --compact file's decode
  bool memory = true;               // peak memory of its encode and decode (forks)
  std::optional<RivalCodec> rival;  // none: the default file timed alone
};

// Adds the kLmap* figures of `grid` to `result`, and the rival's times (timed
// alone when the default file cannot be written). A file that cannot be
// written or read back adds a note; a default file that cannot be written or
// decoded counts every cell as wrong (kLmapCellsWrong), so the round-trip
// goal fails rather than skips the map.
Status AddLmapFigures(const Grid& grid, const LmapMeasure& what, MapResult* result);

// Cells of `decoded` that differ from `original`, compared one by one; every
// cell of `original` when the two differ in width or height.
std::size_t CellsWrong(const Grid& original, const Grid& decoded);

}  // namespace linemap::bench

#endif  // LINEMAP_TOOLS_BENCH_LMAP_FIGURES_H_
