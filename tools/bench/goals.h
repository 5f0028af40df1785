// The goals of .lmap 2.0 as `linemap bench` checks them on a corpus: exact
// round trip, size against PNG-9 and the other codecs, what the vector layers
// cost, how well they hold the walls, and speed against libpng. Each goal is
// decided from the figures the bench measured (never re-measured here), so
// the decisions can be checked on hand-made results.
#ifndef LINEMAP_TOOLS_BENCH_GOALS_H_
#define LINEMAP_TOOLS_BENCH_GOALS_H_

#include <optional>
#include <string>
#include <vector>

#include "tools/bench/report.h"
#include "tools/bench/results.h"

namespace linemap::bench {

// The targets. Sizes and layer cost at the corpus median; the fidelity goals
// on every map; speed as the ratio of the corpus-median CPU times.
inline constexpr double kGoalMedianRatioToPng9 = 0.42;  // default file / PNG-9, at most
inline constexpr double kGoalMedianLayerCost = 0.10;    // default / raster-only - 1, at most
inline constexpr double kGoalMinCoveredShare = 0.99;    // edge cells near a wall or in furniture
inline constexpr double kGoalMinDecodeSpeedup = 2.0;    // libpng decode ms / .lmap decode ms
inline constexpr double kGoalMaxEncodeTimeRatio = 1.0;  // .lmap encode ms / libpng encode ms

// Per-map figures the goals are decided on; nullopt when a figure they need
// is missing (or a divisor is not positive).
std::optional<double> LayerCost(const MapResult& result);           // lmap2 / raster-only - 1
std::optional<double> DecodeSpeedupVsPng(const MapResult& result);  // PNG dec ms / lmap2 dec ms
std::optional<double> EncodeTimeVsPng(const MapResult& result);     // lmap2 enc ms / PNG enc ms

// Stores the three figures above under their keys (for the CSV).
void AddGoalFigures(MapResult* result);

enum class Verdict {
  kPass,
  kFail,        // at least one map (or the median) misses the goal
  kIncomplete,  // none misses it, but some map was not measured
};
const char* VerdictName(Verdict verdict);  // "PASS", "FAIL", "INCOMPLETE"

struct GoalOutcome {
  std::string goal;      // what is promised, in words
  std::string target;    // the threshold
  std::string measured;  // the figures that decide it
  Verdict verdict = Verdict::kIncomplete;
  std::vector<std::string> failing;  // maps (or "map: anchor") that miss it
  std::vector<std::string> missing;  // maps where a figure it needs is missing
};

// Every goal, in the order the summary prints them.
std::vector<GoalOutcome> CheckGoals(const std::vector<MapResult>& results);

// The per-map table with a median row, the summary (one row per goal, with
// PASS / FAIL and the figures that decide it) and, when a goal is missed or
// incomplete, the maps that miss it or lack a figure. The verdicts come last
// so that they end a terminal's output.
std::vector<NamedTable> GoalTables(const std::vector<MapResult>& results);

}  // namespace linemap::bench

#endif  // LINEMAP_TOOLS_BENCH_GOALS_H_
