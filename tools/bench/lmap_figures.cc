#include "tools/bench/lmap_figures.h"

// The codec (issue 6) lands on its own branch; these columns switch on by
// themselves once its public header is in the tree.
#if __has_include("linemap/codec.h")
#include "linemap/codec.h"
#define LINEMAP_BENCH_HAVE_CODEC 1
#endif

#include "tools/bench/measure.h"

namespace linemap::bench {

#ifdef LINEMAP_BENCH_HAVE_CODEC
namespace {

constexpr double kMb = 1024.0 * 1024.0;

std::vector<LineSegment> ToLineSegments(const std::vector<LatticeSegment>& stored) {
  std::vector<LineSegment> segments;
  segments.reserve(stored.size());
  for (const LatticeSegment& s : stored) {
    segments.push_back({static_cast<double>(s.a.col), static_cast<double>(s.a.row),
                        static_cast<double>(s.b.col), static_cast<double>(s.b.row)});
  }
  return segments;
}

// Eval figures of the lossy decode, and the geometry for the SVG overlay.
Status AddLossyEval(const Grid& grid, const std::vector<std::uint8_t>& lossy, MapResult* result) {
  LINEMAP_ASSIGN_OR_RETURN(LmapContents contents, DecodeLmapContents(lossy));
  const GridComparison eval = CompareGrids(grid, contents.grid);
  result->figures[key::kEvalRecall] = eval.obstacle_recall_1;
  result->figures[key::kEvalPrecision] = eval.obstacle_precision_1;
  result->figures[key::kEvalFreeIou] = eval.free_iou;
  result->figures[key::kEvalLeaks] = static_cast<double>(eval.leaks);
  result->figures[key::kEvalUnknownFreed] = eval.unknown_turned_free_share;
  MapResult::LmapGeometry geometry;
  geometry.segments = ToLineSegments(contents.segments);
  geometry.room_chains = contents.room_chains;
  geometry.blob_outlines = contents.blob_outlines;
  result->figures[key::kEvalLines] = static_cast<double>(geometry.segments.size());
  if (!geometry.segments.empty()) {
    const LineFidelity fidelity = MeasureLineFidelity(ComputeEdgeMap(grid), geometry.segments);
    result->figures[key::kEvalDisplCm] = fidelity.displ_ave_cells * grid.meta.resolution * 100.0;
  }
  result->lmap_geometry = std::move(geometry);
  return Status::Ok();
}

}  // namespace

Status AddLmapFigures(const Grid& grid, const LmapMeasure& what, MapResult* result) {
  const EncodeOptions lossy_options;  // the codec's defaults: what `linemap encode` does
  LINEMAP_ASSIGN_OR_RETURN(std::vector<std::uint8_t> lossy, EncodeLmap(grid, lossy_options));
  result->figures[key::kLmapLossyBytes] = static_cast<double>(lossy.size());
  auto encode = [&] { (void)EncodeLmap(grid, lossy_options); };
  auto decode = [&] { (void)DecodeLmap(lossy); };
  result->figures[key::kLmapEncodeMs] = Median(TimeRuns(encode, what.repeats));
  result->figures[key::kLmapDecodeMs] = Median(TimeRuns(decode, what.repeats));
  if (what.memory) {
    if (auto peak = PeakExtraMemoryBytes(encode)) {
      result->figures[key::kLmapEncodePeakMb] = *peak / kMb;
    }
    if (auto peak = PeakExtraMemoryBytes(decode)) {
      result->figures[key::kLmapDecodePeakMb] = *peak / kMb;
    }
  }
  if (!what.everything) return Status::Ok();
  EncodeOptions lossless_options;
  lossless_options.lossless = true;
  StatusOr<std::vector<std::uint8_t>> lossless = EncodeLmap(grid, lossless_options);
  if (lossless.ok()) {
    result->figures[key::kLmapLosslessBytes] = static_cast<double>(lossless->size());
  } else {
    result->notes.push_back(".lmap lossless: " + lossless.status().message());
  }
  return AddLossyEval(grid, lossy, result);
}

#else

Status AddLmapFigures(const Grid& /*grid*/, const LmapMeasure& /*what*/, MapResult* /*result*/) {
  return UnsupportedError(
      "the .lmap codec (issue 6) is not merged into this tree yet: no .lmap columns");
}

#endif

}  // namespace linemap::bench
