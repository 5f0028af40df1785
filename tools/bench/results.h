// What `linemap bench` measures on one map, as named figures, and the
// columns and summaries built from them.
#ifndef LINEMAP_TOOLS_BENCH_RESULTS_H_
#define LINEMAP_TOOLS_BENCH_RESULTS_H_

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "linemap/cells.h"
#include "linemap/lines.h"

namespace linemap::bench {

// Figure keys (also the CSV column names).
namespace key {
inline constexpr const char* kWidth = "width";
inline constexpr const char* kHeight = "height";
inline constexpr const char* kCells = "cells";
inline constexpr const char* kSourceBytes = "source_bytes";
inline constexpr const char* kPng8Bytes = "png8_bytes";          // smaller of 8-bit grey / palette
inline constexpr const char* kPng2Bytes = "png2_bytes";          // 2-bit packed palette
inline constexpr const char* kPng9Bytes = "png9_bytes";          // smallest PNG: the ratio base
inline constexpr const char* kPnmtopngBytes = "pnmtopng_bytes";  // netpbm, as a cross-check
inline constexpr const char* kZstdBytes = "zstd19_bytes";
inline constexpr const char* kXzBytes = "xz9e_bytes";  // xz -9e (preset 9, extreme)
inline constexpr const char* kJbigBytes = "jbig_bytes";
inline constexpr const char* kJxlBytes = "jxl_bytes";    // cjxl lossless, effort 9
inline constexpr const char* kWebpBytes = "webp_bytes";  // cwebp -lossless -z 9
// .lmap 2.0 as `linemap encode` writes it by default: exact, with the wall,
// room and furniture layers. Its encode / decode times and memory are the
// kLmap* speed figures below.
inline constexpr const char* kLmapBytes = "lmap2_bytes";
// .lmap 2.0 --raster-only: exact, cells only (the smallest exact file).
inline constexpr const char* kLmapRasterBytes = "lmap2_raster_bytes";
// .lmap 2.3 --compact, with the layers and --raster-only: exact, the cells
// coded for size (EncodeOptions::compact); the decode time of the former.
inline constexpr const char* kLmapCompactBytes = "lmap2_compact_bytes";
inline constexpr const char* kLmapRasterCompactBytes = "lmap2_raster_compact_bytes";
inline constexpr const char* kLmapCompactDecodeMs = "lmap2_compact_decode_ms";
inline constexpr const char* kPngEncodeMs = "png_encode_ms";
inline constexpr const char* kPngDecodeMs = "png_decode_ms";
inline constexpr const char* kPngEncodePeakMb = "png_encode_peak_mb";
inline constexpr const char* kPngDecodePeakMb = "png_decode_peak_mb";
inline constexpr const char* kLmapEncodeMs = "lmap2_encode_ms";
inline constexpr const char* kLmapDecodeMs = "lmap2_decode_ms";
// CPU time of the cjxl / djxl / cwebp / dwebp process, one run (start-up and
// file reads and writes included).
inline constexpr const char* kJxlEncodeMs = "jxl_encode_ms";
inline constexpr const char* kJxlDecodeMs = "jxl_decode_ms";
inline constexpr const char* kWebpEncodeMs = "webp_encode_ms";
inline constexpr const char* kWebpDecodeMs = "webp_decode_ms";
// Throughput, Mcells per CPU second, from the times above.
inline constexpr const char* kPngEncodeMcellsPerS = "png_encode_mcells_per_s";
inline constexpr const char* kPngDecodeMcellsPerS = "png_decode_mcells_per_s";
inline constexpr const char* kLmapEncodeMcellsPerS = "lmap2_encode_mcells_per_s";
inline constexpr const char* kLmapDecodeMcellsPerS = "lmap2_decode_mcells_per_s";
inline constexpr const char* kLmapEncodePeakMb = "lmap2_encode_peak_mb";
inline constexpr const char* kLmapDecodePeakMb = "lmap2_decode_peak_mb";
inline constexpr const char* kRepeats = "timing_repeats";
inline constexpr const char* kRmLineLines = "rmline_lines";
inline constexpr const char* kRmLineDisplCells = "rmline_displ_cells";
inline constexpr const char* kRmLineEdgeCells = "rmline_edge_cells";  // DisPL's denominator
inline constexpr const char* kRmLineDisplCm = "rmline_displ_cm";
inline constexpr const char* kRmLineMs = "rmline_ms";
inline constexpr const char* kLinemapLines = "linemap_lines";
inline constexpr const char* kLinemapDisplCm = "linemap_displ_cm";
inline constexpr const char* kLinemapMs = "linemap_ms";
// The default 2.0 file checked against the map: cells its decode gets wrong
// (0 = exact; every cell when the decode fails or has another size), and the
// same for the --raster-only file.
inline constexpr const char* kLmapCellsWrong = "lmap2_cells_wrong";
inline constexpr const char* kLmapRasterCellsWrong = "lmap2_raster_cells_wrong";
inline constexpr const char* kLmapCompactCellsWrong = "lmap2_compact_cells_wrong";
inline constexpr const char* kLmapRasterCompactCellsWrong = "lmap2_raster_compact_cells_wrong";
// The default file's layers (read with DecodeLmapVectors, no raster decode):
// how many, and MeasureLayerFidelity() of them against the map.
inline constexpr const char* kLmapWalls = "lmap2_walls";                 // polylines
inline constexpr const char* kLmapWallSegments = "lmap2_wall_segments";  // their segments
inline constexpr const char* kLmapRooms = "lmap2_rooms";
inline constexpr const char* kLmapFurniture = "lmap2_furniture";
inline constexpr const char* kLmapEdgeCells = "lmap2_edge_cells";
inline constexpr const char* kLmapWithin1Share = "lmap2_within1_share";  // of edge cells
inline constexpr const char* kLmapCoveredShare = "lmap2_covered_share";  // ... or in furniture
inline constexpr const char* kLmapDisplCells = "lmap2_displ_cells";      // DisPL_ave of the walls
inline constexpr const char* kLmapDisplCm = "lmap2_displ_cm";
// Derived per map for the 2.0 goals (see goals.h).
inline constexpr const char* kLmapLayerCost = "lmap2_layer_cost";  // default / raster-only - 1
inline constexpr const char* kLmapDecodeSpeedupVsPng = "lmap2_decode_speedup_vs_png";
inline constexpr const char* kLmapEncodeTimeVsPng = "lmap2_encode_time_vs_png";
}  // namespace key

struct MapResult {
  std::string name;
  std::string path;
  std::map<std::string, double> figures;
  std::vector<std::string> notes;  // comparators that failed on this map, and why
  // Kept for the SVG overlay (cell units).
  std::vector<LineSegment> rmline_segments;
  // The layers of the default .lmap 2.0 file: its walls cut into their
  // segments, the room border chains, the furniture outlines.
  struct LmapGeometry {
    std::vector<LineSegment> segments;
    std::vector<std::vector<CellIndex>> room_chains;
    std::vector<std::vector<CellIndex>> blob_outlines;
  };
  std::optional<LmapGeometry> lmap_geometry;

  std::optional<double> Get(const std::string& figure) const;
  // figure / png9_bytes, when both are there.
  std::optional<double> RatioToPng9(const std::string& figure) const;
};

// A column of a per-map table: a figure with its header and decimals, or a
// ratio of a size to PNG-9 when `ratio` is set.
struct Column {
  std::string figure;
  std::string header;
  int decimals = 0;
  bool ratio = false;
};

std::optional<double> ColumnValue(const MapResult& result, const Column& column);

// The median of a column over the maps that have it; nullopt when none has.
std::optional<double> ColumnMedian(const std::vector<MapResult>& results, const Column& column);

}  // namespace linemap::bench

#endif  // LINEMAP_TOOLS_BENCH_RESULTS_H_
