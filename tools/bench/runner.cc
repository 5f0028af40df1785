#include "tools/bench/runner.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <optional>
#include <span>
#include <utility>

#include "format/file_io.h"
#include "linemap/codec.h"
#include "linemap/lmap_vectors.h"
#include "linemap/map_io.h"
#include "tools/bench/corpus.h"
#include "tools/bench/general_codecs.h"
#include "tools/bench/goals.h"
#include "tools/bench/image_anchors.h"
#include "tools/bench/jbig.h"
#include "tools/bench/lmap_figures.h"
#include "tools/bench/measure.h"
#include "tools/bench/netpbm.h"
#include "tools/bench/opencv_lines.h"
#include "tools/bench/png_codec.h"
#include "tools/bench/subprocess.h"
#include "tools/bench/synthetic.h"
#include "tools/bench/table.h"

namespace linemap::bench {
namespace {

constexpr double kMb = 1024.0 * 1024.0;

void Note(MapResult* result, const std::string& what, const Status& status) {
  result->notes.push_back(what + ": " + status.message());
}

std::span<const std::uint8_t> Bytes(const std::string& s) {
  return {reinterpret_cast<const std::uint8_t*>(s.data()), s.size()};
}

struct SmallestPng {
  std::string bytes;  // empty when libpng failed on every layout
  PngLayout layout = PngLayout::kGrey8;
};

// The smallest of the libpng layouts; sets the PNG size figures.
SmallestPng AddPngSizes(const Grid& grid, MapResult* result) {
  SmallestPng best;
  std::optional<double> png8;
  for (PngLayout layout : {PngLayout::kGrey8, PngLayout::kPalette8, PngLayout::kPalette2}) {
    StatusOr<std::string> png = EncodeTrinaryPng(grid, layout, 9);
    if (!png.ok()) {
      Note(result, std::string("PNG ") + PngLayoutName(layout), png.status());
      continue;
    }
    const double size = static_cast<double>(png->size());
    if (layout == PngLayout::kPalette2) {
      result->figures[key::kPng2Bytes] = size;
    } else {
      png8 = png8 ? std::min(*png8, size) : size;
    }
    if (best.bytes.empty() || png->size() < best.bytes.size()) best = {std::move(*png), layout};
  }
  if (png8) result->figures[key::kPng8Bytes] = *png8;
  if (!best.bytes.empty()) {
    result->figures[key::kPng9Bytes] = static_cast<double>(best.bytes.size());
  }
  return best;
}

// netpbm's own `pnmtopng -compression 9` on map_saver's PGM of the grid.
void AddPnmtopngSize(const Grid& grid, MapResult* result) {
  const StatusOr<std::uint64_t> bytes = PnmtopngBytes(grid);
  if (!bytes.ok()) return Note(result, "pnmtopng", bytes.status());
  result->figures[key::kPnmtopngBytes] = static_cast<double>(*bytes);
}

void AddGeneralCodecSizes(const Grid& grid, MapResult* result) {
  StatusOr<std::string> zstd = ZstdCompress(RawCells(grid), 19);
  if (zstd.ok()) {
    result->figures[key::kZstdBytes] = static_cast<double>(zstd->size());
  } else {
    Note(result, "zstd", zstd.status());
  }
  StatusOr<std::string> xz = XzCompress(RawCells(grid), 9, /*extreme=*/true);
  if (xz.ok()) {
    result->figures[key::kXzBytes] = static_cast<double>(xz->size());
  } else {
    Note(result, "xz -9e", xz.status());
  }
}

void AddJbigSize(const Grid& grid, MapResult* result) {
  StatusOr<JbigSizes> jbig = JbigTwoPlaneSizes(grid);
  if (jbig.ok()) {
    result->figures[key::kJbigBytes] = static_cast<double>(jbig->total());
  } else {
    Note(result, "JBIG1", jbig.status());
  }
}

// An image codec's file of the map, kept only when its decoder gives every
// pixel back; the codec's own messages name it.
void AddImageAnchor(const Grid& grid, const ImageCodec& codec, const char* bytes_key,
                    const char* encode_key, const char* decode_key, MapResult* result) {
  StatusOr<AnchorFile> file = EncodeImageAnchor(grid, codec);
  if (!file.ok()) {
    result->notes.push_back(file.status().message());
    return;
  }
  StatusOr<double> decode_ms = DecodeAndCheckImageAnchor(grid, codec, file->bytes);
  if (!decode_ms.ok()) {
    result->notes.push_back(decode_ms.status().message());
    return;
  }
  result->figures[bytes_key] = static_cast<double>(file->bytes.size());
  result->figures[encode_key] = file->encode_cpu_ms;
  result->figures[decode_key] = *decode_ms;
}

// libpng encode and decode of the layout that gave the smallest file, as a
// user would keep it: timed in blocks beside the default .lmap file's
// (AddLmapFigures), its peak memory here. `grid` and `png` must outlive the
// codec, which reads them.
RivalCodec PngRival(const Grid& grid, const SmallestPng& png) {
  const PngLayout layout = png.layout;
  const std::string* bytes = &png.bytes;
  return {[&grid, layout] { (void)EncodeTrinaryPng(grid, layout, 9); },
          [bytes] { (void)DecodeTrinaryPng(Bytes(*bytes)); }, key::kPngEncodeMs, key::kPngDecodeMs};
}

void AddPngMemory(const RivalCodec& png, MapResult* result) {
  if (auto peak = PeakExtraMemoryBytes(png.encode))
    result->figures[key::kPngEncodePeakMb] = *peak / kMb;
  if (auto peak = PeakExtraMemoryBytes(png.decode))
    result->figures[key::kPngDecodePeakMb] = *peak / kMb;
}

// `displ_cells_key` may be nullptr (DisPL in cm only); when given, the edge
// cells DisPL was averaged over are kept too (kRmLineEdgeCells).
void AddLineFigures(const Grid& grid, LineMethod method, const char* lines_key,
                    const char* displ_key, const char* displ_cells_key, const char* ms_key,
                    MapResult* result) {
  LineExtractionOptions options;
  options.method = method;
  StatusOr<LineExtraction> lines = InternalError("not run");
  const double ms = Median(TimeRuns([&] { lines = ExtractLines(grid, options); }, 1));
  if (!lines.ok()) {
    return Note(result, method == LineMethod::kRmLine ? "RM-Line" : "linemap lines",
                lines.status());
  }
  const LineFidelity fidelity = MeasureLineFidelity(lines->edges, lines->segments);
  result->figures[lines_key] = static_cast<double>(lines->segments.size());
  result->figures[displ_key] = fidelity.displ_ave_cells * grid.meta.resolution * 100.0;
  if (displ_cells_key) {
    result->figures[displ_cells_key] = fidelity.displ_ave_cells;
    result->figures[key::kRmLineEdgeCells] = static_cast<double>(fidelity.edge_cells);
  }
  result->figures[ms_key] = ms;
  if (method == LineMethod::kRmLine) result->rmline_segments = std::move(lines->segments);
}

// OpenCV's detectors (when built in), scored against the same edge map.
void AddOpenCvFigures(const Grid& grid, MapResult* result) {
  if (!OpenCvLineDetectorsBuilt()) return;
  StatusOr<std::vector<DetectorRun>> runs = OpenCvLineDetectors(grid);
  if (!runs.ok()) return Note(result, "OpenCV", runs.status());
  const EdgeMap edges = ComputeEdgeMap(grid);
  for (const DetectorRun& run : *runs) {
    const LineFidelity fidelity = MeasureLineFidelity(edges, run.segments);
    result->figures[run.key + "_lines"] = static_cast<double>(run.segments.size());
    result->figures[run.key + "_displ_cm"] =
        fidelity.displ_ave_cells * grid.meta.resolution * 100.0;
    result->figures[run.key + "_ms"] = run.ms;
  }
}

// The 2.0 goal compares the file's DisPL_ave with RM-Line's: say so when
// the two were averaged over different edge cells (then they do not compare).
void CheckSameEdgeCells(MapResult* result) {
  const std::optional<double> rmline = result->Get(key::kRmLineEdgeCells);
  const std::optional<double> file = result->Get(key::kLmapEdgeCells);
  if (rmline && file && *rmline != *file) {
    result->notes.push_back("DisPL_ave: RM-Line's is over " + FormatCount(rmline) +
                            " edge cells, the .lmap 2.0 walls' over " + FormatCount(file));
  }
}

// Mcells per CPU second for every time measured: cells / 1e6 / (ms / 1e3).
void AddThroughput(MapResult* result) {
  const std::optional<double> cells = result->Get(key::kCells);
  if (!cells) return;
  const std::pair<const char*, const char*> pairs[] = {
      {key::kPngEncodeMs, key::kPngEncodeMcellsPerS},
      {key::kPngDecodeMs, key::kPngDecodeMcellsPerS},
      {key::kLmapEncodeMs, key::kLmapEncodeMcellsPerS},
      {key::kLmapDecodeMs, key::kLmapDecodeMcellsPerS}};
  for (const auto& [ms_key, rate_key] : pairs) {
    const std::optional<double> ms = result->Get(ms_key);
    if (ms && *ms > 0) result->figures[rate_key] = *cells / 1e3 / *ms;
  }
}

}  // namespace

MapResult MeasureMap(const std::string& name, const std::string& source_path, const Grid& grid,
                     const BenchOptions& options) {
  MapResult result;
  result.name = name;
  result.path = source_path;
  result.figures[key::kWidth] = grid.width();
  result.figures[key::kHeight] = grid.height();
  result.figures[key::kCells] = static_cast<double>(grid.size());
  // The source file is the image (a YAML's `image:`), as stored on disk.
  const bool yaml = source_path.ends_with(".yaml") || source_path.ends_with(".yml");
  const std::string image = yaml ? YamlImagePath(source_path) : source_path;
  std::error_code ec;
  const auto source_size = std::filesystem::file_size(image, ec);
  if (!image.empty() && !ec) result.figures[key::kSourceBytes] = static_cast<double>(source_size);
  const int repeats = RepeatsFor(grid.size(), options.repeats);
  result.figures[key::kRepeats] = repeats;
  const SmallestPng png = AddPngSizes(grid, &result);
  AddGeneralCodecSizes(grid, &result);
  LmapMeasure lmap_measure{repeats, options.measure_memory, std::nullopt};
  if (!png.bytes.empty()) lmap_measure.rival = PngRival(grid, png);
  // RM-Line's DisPL_ave is also the bar the 2.0 file's walls must meet.
  AddLineFigures(grid, LineMethod::kRmLine, key::kRmLineLines, key::kRmLineDisplCm,
                 key::kRmLineDisplCells, key::kRmLineMs, &result);
  AddLineFigures(grid, LineMethod::kLinemap, key::kLinemapLines, key::kLinemapDisplCm, nullptr,
                 key::kLinemapMs, &result);
  AddOpenCvFigures(grid, &result);
  Status lmap = AddLmapFigures(grid, lmap_measure, &result);
  if (!lmap.ok()) Note(&result, ".lmap 2.0", lmap);
  // What runs other processes comes after every in-process timing: right
  // after the anchors' processes (cjxl, cwebp) the timings ran up to twice
  // as long (the linemap extractor's median 10.7-12.3 ms against 5.5-5.9 ms
  // in runs without anchors).
  if (lmap_measure.rival && options.measure_memory) AddPngMemory(*lmap_measure.rival, &result);
  if (options.pnmtopng && ToolAvailable("pnmtopng")) AddPnmtopngSize(grid, &result);
  // PNG-9, the ratio base, is the smallest PNG anyone would get: netpbm's
  // palette order sometimes compresses better than libpng's layouts here.
  if (auto netpbm = result.Get(key::kPnmtopngBytes)) {
    if (auto libpng = result.Get(key::kPng9Bytes); !libpng || *netpbm < *libpng) {
      result.figures[key::kPng9Bytes] = *netpbm;
    }
  }
  if (options.jbig) AddJbigSize(grid, &result);
  if (options.webp) {
    AddImageAnchor(grid, WebpCodec(), key::kWebpBytes, key::kWebpEncodeMs, key::kWebpDecodeMs,
                   &result);
  }
  if (options.jxl) {
    AddImageAnchor(grid, JpegXlCodec(), key::kJxlBytes, key::kJxlEncodeMs, key::kJxlDecodeMs,
                   &result);
  }
  AddThroughput(&result);
  AddGoalFigures(&result);
  CheckSameEdgeCells(&result);
  return result;
}

namespace {

// A map of the scaling table: width x height cells.
struct ScalingSize {
  int width = 0;
  int height = 0;
  double mcells() const { return static_cast<double>(width) * height / 1e6; }
};

// The scaling maps up to `max_mcells` (1, 4, 16, 64 or 282): squares of
// 1024, 2048, 4096 and 8192 cells a side, then the largest map nav2 users
// have reported (20,768 x 13,612 cells, 282 Mcells).
std::vector<ScalingSize> ScalingSizes(int max_mcells) {
  std::vector<ScalingSize> sizes;
  for (int side : {1, 2, 4, 8}) {
    if (side * side <= max_mcells) sizes.push_back({1024 * side, 1024 * side});
  }
  if (max_mcells >= 282) sizes.push_back({20768, 13612});
  return sizes;
}

// Timed samples per scaling map: at least 9 up to 16 Mcells, 5 at 64 and
// 3 at 282, so that each row is a median of warm runs (the first run of a
// process pays for fresh memory) and a few slow runs on a shared machine do
// not move it; a round of the 282-Mcell map takes about half a minute.
int ScalingRuns(const ScalingSize& size, int repeats) {
  const std::size_t cells = static_cast<std::size_t>(size.width) * size.height;
  const int least = cells <= (std::size_t{16} << 20) ? 9 : cells <= (std::size_t{64} << 20) ? 5 : 3;
  return std::max(least, RepeatsFor(cells, repeats));
}

// A tenth of each side from 30 % of it: 1 % of the map, away from the
// centre, where the layers' sections of the larger maps meet.
CellWindow OnePercentWindow(const Grid& grid) {
  const int c0 = grid.width() * 3 / 10, r0 = grid.height() * 3 / 10;
  return {c0, r0, c0 + std::max(1, grid.width() / 10), r0 + std::max(1, grid.height() / 10)};
}

// Whether the window decode of the file is the crop of the map it was
// made from (the default file is exact): a window that decodes other cells
// is reported as failed, not timed as a success.
bool WindowIsTheCrop(const Grid& grid, const std::vector<std::uint8_t>& lmap, const CellWindow& w) {
  const StatusOr<Grid> window = DecodeLmapRegion(lmap, w);
  if (!window.ok() || window->width() != w.col1 - w.col0 || window->height() != w.row1 - w.row0) {
    return false;
  }
  for (int r = w.row0; r < w.row1; ++r) {
    for (int c = w.col0; c < w.col1; ++c) {
      if (window->at(c - w.col0, r - w.row0) != grid.at(c, r)) return false;
    }
  }
  return true;
}

// One scaling map and its timings so far. Each timed sample of an
// operation is the mean of `loops` runs back to back (TimeSample): the
// 1-Mcell map decodes in under 2 ms, the window in 1.
struct ScalingMap {
  ScalingSize size;
  int runs = 0;
  Grid grid;
  std::string png;
  std::vector<std::uint8_t> lmap;
  std::vector<double> png_encode_ms, png_decode_ms, lmap_encode_ms, lmap_decode_ms;
  std::vector<double> lmap_window_ms;
  bool window_failed = false;
  std::optional<CellIndex> room_cell;
  std::vector<double> lmap_room_ms;
  bool room_failed = false;
  struct Loops {
    int png_encode = 1, png_decode = 1, lmap_encode = 1, lmap_decode = 1, window = 1, room = 1;
  } loops;
  double rmline_ms = 0;
  double linemap_lines_ms = 0;
};

// The cell nearest the centre of `window` (rings of growing Chebyshev
// radius, up to 64 cells) that some room of `lmap` holds, or nullopt.
std::optional<CellIndex> CellInARoom(const std::vector<std::uint8_t>& lmap,
                                     const CellWindow& window) {
  const CellIndex centre{(window.col0 + window.col1) / 2, (window.row0 + window.row1) / 2};
  for (int radius = 0; radius <= 64; ++radius) {
    for (int dr = -radius; dr <= radius; ++dr) {
      for (int dc = -radius; dc <= radius; ++dc) {
        if (std::max(std::abs(dc), std::abs(dr)) != radius) continue;
        const CellIndex cell{centre.col + dc, centre.row + dr};
        StatusOr<std::optional<LmapRoom>> room = DecodeLmapRoomAt(lmap, cell);
        if (room.ok() && room->has_value()) return cell;
      }
    }
  }
  return std::nullopt;
}

}  // namespace

int ScalingProgressSteps(int max_mcells, int repeats) {
  const std::vector<ScalingSize> sizes = ScalingSizes(max_mcells);
  int rounds = 0;
  for (const ScalingSize& size : sizes) rounds = std::max(rounds, ScalingRuns(size, repeats));
  return sizes.empty() ? 0 : static_cast<int>(sizes.size()) + rounds;
}

namespace {

// Generates the map, makes its PNG and .lmap, times the line extractors once
// and sets each operation's loops (SampleLoops: an untimed run each).
ScalingMap PrepareScalingMap(const ScalingSize& size, int repeats) {
  ScalingMap map;
  map.size = size;
  map.runs = ScalingRuns(size, repeats);
  map.grid = GenerateOfficeMapOfSize(size.width, size.height);
  if (StatusOr<std::string> png = EncodeTrinaryPng(map.grid, PngLayout::kGrey8, 9); png.ok()) {
    map.png = *std::move(png);
  }
  if (StatusOr<std::vector<std::uint8_t>> lmap = EncodeLmap(map.grid, EncodeOptions()); lmap.ok()) {
    map.lmap = *std::move(lmap);
    map.room_cell = CellInARoom(map.lmap, OnePercentWindow(map.grid));
  }
  LineExtractionOptions options;
  options.method = LineMethod::kRmLine;
  map.rmline_ms = TimeRuns([&] { (void)ExtractLines(map.grid, options); }, 1)[0];
  const LineExtractionOptions linemap_defaults;
  map.linemap_lines_ms = TimeRuns([&] { (void)ExtractLines(map.grid, linemap_defaults); }, 1)[0];
  // The PNG's and the .lmap file's encodes take tens of ms at the least: a
  // run each (their loop count would be 1).
  if (!map.png.empty()) {
    map.loops.png_decode = SampleLoops([&] { (void)DecodeTrinaryPng(Bytes(map.png)); });
  }
  if (!map.lmap.empty()) {
    map.loops.lmap_decode = SampleLoops([&] { (void)DecodeLmap(map.lmap); });
    const CellWindow window = OnePercentWindow(map.grid);
    map.window_failed = !WindowIsTheCrop(map.grid, map.lmap, window);
    map.loops.window = SampleLoops([&] { (void)DecodeLmapRegion(map.lmap, window); });
    if (map.room_cell) {
      map.loops.room = SampleLoops([&] { (void)DecodeLmapRoomAt(map.lmap, *map.room_cell); });
    }
  }
  return map;
}

// One round's sample of every operation of `map`.
void TimeScalingRound(ScalingMap* map) {
  const ScalingMap::Loops& loops = map->loops;
  map->png_encode_ms.push_back(TimeSample(
      [&] { (void)EncodeTrinaryPng(map->grid, PngLayout::kGrey8, 9); }, loops.png_encode));
  if (!map->png.empty()) {
    map->png_decode_ms.push_back(
        TimeSample([&] { (void)DecodeTrinaryPng(Bytes(map->png)); }, loops.png_decode));
  }
  if (map->lmap.empty()) return;
  map->lmap_encode_ms.push_back(
      TimeSample([&] { (void)EncodeLmap(map->grid, EncodeOptions()); }, loops.lmap_encode));
  map->lmap_decode_ms.push_back(
      TimeSample([&] { (void)DecodeLmap(map->lmap); }, loops.lmap_decode));
  const CellWindow window = OnePercentWindow(map->grid);
  bool window_ok = true;
  map->lmap_window_ms.push_back(TimeSample(
      [&] { window_ok = window_ok && DecodeLmapRegion(map->lmap, window).ok(); }, loops.window));
  map->window_failed = map->window_failed || !window_ok;
  if (map->room_cell) {
    bool room_ok = true;
    map->lmap_room_ms.push_back(TimeSample(
        [&] {
          const StatusOr<std::optional<LmapRoom>> room =
              DecodeLmapRoomAt(map->lmap, *map->room_cell);
          room_ok = room_ok && room.ok() && room->has_value();
        },
        loops.room));
    map->room_failed = map->room_failed || !room_ok;
  }
}

}  // namespace

std::vector<ScalingRow> RunScaling(int max_mcells, int repeats,
                                   const std::function<void(const std::string&)>& progress) {
  std::vector<ScalingMap> maps;
  for (const ScalingSize& size : ScalingSizes(max_mcells)) {
    progress("preparing " + FormatFixed(size.mcells(), 1) + " Mcells");
    maps.push_back(PrepareScalingMap(size, repeats));
  }
  // The runs are interleaved (round k times every size once), so that a slow
  // phase of a shared machine slows every size alike rather than one row.
  int rounds = 0;
  for (const ScalingMap& map : maps) rounds = std::max(rounds, map.runs);
  for (int round = 0; round < rounds; ++round) {
    progress("round " + std::to_string(round + 1) + "/" + std::to_string(rounds));
    for (ScalingMap& map : maps) {
      if (round < map.runs) TimeScalingRound(&map);
    }
  }
  std::vector<ScalingRow> rows;
  for (const ScalingMap& map : maps) {
    const double mcells = map.size.mcells();
    ScalingRow row;
    row.mcells = mcells;
    row.width = map.size.width;
    row.height = map.size.height;
    row.repeats = map.runs;
    const auto fastest = [](const std::vector<double>& v) {
      return *std::min_element(v.begin(), v.end());
    };
    row.png_encode_ms_per_mcell = Median(map.png_encode_ms) / mcells;
    row.png_encode_fastest_ms_per_mcell = fastest(map.png_encode_ms) / mcells;
    if (!map.png_decode_ms.empty()) {
      row.png_decode_ms_per_mcell = Median(map.png_decode_ms) / mcells;
      row.png_decode_fastest_ms_per_mcell = fastest(map.png_decode_ms) / mcells;
    }
    row.rmline_ms_per_mcell = map.rmline_ms / mcells;
    row.linemap_lines_ms_per_mcell = map.linemap_lines_ms / mcells;
    if (!map.lmap_encode_ms.empty()) {
      row.lmap_encode_ms_per_mcell = Median(map.lmap_encode_ms) / mcells;
      row.lmap_decode_ms_per_mcell = Median(map.lmap_decode_ms) / mcells;
      row.lmap_encode_fastest_ms_per_mcell = fastest(map.lmap_encode_ms) / mcells;
      row.lmap_decode_fastest_ms_per_mcell = fastest(map.lmap_decode_ms) / mcells;
      if (!map.window_failed) row.lmap_window_ms = Median(map.lmap_window_ms);
      if (row.lmap_window_ms && *row.lmap_window_ms > 0) {
        row.lmap_window_speedup = Median(map.lmap_decode_ms) / *row.lmap_window_ms;
      }
      if (!map.lmap_room_ms.empty() && !map.room_failed)
        row.lmap_room_ms = Median(map.lmap_room_ms);
    }
    rows.push_back(row);
  }
  return rows;
}

}  // namespace linemap::bench
