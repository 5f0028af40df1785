// The tables `linemap bench` prints and writes: per-map tables, the medians
// by method, the scaling table; as text, Markdown and CSV.
#ifndef LINEMAP_TOOLS_BENCH_REPORT_H_
#define LINEMAP_TOOLS_BENCH_REPORT_H_

#include <string>
#include <vector>

#include "tools/bench/results.h"
#include "tools/bench/runner.h"
#include "tools/bench/table.h"

namespace linemap::bench {

struct NamedTable {
  std::string title;
  std::string caption;  // one or two sentences under the title; may be empty
  Table table;
};

// Per map: sizes, ratios to PNG-9, line extraction, speed and memory.
std::vector<NamedTable> PerMapTables(const std::vector<MapResult>& results);

// One row per method: median size and ratio to PNG-9, worst ratio, maps
// smaller than PNG-9, encode / decode time.
NamedTable MediansTable(const std::vector<MapResult>& results);

// One row per line extractor: median lines, DisPL_ave, time.
NamedTable LineMediansTable(const std::vector<MapResult>& results);

NamedTable ScalingTable(const std::vector<ScalingRow>& rows);

// The huge-map goals of the scaling table, with PASS / FAIL: the encode's
// and the decode's cost per Mcell flat within 25 % over the sizes (of the
// medians), and a 1 % window at least 20x faster than the whole map at
// every size, its cells the crop of the map's.
NamedTable ScalingGoalsTable(const std::vector<ScalingRow>& rows);

// Every figure of every map, one row per map, columns named by the keys.
std::string ResultsCsv(const std::vector<MapResult>& results);

std::string TablesText(const std::vector<NamedTable>& tables);
std::string TablesMarkdown(const std::vector<NamedTable>& tables);

}  // namespace linemap::bench

#endif  // LINEMAP_TOOLS_BENCH_REPORT_H_
