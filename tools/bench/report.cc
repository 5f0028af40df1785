#include "tools/bench/report.h"

#include <algorithm>
#include <cstdio>
#include <functional>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "tools/bench/image_anchors.h"
#include "tools/bench/opencv_lines.h"

namespace linemap::bench {
namespace {

bool AnyMapHas(const std::vector<MapResult>& results, const Column& column) {
  for (const MapResult& result : results) {
    if (ColumnValue(result, column)) return true;
  }
  return false;
}

// Columns no map has (a comparator skipped or not installed: the notes say
// why) are left out rather than printed as a column of n/a.
Table ColumnsTable(const std::vector<MapResult>& results, std::vector<Column> columns) {
  std::erase_if(columns, [&](const Column& column) { return !AnyMapHas(results, column); });
  std::vector<std::string> headers = {"map"};
  for (const Column& column : columns) headers.push_back(column.header);
  Table table(headers);
  for (const MapResult& result : results) {
    std::vector<std::string> row = {result.name};
    for (const Column& column : columns) {
      row.push_back(FormatFixed(ColumnValue(result, column), column.decimals));
    }
    table.AddRow(row);
  }
  std::vector<std::string> medians = {"median"};
  for (const Column& column : columns) {
    medians.push_back(FormatFixed(ColumnMedian(results, column), column.decimals));
  }
  table.AddRow(medians);
  return table;
}

struct SizeMethod {
  std::string name;
  std::string figure;  // size in bytes
  std::string encode_ms;
  std::string decode_ms;
};

// The encoder's command line as a user would type it, without the paths.
std::string CommandText(const std::vector<std::string>& argv) {
  std::string text;
  for (const std::string& arg : argv) {
    if (arg == "{in}" || arg == "{out}" || arg == "-o" || arg == "-quiet") continue;
    text += (text.empty() ? "" : " ") + arg;
  }
  return text;
}

std::string JxlLabel() { return "JPEG XL lossless (" + CommandText(JpegXlCodec().encode) + ")"; }
std::string WebpLabel() { return "WebP lossless (" + CommandText(WebpCodec().encode) + ")"; }

std::vector<SizeMethod> SizeMethods() {
  return {
      {"source image (as stored)", key::kSourceBytes, "", ""},
      {"PNG-9, smallest of the four below", key::kPng9Bytes, key::kPngEncodeMs, key::kPngDecodeMs},
      {"PNG 8-bit (grey or palette, libpng z9)", key::kPng8Bytes, "", ""},
      {"PNG 2-bit palette (libpng z9)", key::kPng2Bytes, "", ""},
      {"pnmtopng -compression 9", key::kPnmtopngBytes, "", ""},
      {"zstd -19 (raw cells)", key::kZstdBytes, "", ""},
      {"xz -9e (raw cells)", key::kXzBytes, "", ""},
      {"JBIG1 two planes (pbmtojbg -q)", key::kJbigBytes, "", ""},
      {WebpLabel(), key::kWebpBytes, key::kWebpEncodeMs, key::kWebpDecodeMs},
      {JxlLabel(), key::kJxlBytes, key::kJxlEncodeMs, key::kJxlDecodeMs},
      {".lmap 2.0 (default: exact, walls + rooms + furniture)", key::kLmapBytes, key::kLmapEncodeMs,
       key::kLmapDecodeMs},
      {".lmap 2.0 --raster-only", key::kLmapRasterBytes, "", ""},
      {".lmap 2.3 --compact (exact, layers, cells coded for size)", key::kLmapCompactBytes, "",
       key::kLmapCompactDecodeMs},
      {".lmap 2.3 --compact --raster-only", key::kLmapRasterCompactBytes, "", ""},
  };
}

std::string MedianText(const std::vector<MapResult>& results, const std::string& figure,
                       int decimals, bool ratio = false) {
  if (figure.empty()) return "";
  return FormatFixed(ColumnMedian(results, {figure, "", decimals, ratio}), decimals);
}

// The per-map size columns: the source, every comparator and every .lmap
// file, in bytes (with the cells and PNG-9, the base) or as ratios to
// PNG-9 (3 decimals).
std::vector<Column> SizeColumns(bool as_ratio) {
  const std::pair<const char*, const char*> sizes[] = {
      {key::kSourceBytes, "source"},
      {key::kPng8Bytes, "PNG 8b"},
      {key::kPng2Bytes, "PNG 2b"},
      {key::kPnmtopngBytes, "pnmtopng"},
      {key::kZstdBytes, "zstd-19"},
      {key::kXzBytes, "xz-9e"},
      {key::kJbigBytes, "JBIG1"},
      {key::kWebpBytes, "WebP"},
      {key::kJxlBytes, "JPEG XL"},
      {key::kLmapBytes, "lmap 2.0"},
      {key::kLmapRasterBytes, "lmap raster"},
      {key::kLmapCompactBytes, "compact"},
      {key::kLmapRasterCompactBytes, "raster compact"}};
  std::vector<Column> columns;
  if (!as_ratio) columns = {{key::kCells, "cells"}};
  for (const auto& [figure, header] : sizes) {
    columns.push_back(as_ratio ? Column{figure, header, 3, true} : Column{figure, header});
    // PNG-9, the base of the ratios, follows the source among the sizes.
    if (!as_ratio && std::string(figure) == key::kSourceBytes) {
      columns.push_back({key::kPng9Bytes, "PNG-9"});
    }
  }
  return columns;
}

}  // namespace

std::vector<NamedTable> PerMapTables(const std::vector<MapResult>& results) {
  std::vector<NamedTable> tables;
  tables.push_back(
      {"Sizes (bytes)",
       "PNG-9 = the smallest of libpng's 8-bit grey, 8-bit palette and 2-bit palette at zlib "
       "level 9 and netpbm's pnmtopng -compression 9 (the ratio base; encode / decode times "
       "are libpng's on its smallest layout); zstd and xz compress the raw cells (1 byte per "
       "cell; xz -9e = preset 9 | LZMA_PRESET_EXTREME); JBIG1 is the sum of the not-free and "
       "occupied bit-planes; WebP and JPEG XL encode map_saver's 8-bit grey PGM (" +
           CommandText(WebpCodec().encode) + "; " + CommandText(JpegXlCodec().encode) +
           "), each file decoded back (dwebp, djxl) and checked pixel for pixel. lmap 2.0 = "
           "`linemap encode` with no option (exact, walls + rooms + furniture); lmap raster = "
           "--raster-only (exact, cells only); compact and raster compact = the same with "
           "--compact (cells coded for size, version 2.3).",
       ColumnsTable(results, SizeColumns(/*as_ratio=*/false))});
  tables.push_back({"Size ratio to PNG-9", "Below 1 = smaller than the smallest PNG.",
                    ColumnsTable(results, SizeColumns(/*as_ratio=*/true))});
  tables.push_back(
      {"Line extraction",
       "Lines and DisPL_ave (RM-Line Eq. 5: mean distance from an edge cell to the nearest "
       "segment) in cm, extraction CPU time in ms (one run).",
       ColumnsTable(results, {{key::kRmLineLines, "RM-Line lines"},
                              {key::kRmLineDisplCm, "DisPL cm", 2},
                              {key::kRmLineMs, "ms", 1},
                              {key::kLinemapLines, "linemap lines"},
                              {key::kLinemapDisplCm, "DisPL cm", 2},
                              {key::kLinemapMs, "ms", 1}})});
  if (OpenCvLineDetectorsBuilt()) {
    std::vector<Column> columns;
    for (const DetectorName& name : OpenCvDetectorNames()) {
      const std::string k = name.key;
      columns.push_back({k + "_lines", std::string(name.label) + " lines"});
      columns.push_back({k + "_displ_cm", "DisPL cm", 2});
      columns.push_back({k + "_ms", "ms", 1});
    }
    tables.push_back(
        {"OpenCV 4.6 line detectors",
         "On the map drawn as RM-Line's paper did (obstacles grey 100, else 0) and as black / "
         "white; DisPL_ave over the same edge cells as RM-Line; CPU ms of the detector.",
         ColumnsTable(results, columns)});
  }
  tables.push_back(
      {"Speed and memory",
       "CPU time per run, median of `runs` samples (5 up to 1 Mcell, 3 up to 4 Mcells, 1 "
       "above; a sample of an operation under 10 ms is the mean of as many runs back to back "
       "as reach 10 ms, at most 100), libpng's and the .lmap file's in blocks (an untimed run, "
       "then half "
       "the samples; libpng, .lmap, .lmap, libpng); peak = "
       "resident memory the operation adds, in MB, measured once in a forked child; "
       "Mcells/s = cells / CPU time. lmap2 = the default .lmap 2.0 file (encode with its "
       "layers; decode of the whole grid).",
       ColumnsTable(results, {{key::kRepeats, "runs"},
                              {key::kPngEncodeMs, "PNG enc ms", 1},
                              {key::kPngDecodeMs, "PNG dec ms", 1},
                              {key::kPngEncodePeakMb, "PNG enc MB", 1},
                              {key::kPngDecodePeakMb, "PNG dec MB", 1},
                              {key::kLmapEncodeMs, "lmap2 enc ms", 1},
                              {key::kLmapDecodeMs, "lmap2 dec ms", 1},
                              {key::kLmapEncodePeakMb, "lmap2 enc MB", 1},
                              {key::kLmapDecodePeakMb, "lmap2 dec MB", 1},
                              {key::kPngEncodeMcellsPerS, "PNG enc Mcells/s", 1},
                              {key::kPngDecodeMcellsPerS, "PNG dec Mcells/s", 1},
                              {key::kLmapEncodeMcellsPerS, "lmap2 enc Mcells/s", 1},
                              {key::kLmapDecodeMcellsPerS, "lmap2 dec Mcells/s", 1}})});
  return tables;
}

NamedTable MediansTable(const std::vector<MapResult>& results) {
  Table table({"method", "maps", "median bytes", "median ratio", "worst ratio", "maps < PNG-9",
               "enc ms", "dec ms"});
  for (const SizeMethod& method : SizeMethods()) {
    std::size_t maps = 0, smaller = 0;
    double worst = 0;
    for (const MapResult& result : results) {
      const std::optional<double> ratio = result.RatioToPng9(method.figure);
      if (!ratio) continue;
      ++maps;
      worst = std::max(worst, *ratio);
      if (*ratio < 1.0) ++smaller;
    }
    const bool any = maps > 0;
    table.AddRow({method.name, std::to_string(maps), MedianText(results, method.figure, 0),
                  MedianText(results, method.figure, 3, true), any ? FormatFixed(worst, 3) : "n/a",
                  any ? std::to_string(smaller) + "/" + std::to_string(maps) : "n/a",
                  MedianText(results, method.encode_ms, 1),
                  MedianText(results, method.decode_ms, 1)});
  }
  return {"Medians over the corpus",
          "Ratio = size / PNG-9 per map, then the median (not the ratio of the medians). "
          "Every method is exact. n/a = not measured in "
          "this build (see the notes). WebP and JPEG XL times are the CPU time of the "
          "cwebp / dwebp / cjxl / djxl process, one run, start-up and file I/O included.",
          table};
}

NamedTable LineMediansTable(const std::vector<MapResult>& results) {
  Table table({"extractor", "maps", "median lines", "median DisPL cm", "median ms"});
  auto row = [&](const std::string& name, const char* lines, const char* displ, const char* ms) {
    std::size_t maps = 0;
    for (const MapResult& result : results) maps += result.Get(lines).has_value() ? 1 : 0;
    table.AddRow({name, std::to_string(maps), MedianText(results, lines, 0),
                  MedianText(results, displ, 2), MedianText(results, ms, 1)});
  };
  // The labels state the library defaults the bench runs with.
  const LineExtractionOptions defaults;
  char rmline[96], linemap[96];
  std::snprintf(rmline, sizeof rmline, "RM-Line (dtheta %g deg, ds %g cell)",
                defaults.rmline_dtheta_deg, defaults.rmline_ds_cells);
  std::snprintf(linemap, sizeof linemap, "linemap extractor (epsilon %g cells)",
                defaults.epsilon_cells);
  row(rmline, key::kRmLineLines, key::kRmLineDisplCm, key::kRmLineMs);
  row(linemap, key::kLinemapLines, key::kLinemapDisplCm, key::kLinemapMs);
  for (const DetectorName& name : OpenCvDetectorNames()) {
    const std::string k = name.key;
    const std::string lines = k + "_lines", displ = k + "_displ_cm", ms = k + "_ms";
    if (OpenCvLineDetectorsBuilt()) {
      row(std::string("OpenCV ") + name.label, lines.c_str(), displ.c_str(), ms.c_str());
    }
  }
  return {"Line extraction medians",
          OpenCvLineDetectorsBuilt()
              ? ""
              : "OpenCV detectors: not built (configure with -DLINEMAP_BENCH_OPENCV=ON).",
          table};
}

namespace {

// One figure of a scaling row, per Mcell; unset where it was not measured.
using ScalingFigure = std::function<std::optional<double>(const ScalingRow&)>;

std::optional<double> Figure(double value) { return value; }

// largest / smallest - 1 of a figure over the sizes, in %; unset when a size
// lacks it or one is not positive.
std::optional<double> Spread(const std::vector<ScalingRow>& rows, const ScalingFigure& figure) {
  std::optional<double> lo, hi;
  for (const ScalingRow& row : rows) {
    const std::optional<double> v = figure(row);
    if (!v) return std::nullopt;
    lo = lo ? std::min(*lo, *v) : *v;
    hi = hi ? std::max(*hi, *v) : *v;
  }
  if (!lo || *lo <= 0) return std::nullopt;
  return 100.0 * (*hi / *lo - 1.0);
}

// A spread row of the scaling table: the spread of each timed column's
// figure (PNG encode and decode, RM-Line, linemap lines, lmap2 encode and
// decode), blank where `columns` holds no figure, and none for the window.
std::vector<std::string> SpreadRow(const std::string& label, const std::vector<ScalingRow>& rows,
                                   const std::vector<ScalingFigure>& columns) {
  std::vector<std::string> cells = {label, "", ""};
  for (const ScalingFigure& figure : columns) {
    cells.push_back(figure ? FormatFixed(Spread(rows, figure), 0) : "");
  }
  cells.insert(cells.end(), {"", "", ""});
  return cells;
}

}  // namespace

NamedTable ScalingTable(const std::vector<ScalingRow>& rows) {
  Table table({"map", "Mcells", "runs", "PNG enc ms/Mcell", "PNG dec ms/Mcell", "RM-Line ms/Mcell",
               "linemap lines ms/Mcell", "lmap2 enc ms/Mcell", "lmap2 dec ms/Mcell",
               "1 % window ms", "window x faster", "room ms"});
  for (const ScalingRow& row : rows) {
    table.AddRow(
        {std::to_string(row.width) + " x " + std::to_string(row.height), FormatFixed(row.mcells, 1),
         std::to_string(row.repeats), FormatFixed(row.png_encode_ms_per_mcell, 1),
         FormatFixed(row.png_decode_ms_per_mcell, 1), FormatFixed(row.rmline_ms_per_mcell, 1),
         FormatFixed(row.linemap_lines_ms_per_mcell, 1),
         FormatFixed(row.lmap_encode_ms_per_mcell, 1), FormatFixed(row.lmap_decode_ms_per_mcell, 1),
         FormatFixed(row.lmap_window_ms, 2), FormatFixed(row.lmap_window_speedup, 1),
         FormatFixed(row.lmap_room_ms, 2)});
  }
  table.AddRow(SpreadRow("spread %", rows,
                         {[](const ScalingRow& r) { return Figure(r.png_encode_ms_per_mcell); },
                          [](const ScalingRow& r) { return Figure(r.png_decode_ms_per_mcell); },
                          [](const ScalingRow& r) { return Figure(r.rmline_ms_per_mcell); },
                          [](const ScalingRow& r) { return Figure(r.linemap_lines_ms_per_mcell); },
                          [](const ScalingRow& r) { return r.lmap_encode_ms_per_mcell; },
                          [](const ScalingRow& r) { return r.lmap_decode_ms_per_mcell; }}));
  // The same over each size's fastest run (the line extractors run once).
  table.AddRow(SpreadRow(
      "spread % of the fastest runs", rows,
      {[](const ScalingRow& r) { return Figure(r.png_encode_fastest_ms_per_mcell); },
       [](const ScalingRow& r) { return Figure(r.png_decode_fastest_ms_per_mcell); }, nullptr,
       nullptr, [](const ScalingRow& r) { return r.lmap_encode_fastest_ms_per_mcell; },
       [](const ScalingRow& r) { return r.lmap_decode_fastest_ms_per_mcell; }}));
  return {"Scaling",
          "Generated office maps (96-cell rooms, doors, furniture, speckle) of 1024^2, 2048^2, "
          "4096^2 and 8192^2 cells and of 20,768 x 13,612 (the largest map nav2 users have "
          "reported; the 20,768-cell square's corner), each drawn anew rather "
          "than tiled (zlib would find the repeated tiles and speed up); lmap2 = the default "
          ".lmap 2.0 file; Mcells = millions of cells; CPU time per Mcell (median of `runs` "
          "samples: at least 9 up to 16 Mcells, 5 at 67 and 3 at 283; a sample of an operation "
          "under 10 ms is the mean of as many runs back to back as reach 10 ms, at most 100; "
          "RM-Line and linemap lines one run). spread = largest / smallest - 1 (goal: within "
          "25%), of the medians and of each size's fastest sample (a shared machine only adds "
          "time, so a slow phase that moved one size's median shows as a gap between the two). "
          "1 % window: a tenth of each side from 30 % of it, decoded with DecodeLmapRegion "
          "(median ms), and how many times faster than the whole map (goal: 20x; the window "
          "meets at least one tile, 1024 cells a side up to 4096 and 512 beyond, and on maps up "
          "to 4096 cells a side it reads all the layers, which are one section there, so it "
          "cannot gain much on those). room: one room as a viewer loads it when the user picks "
          "a point near the window's centre (DecodeLmapRoomAt: the header, the layer sections "
          "around the point, the tiles of the room's box; median ms).",
          table};
}

NamedTable ScalingGoalsTable(const std::vector<ScalingRow>& rows) {
  constexpr double kGoalSpreadPercent = 25.0;
  constexpr double kGoalWindowSpeedup = 20.0;
  Table table({"goal", "measured", "verdict"});
  const auto spread_row = [&](const std::string& what, const ScalingFigure& median,
                              const ScalingFigure& fastest) {
    const std::optional<double> spread = Spread(rows, median);
    const std::optional<double> of_fastest = Spread(rows, fastest);
    table.AddRow({what + " cost per Mcell flat within 25 % over the sizes",
                  spread ? FormatFixed(*spread, 0) + " % (of the fastest runs: " +
                               (of_fastest ? FormatFixed(*of_fastest, 0) : "n/a") + " %)"
                         : "n/a",
                  !spread                         ? "INCOMPLETE"
                  : *spread <= kGoalSpreadPercent ? "PASS"
                                                  : "FAIL"});
  };
  spread_row(
      "encode", [](const ScalingRow& r) { return r.lmap_encode_ms_per_mcell; },
      [](const ScalingRow& r) { return r.lmap_encode_fastest_ms_per_mcell; });
  spread_row(
      "decode", [](const ScalingRow& r) { return r.lmap_decode_ms_per_mcell; },
      [](const ScalingRow& r) { return r.lmap_decode_fastest_ms_per_mcell; });
  std::string speedups;
  bool all_measured = !rows.empty(), all_fast = true;
  for (const ScalingRow& row : rows) {
    speedups += (speedups.empty() ? "" : ", ") +
                (row.lmap_window_speedup ? FormatFixed(*row.lmap_window_speedup, 1) + "x"
                                         : std::string("failed")) +
                " at " + FormatFixed(row.mcells, 1);
    all_measured = all_measured && row.lmap_window_speedup.has_value();
    all_fast =
        all_fast && row.lmap_window_speedup && *row.lmap_window_speedup >= kGoalWindowSpeedup;
  }
  table.AddRow(
      {"1 % window at least 20x faster than the whole map, its cells the crop of the "
       "map's, at every size",
       speedups + " Mcells",
       !all_measured ? "FAIL"
       : all_fast    ? "PASS"
                     : "FAIL"});
  return {"Huge-map goals",
          "From the scaling table above: spread = largest / smallest - 1 of the medians per "
          "Mcell over the sizes; a window that fails or whose cells differ from the crop of "
          "the map counts as failed.",
          table};
}

std::string ResultsCsv(const std::vector<MapResult>& results) {
  std::set<std::string> keys;
  for (const MapResult& result : results) {
    for (const auto& [figure, value] : result.figures) keys.insert(figure);
  }
  std::vector<std::string> headers = {"map", "path"};
  headers.insert(headers.end(), keys.begin(), keys.end());
  headers.push_back("notes");
  Table table(headers);
  for (const MapResult& result : results) {
    std::vector<std::string> row = {result.name, result.path};
    for (const std::string& figure : keys) {
      const std::optional<double> v = result.Get(figure);
      row.push_back(v ? FormatFixed(v, 6) : "");
    }
    std::string notes;
    for (const std::string& note : result.notes) notes += (notes.empty() ? "" : "; ") + note;
    row.push_back(notes);
    table.AddRow(row);
  }
  return table.Csv();
}

std::string TablesText(const std::vector<NamedTable>& tables) {
  std::string out;
  for (const NamedTable& t : tables) {
    out += "\n== " + t.title + " ==\n";
    if (!t.caption.empty()) out += t.caption + "\n";
    out += t.table.Text();
  }
  return out;
}

std::string TablesMarkdown(const std::vector<NamedTable>& tables) {
  std::string out;
  for (const NamedTable& t : tables) {
    out += "\n### " + t.title + "\n\n";
    if (!t.caption.empty()) out += t.caption + "\n\n";
    out += t.table.Markdown();
  }
  return out;
}

}  // namespace linemap::bench
