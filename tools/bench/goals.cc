#include "tools/bench/goals.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>

#include "tools/bench/anchors.h"
#include "tools/bench/measure.h"

namespace linemap::bench {
namespace {

using Getter = std::function<std::optional<double>(const MapResult&)>;

// The median goals' figures are quotients of byte counts: one that equals
// the limit in exact arithmetic (1100 / 1000 - 1 against 10 %) must not fail
// by a rounding error.
constexpr double kRoundingSlack = 1e-9;

std::optional<double> Quotient(const MapResult& result, const char* numerator,
                               const char* denominator) {
  const std::optional<double> n = result.Get(numerator);
  const std::optional<double> d = result.Get(denominator);
  if (!n || !d || *d <= 0) return std::nullopt;
  return *n / *d;
}

Getter Figure(const char* figure) {
  return [figure](const MapResult& r) { return r.Get(figure); };
}

std::optional<double> RatioToPng9(const MapResult& r) { return r.RatioToPng9(key::kLmapBytes); }

std::string Fixed(double value, int decimals) { return FormatFixed(value, decimals); }
std::string Percent(double fraction) { return FormatFixed(100.0 * fraction, 1) + " %"; }

Verdict Decide(bool misses, bool incomplete) {
  if (misses) return Verdict::kFail;
  return incomplete ? Verdict::kIncomplete : Verdict::kPass;
}

// The maps that have `get`'s figure, with it; the others' names go to
// `missing`.
struct MapValue {
  const MapResult* map;
  double value;
};
std::vector<MapValue> Values(const std::vector<MapResult>& results, const Getter& get,
                             std::vector<std::string>* missing) {
  std::vector<MapValue> values;
  for (const MapResult& r : results) {
    if (const std::optional<double> v = get(r)) {
      values.push_back({&r, *v});
    } else {
      missing->push_back(r.name);
    }
  }
  return values;
}

double MedianOf(const std::vector<MapValue>& values) {
  std::vector<double> v;
  for (const MapValue& mv : values) v.push_back(mv.value);
  return Median(v);
}

// The map with the largest value (or smallest, when `largest` is false).
const MapValue& Extreme(const std::vector<MapValue>& values, bool largest) {
  return *std::max_element(values.begin(), values.end(), [&](const MapValue& a, const MapValue& b) {
    return largest ? a.value < b.value : a.value > b.value;
  });
}

// Per-map decisions of the goals every map must meet: true = misses it.
bool MissesRoundTrip(const MapResult& r) {
  const std::optional<double> wrong = r.Get(key::kLmapCellsWrong);
  return wrong && *wrong != 0;
}
bool MissesCoverage(const MapResult& r) {
  const std::optional<double> share = r.Get(key::kLmapCoveredShare);
  return share && *share < kGoalMinCoveredShare;
}
// DisPL_ave of the file's walls minus RM-Line's, in cells (<= 0 meets the
// goal); +infinity when the file has no wall but the map has edge cells.
std::optional<double> DisplExcess(const MapResult& r) {
  const std::optional<double> rmline = r.Get(key::kRmLineDisplCells);
  if (!rmline) return std::nullopt;
  if (const std::optional<double> mine = r.Get(key::kLmapDisplCells)) return *mine - *rmline;
  const std::optional<double> walls = r.Get(key::kLmapWalls);
  const std::optional<double> edges = r.Get(key::kLmapEdgeCells);
  if (walls && *walls == 0 && edges && *edges > 0) return HUGE_VAL;
  return std::nullopt;
}
bool MissesDispl(const MapResult& r) {
  const std::optional<double> excess = DisplExcess(r);
  return excess && *excess > 0;
}
// The anchors a map of at least kAnchorMinCells cells loses to.
std::vector<std::string> AnchorsLost(const MapResult& r) {
  std::vector<std::string> lost;
  const std::optional<double> cells = r.Get(key::kCells);
  const std::optional<double> mine = r.Get(AnchorSubject().figure);
  if (!cells || *cells < kAnchorMinCells || !mine) return lost;
  for (const Anchor& anchor : SizeAnchors()) {
    const std::optional<double> theirs = r.Get(anchor.figure);
    if (theirs && *mine >= *theirs) lost.push_back(anchor.name);
  }
  return lost;
}

GoalOutcome RoundTripGoal(const std::vector<MapResult>& results) {
  GoalOutcome o{"every default file decodes to the input cell for cell",
                "0 cells wrong, every map",
                "",
                Verdict::kIncomplete,
                {},
                {}};
  const std::vector<MapValue> values = Values(results, Figure(key::kLmapCellsWrong), &o.missing);
  for (const MapValue& v : values) {
    if (MissesRoundTrip(*v.map)) {
      o.failing.push_back(v.map->name + " (" + FormatCount(v.value) + " cells)");
    }
  }
  o.measured = std::to_string(values.size() - o.failing.size()) + "/" +
               std::to_string(values.size()) + " maps exact (decoded and compared)";
  o.verdict = Decide(!o.failing.empty(), !o.missing.empty() || values.empty());
  return o;
}

// A goal on the corpus median of a per-map figure: at most `limit`.
GoalOutcome MedianAtMostGoal(const std::vector<MapResult>& results, const std::string& goal,
                             const Getter& get, double limit, bool percent) {
  auto show = [&](double v) { return percent ? Percent(v) : Fixed(v, 3); };
  GoalOutcome o{goal, "median <= " + show(limit), "", Verdict::kIncomplete, {}, {}};
  const std::vector<MapValue> values = Values(results, get, &o.missing);
  if (values.empty()) {
    o.measured = "not measured";
    return o;
  }
  const double median = MedianOf(values);
  const MapValue& worst = Extreme(values, true);
  std::size_t above = 0;
  for (const MapValue& v : values) above += v.value > limit ? 1 : 0;
  o.measured = "median " + show(median) + " over " + std::to_string(values.size()) +
               " maps; largest " + show(worst.value) + " (" + worst.map->name + "); " +
               std::to_string(above) + " maps above";
  o.verdict = Decide(median > limit + kRoundingSlack, !o.missing.empty());
  return o;
}

GoalOutcome AnchorsGoal(const std::vector<MapResult>& results) {
  GoalOutcome o{".lmap 2.0 smaller than PNG-9, WebP, JBIG1, zstd -19, xz -9e and JPEG XL",
                "every map of >= " + FormatCount(kAnchorMinCells) + " cells",
                "",
                Verdict::kIncomplete,
                {},
                {}};
  std::size_t maps = 0, pairs = 0, won = 0;
  const Anchor subject = AnchorSubject();
  for (const MapResult& r : results) {
    const std::optional<double> cells = r.Get(key::kCells);
    if (!cells || *cells < kAnchorMinCells) continue;
    ++maps;
    const std::optional<double> mine = r.Get(subject.figure);
    if (!mine) {
      o.missing.push_back(r.name + ": " + subject.name);
      continue;
    }
    for (const Anchor& anchor : SizeAnchors()) {
      const std::optional<double> theirs = r.Get(anchor.figure);
      if (!theirs) {
        o.missing.push_back(r.name + ": " + anchor.name);
        continue;
      }
      ++pairs;
      if (*mine < *theirs) {
        ++won;
      } else {
        o.failing.push_back(r.name + ": " + anchor.name);
      }
    }
  }
  o.measured = "won " + std::to_string(won) + "/" + std::to_string(pairs) +
               " (map, codec) pairs on " + std::to_string(maps) + " maps";
  o.verdict = Decide(!o.failing.empty(), !o.missing.empty() || maps == 0);
  return o;
}

// A goal every map must meet, with `worst` the map farthest from it.
GoalOutcome EveryMapGoal(const std::vector<MapResult>& results, const std::string& goal,
                         const std::string& target, const Getter& get,
                         const std::function<bool(const MapResult&)>& misses, bool largest_worst,
                         const std::function<std::string(const MapValue&)>& show) {
  GoalOutcome o{goal, target, "", Verdict::kIncomplete, {}, {}};
  const std::vector<MapValue> values = Values(results, get, &o.missing);
  for (const MapValue& v : values) {
    if (misses(*v.map)) o.failing.push_back(v.map->name + " (" + show(v) + ")");
  }
  if (values.empty()) {
    o.measured = "not measured";
    return o;
  }
  const MapValue& worst = Extreme(values, largest_worst);
  o.measured = std::to_string(values.size() - o.failing.size()) + "/" +
               std::to_string(values.size()) + " maps meet it; worst " + show(worst) + " (" +
               worst.map->name + ")";
  o.verdict = Decide(!o.failing.empty(), !o.missing.empty());
  return o;
}

GoalOutcome CoverageGoal(const std::vector<MapResult>& results) {
  return EveryMapGoal(results, "edge cells within 1 cell of a wall or inside furniture",
                      "share >= " + Fixed(kGoalMinCoveredShare, 2) + ", every map",
                      Figure(key::kLmapCoveredShare), MissesCoverage, false,
                      [](const MapValue& v) { return Fixed(v.value, 4); });
}

GoalOutcome DisplGoal(const std::vector<MapResult>& results) {
  return EveryMapGoal(
      results, "DisPL_ave of the walls no larger than RM-Line's", "file - RM-Line <= 0, every map",
      DisplExcess, MissesDispl, true, [](const MapValue& v) {
        if (!std::isfinite(v.value)) return std::string("no walls");
        const double cm_per_cell = v.map->Get(key::kLmapDisplCm).value_or(0) /
                                   std::max(1e-12, v.map->Get(key::kLmapDisplCells).value_or(1));
        char text[96];
        std::snprintf(text, sizeof text, "%+.3f cells, %+.2f cm", v.value, v.value * cm_per_cell);
        return std::string(text);
      });
}

// Speed as the issue measures it: the ratio of the corpus-median CPU times
// over the maps where both were timed; the median of the per-map ratios is
// shown beside it.
GoalOutcome SpeedGoal(const std::vector<MapResult>& results, bool decode) {
  const char* lmap_key = decode ? key::kLmapDecodeMs : key::kLmapEncodeMs;
  const char* png_key = decode ? key::kPngDecodeMs : key::kPngEncodeMs;
  GoalOutcome o{decode ? "decode, in process: .lmap 2.0 vs libpng of the PNG-9"
                       : "encode, in process: .lmap 2.0 vs libpng level 9",
                decode ? "libpng / .lmap >= " + Fixed(kGoalMinDecodeSpeedup, 1) + "x"
                       : ".lmap / libpng <= " + Fixed(kGoalMaxEncodeTimeRatio, 2),
                "",
                Verdict::kIncomplete,
                {},
                {}};
  std::vector<double> lmap_ms, png_ms, per_map;
  for (const MapResult& r : results) {
    const std::optional<double> mine = r.Get(lmap_key), png = r.Get(png_key);
    if (!mine || !png || *mine <= 0 || *png <= 0) {
      o.missing.push_back(r.name);
      continue;
    }
    lmap_ms.push_back(*mine);
    png_ms.push_back(*png);
    per_map.push_back(decode ? *png / *mine : *mine / *png);
  }
  if (per_map.empty()) {
    o.measured = "not measured";
    return o;
  }
  const double lmap = Median(lmap_ms), png = Median(png_ms);
  const double ratio = decode ? png / lmap : lmap / png;
  o.measured = "median CPU ms: .lmap " + Fixed(lmap, 2) + ", libpng " + Fixed(png, 2) + " -> " +
               Fixed(ratio, 2) + (decode ? "x faster" : "x the time") + " (median per map " +
               Fixed(Median(per_map), 2) + "; " + std::to_string(per_map.size()) + " maps)";
  const bool misses = decode ? ratio < kGoalMinDecodeSpeedup : ratio > kGoalMaxEncodeTimeRatio;
  o.verdict = Decide(misses, !o.missing.empty());
  return o;
}

NamedTable SummaryTable(const std::vector<GoalOutcome>& goals) {
  Table table({"goal", "target", "measured", "verdict"});
  for (std::size_t column : {1, 2, 3}) table.LeftAlign(column);
  for (const GoalOutcome& g : goals) {
    table.AddRow({g.goal, g.target, g.measured, VerdictName(g.verdict)});
  }
  return {".lmap 2.0 goals",
          "Default file = `linemap encode` with no option (exact, walls + rooms + furniture). "
          "Every figure is measured in this run: each default file decoded and compared cell "
          "for cell; layers read with DecodeLmapVectors and scored with MeasureLayerFidelity; "
          "RM-Line's DisPL_ave from the line-extraction table of the same map; times are CPU "
          "time. INCOMPLETE = no map misses the goal but some map lacks a figure it needs.",
          table};
}

std::string Join(const std::vector<std::string>& items) {
  std::string out;
  for (const std::string& item : items) out += (out.empty() ? "" : ", ") + item;
  return out;
}

// The first `most` items and how many more: the anchors goal can miss on
// a hundred (map, codec) pairs, which the anchors' losses table lists.
std::string JoinFirst(const std::vector<std::string>& items, std::size_t most) {
  if (items.size() <= most) return Join(items);
  return Join({items.begin(), items.begin() + static_cast<std::ptrdiff_t>(most)}) + " and " +
         std::to_string(items.size() - most) + " more";
}

constexpr std::size_t kListed = 12;

NamedTable MissesTable(const std::vector<GoalOutcome>& goals) {
  Table table({"goal", "verdict", "maps that miss it", "not measured"});
  for (std::size_t column : {1, 2, 3}) table.LeftAlign(column);
  for (const GoalOutcome& g : goals) {
    if (g.failing.empty() && g.missing.empty()) continue;
    table.AddRow({g.goal, VerdictName(g.verdict), JoinFirst(g.failing, kListed),
                  JoinFirst(g.missing, kListed)});
  }
  return {".lmap 2.0 goals: maps that miss them",
          "At most " + std::to_string(kListed) +
              " listed per goal; the per-map table's `misses` column and the anchors' losses "
              "table have them all.",
          table};
}

// The goals a map misses on its own (the median and speed goals are
// decided on the corpus, not per map).
std::string MapMisses(const MapResult& r) {
  std::vector<std::string> misses;
  if (MissesRoundTrip(r)) misses.push_back("exact");
  if (MissesCoverage(r)) misses.push_back("covered");
  if (MissesDispl(r)) misses.push_back("DisPL");
  const std::vector<std::string> lost = AnchorsLost(r);
  if (!lost.empty()) misses.push_back("smaller than " + Join(lost));
  std::string out;
  for (const std::string& m : misses) out += (out.empty() ? "" : "; ") + m;
  return out;
}

struct GoalColumn {
  std::string header;
  Getter get;
  int decimals = 0;
  double scale = 1.0;  // 100 for a percentage
};

std::vector<GoalColumn> PerMapColumns() {
  return {
      {"cells", Figure(key::kCells)},
      {"cells wrong", Figure(key::kLmapCellsWrong)},
      {"lmap 2.0 bytes", Figure(key::kLmapBytes)},
      {"/ PNG-9", RatioToPng9, 3},
      {"layer cost %", LayerCost, 1, 100.0},
      {"walls", Figure(key::kLmapWalls)},
      {"rooms", Figure(key::kLmapRooms)},
      {"furniture", Figure(key::kLmapFurniture)},
      {"covered", Figure(key::kLmapCoveredShare), 4},
      {"within 1", Figure(key::kLmapWithin1Share), 4},
      {"DisPL cells", Figure(key::kLmapDisplCells), 3},
      {"RM-Line cells", Figure(key::kRmLineDisplCells), 3},
      {"DisPL cm", Figure(key::kLmapDisplCm), 2},
      {"RM-Line cm", Figure(key::kRmLineDisplCm), 2},
      {"dec x libpng", DecodeSpeedupVsPng, 2},
      {"enc / libpng", EncodeTimeVsPng, 2},
  };
}

std::string Cell(std::optional<double> value, const GoalColumn& column) {
  if (value) *value *= column.scale;
  return FormatFixed(value, column.decimals);
}

NamedTable PerMapTable(const std::vector<MapResult>& results) {
  const std::vector<GoalColumn> columns = PerMapColumns();
  std::vector<std::string> headers = {"map"};
  for (const GoalColumn& c : columns) headers.push_back(c.header);
  headers.push_back("misses");
  Table table(headers);
  table.LeftAlign(headers.size() - 1);
  for (const MapResult& r : results) {
    std::vector<std::string> row = {r.name};
    for (const GoalColumn& c : columns) row.push_back(Cell(c.get(r), c));
    row.push_back(MapMisses(r));
    table.AddRow(row);
  }
  std::vector<std::string> medians = {"median"};
  for (const GoalColumn& c : columns) {
    std::vector<std::string> missing;
    const std::vector<MapValue> values = Values(results, c.get, &missing);
    medians.push_back(values.empty() ? "n/a" : Cell(MedianOf(values), c));
  }
  medians.push_back("");
  table.AddRow(medians);
  return {".lmap 2.0 goals per map",
          "cells wrong = cells of the default file's decode that differ from the map; layer "
          "cost = default bytes / --raster-only bytes - 1; covered = share of edge cells "
          "(occupied, with a free 4-neighbour) within 1 cell of a wall or inside furniture, "
          "within 1 = of a wall only; DisPL = DisPL_ave of the file's walls over the same edge "
          "cells as RM-Line's; dec x libpng = libpng decode ms / .lmap decode ms; enc / libpng "
          "= .lmap encode ms / libpng encode ms; misses = the per-map goals this map misses.",
          table};
}

}  // namespace

std::optional<double> LayerCost(const MapResult& result) {
  const std::optional<double> q = Quotient(result, key::kLmapBytes, key::kLmapRasterBytes);
  if (!q) return std::nullopt;
  return *q - 1.0;
}

std::optional<double> DecodeSpeedupVsPng(const MapResult& result) {
  return Quotient(result, key::kPngDecodeMs, key::kLmapDecodeMs);
}

std::optional<double> EncodeTimeVsPng(const MapResult& result) {
  return Quotient(result, key::kLmapEncodeMs, key::kPngEncodeMs);
}

void AddGoalFigures(MapResult* result) {
  if (auto v = LayerCost(*result)) result->figures[key::kLmapLayerCost] = *v;
  if (auto v = DecodeSpeedupVsPng(*result)) result->figures[key::kLmapDecodeSpeedupVsPng] = *v;
  if (auto v = EncodeTimeVsPng(*result)) result->figures[key::kLmapEncodeTimeVsPng] = *v;
}

const char* VerdictName(Verdict verdict) {
  switch (verdict) {
    case Verdict::kPass:
      return "PASS";
    case Verdict::kFail:
      return "FAIL";
    case Verdict::kIncomplete:
      return "INCOMPLETE";
  }
  return "?";
}

std::vector<GoalOutcome> CheckGoals(const std::vector<MapResult>& results) {
  return {
      RoundTripGoal(results),
      MedianAtMostGoal(results, "size: default .lmap 2.0 / PNG-9", RatioToPng9,
                       kGoalMedianRatioToPng9, false),
      AnchorsGoal(results),
      MedianAtMostGoal(results, "layer cost: default / --raster-only - 1", LayerCost,
                       kGoalMedianLayerCost, true),
      CoverageGoal(results),
      DisplGoal(results),
      SpeedGoal(results, true),
      SpeedGoal(results, false),
  };
}

std::vector<NamedTable> GoalTables(const std::vector<MapResult>& results) {
  const std::vector<GoalOutcome> goals = CheckGoals(results);
  std::vector<NamedTable> tables = {PerMapTable(results), SummaryTable(goals)};
  NamedTable misses = MissesTable(goals);
  if (!misses.table.rows().empty()) tables.push_back(std::move(misses));
  return tables;
}

}  // namespace linemap::bench
