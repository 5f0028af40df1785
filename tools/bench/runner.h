// Measuring one map with every comparator, and the scaling table.
#ifndef LINEMAP_TOOLS_BENCH_RUNNER_H_
#define LINEMAP_TOOLS_BENCH_RUNNER_H_

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "linemap/grid.h"
#include "tools/bench/results.h"

namespace linemap::bench {

struct BenchOptions {
  int repeats = 5;  // timed runs per map up to 1 Mcell (fewer above; see RepeatsFor)
  bool measure_memory = true;
  bool jbig = true;      // needs pbmtojbg in PATH
  bool jxl = true;       // needs cjxl and djxl in PATH (libjxl-tools); ~1.3 s CPU per Mcell
  bool webp = true;      // needs cwebp and dwebp in PATH (webp)
  bool pnmtopng = true;  // cross-check size with netpbm's pnmtopng -compression 9
};

// Every figure of `grid` (loaded from `source_path`). Never fails as a
// whole: a comparator that fails leaves its figures out and adds a note.
MapResult MeasureMap(const std::string& name, const std::string& source_path, const Grid& grid,
                     const BenchOptions& options);

// One row of the scaling table.
struct ScalingRow {
  int width = 0;  // cells
  int height = 0;
  double mcells = 0;  // millions of cells
  int repeats = 0;
  double png_encode_ms_per_mcell = 0;
  double png_decode_ms_per_mcell = 0;
  double rmline_ms_per_mcell = 0;
  double linemap_lines_ms_per_mcell = 0;  // ExtractLines() with the defaults
  std::optional<double> lmap_encode_ms_per_mcell;
  std::optional<double> lmap_decode_ms_per_mcell;
  // The same from the fastest run of each: a shared machine only ever adds
  // time, so the fastest runs say what the code costs when a noisy phase
  // moved the medians of one size.
  double png_encode_fastest_ms_per_mcell = 0;
  double png_decode_fastest_ms_per_mcell = 0;
  std::optional<double> lmap_encode_fastest_ms_per_mcell;
  std::optional<double> lmap_decode_fastest_ms_per_mcell;
  // A window of 1 % of the map (a tenth of each side, from 30 % of each
  // side, away from the centre where the layers' sections of the 64-Mcell
  // map meet), decoded with DecodeLmapRegion, against decoding the whole
  // map: ms (median) and how many times faster; unset if a window failed.
  std::optional<double> lmap_window_ms;
  std::optional<double> lmap_window_speedup;
  // One room as a viewer loads it when the user picks a point: the room
  // holding the cell nearest the window's centre that lies in a room,
  // with the cells of its box (DecodeLmapRoomAt from the file's bytes): ms
  // (median); unset when no room was found or a load failed.
  std::optional<double> lmap_room_ms;
};

// Generated office maps of 1024^2, 2048^2, 4096^2 and 8192^2 cells and of
// 20,768 x 13,612 (1, 4, 16, 64 and 282 Mcells, as `max_mcells` names them;
// those up to it), timed in interleaved rounds; `progress`
// is called ScalingProgressSteps(max_mcells, repeats) times: once per size
// while it is prepared, then once per round.
std::vector<ScalingRow> RunScaling(int max_mcells, int repeats,
                                   const std::function<void(const std::string&)>& progress);
int ScalingProgressSteps(int max_mcells, int repeats);

}  // namespace linemap::bench

#endif  // LINEMAP_TOOLS_BENCH_RUNNER_H_
