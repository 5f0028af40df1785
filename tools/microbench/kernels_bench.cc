// Google Benchmark micro-benchmarks of linemap's hot kernels: the edge-map
// flood fill (RM-Line section 2.1), connected-component labelling (Kosteley
// et al. 3.2 B/C), RM-Line's ray scoring (2.3), chain rasterisation (polygon
// fill of a room chain) and, once the codec is in the tree, the .lmap decode
// (the decoder's rasterisation end to end). Inputs are generated office maps
// (tools/bench/synthetic.h), so every run measures the same cells.
//
//   build/linemap_microbench [--benchmark_filter=REGEX]
#include <benchmark/benchmark.h>

#if __has_include("linemap/codec.h")
#include "linemap/codec.h"
#define LINEMAP_MICROBENCH_HAVE_CODEC 1
#endif

#include "codec/lines/rmline.h"
#include "linemap/labeling.h"
#include "linemap/lines.h"
#include "linemap/segmentation.h"
#include "tools/bench/png_codec.h"
#include "tools/bench/synthetic.h"

namespace linemap::bench {
namespace {

void SetCellsProcessed(benchmark::State& state, std::size_t cells) {
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) *
                          static_cast<std::int64_t>(cells));
}

void BM_EdgeMapFloodFill(benchmark::State& state) {
  const Grid grid = GenerateOfficeMap(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(ComputeEdgeMap(grid));
  SetCellsProcessed(state, grid.size());
}
BENCHMARK(BM_EdgeMapFloodFill)->Arg(512)->Arg(2048)->Unit(benchmark::kMillisecond);

BinaryMask FreeMask(const Grid& grid) {
  BinaryMask mask(grid.width(), grid.height());
  for (std::size_t i = 0; i < grid.size(); ++i) {
    mask.bits[i] = grid.cells()[i] == Cell::kFree ? 1 : 0;
  }
  return mask;
}

void BM_LabelComponents(benchmark::State& state) {
  const Grid grid = GenerateOfficeMap(static_cast<int>(state.range(0)));
  const BinaryMask mask = FreeMask(grid);
  const Connectivity connectivity =
      state.range(1) == 4 ? Connectivity::kFour : Connectivity::kEight;
  for (auto _ : state) benchmark::DoNotOptimize(LabelComponents(mask, connectivity));
  SetCellsProcessed(state, grid.size());
}
BENCHMARK(BM_LabelComponents)
    ->Args({512, 4})
    ->Args({512, 8})
    ->Args({2048, 4})
    ->Args({2048, 8})
    ->Unit(benchmark::kMillisecond);

void BM_RmLineRayScoring(benchmark::State& state) {
  const Grid grid = GenerateOfficeMap(512);
  const EdgeMap edges = ComputeEdgeMap(grid);
  std::vector<std::pair<int, int>> starts;
  for (int row = 0; row < edges.height && starts.size() < 256; row += 3) {
    for (int col = 0; col < edges.width && starts.size() < 256; col += 7) {
      if (edges.is_edge[static_cast<std::size_t>(row) * edges.width + col]) {
        starts.emplace_back(col, row);
      }
    }
  }
  const double dtheta = static_cast<double>(state.range(0));
  std::size_t i = 0;
  for (auto _ : state) {
    const auto [col, row] = starts[i++ % starts.size()];
    benchmark::DoNotOptimize(lines_internal::CastBestRayPair(edges, col, row, dtheta, 0.5));
  }
  state.SetLabel("one active point, dtheta " + std::to_string(state.range(0)) + " deg");
}
BENCHMARK(BM_RmLineRayScoring)->Arg(1)->Arg(5);

// range(1): 0 = RM-Line, 1 = linemap's extractor (LineMethod order).
void BM_ExtractLinesWholeMap(benchmark::State& state) {
  const Grid grid = GenerateOfficeMap(static_cast<int>(state.range(0)));
  LineExtractionOptions options;
  options.method = static_cast<LineMethod>(state.range(1));
  for (auto _ : state) benchmark::DoNotOptimize(ExtractLines(grid, options));
  SetCellsProcessed(state, grid.size());
}
BENCHMARK(BM_ExtractLinesWholeMap)
    ->Args({512, static_cast<int>(LineMethod::kRmLine)})
    ->Args({1024, static_cast<int>(LineMethod::kRmLine)})
    ->Args({512, static_cast<int>(LineMethod::kLinemap)})
    ->Args({1024, static_cast<int>(LineMethod::kLinemap)})
    ->Unit(benchmark::kMillisecond);

// A closed 8-connected chain around a diamond-ish octagon of radius r.
std::vector<CellIndex> OctagonChain(int r) {
  std::vector<CellIndex> chain;
  const int c = r + 2;
  auto walk = [&](int col, int row, int dcol, int drow, int steps) {
    for (int i = 0; i < steps; ++i) chain.push_back({col + i * dcol, row + i * drow});
  };
  const int s = r / 2;
  walk(c - s, c - r, 1, 0, 2 * s);    // bottom edge, east
  walk(c + s, c - r, 1, 1, r - s);    // south-east diagonal
  walk(c + r, c - s, 0, 1, 2 * s);    // east edge, north
  walk(c + r, c + s, -1, 1, r - s);   // north-east diagonal
  walk(c + s, c + r, -1, 0, 2 * s);   // top edge, west
  walk(c - s, c + r, -1, -1, r - s);  // north-west diagonal
  walk(c - r, c + s, 0, -1, 2 * s);   // west edge, south
  walk(c - r, c - s, 1, -1, r - s);   // south-west diagonal
  return chain;
}

void BM_FillChainPolygon(benchmark::State& state) {
  const int r = static_cast<int>(state.range(0));
  const std::vector<CellIndex> chain = OctagonChain(r);
  const int size = 2 * r + 5;
  for (auto _ : state) benchmark::DoNotOptimize(FillChainPolygon(chain, size, size));
  SetCellsProcessed(state, static_cast<std::size_t>(size) * size);
}
BENCHMARK(BM_FillChainPolygon)->Arg(100)->Arg(1000)->Unit(benchmark::kMicrosecond);

void BM_PngEncodeLevel9(benchmark::State& state) {
  const Grid grid = GenerateOfficeMap(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    benchmark::DoNotOptimize(EncodeTrinaryPng(grid, PngLayout::kGrey8, 9));
  }
  SetCellsProcessed(state, grid.size());
}
BENCHMARK(BM_PngEncodeLevel9)->Arg(1024)->Unit(benchmark::kMillisecond);

#ifdef LINEMAP_MICROBENCH_HAVE_CODEC
void BM_LmapDecode(benchmark::State& state) {
  const Grid grid = GenerateOfficeMap(static_cast<int>(state.range(0)));
  StatusOr<std::vector<std::uint8_t>> bytes = EncodeLmap(grid);
  if (!bytes.ok()) {
    state.SkipWithError(bytes.status().message().c_str());
    return;
  }
  for (auto _ : state) benchmark::DoNotOptimize(DecodeLmap(*bytes));
  SetCellsProcessed(state, grid.size());
}
BENCHMARK(BM_LmapDecode)->Arg(1024)->Unit(benchmark::kMillisecond);
#endif

}  // namespace
}  // namespace linemap::bench

BENCHMARK_MAIN();
