// MeasureLineFidelity (RM-Line Eq. 5) against a brute-force computation
// written here independently of the library's segment index.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>

#include "linemap/lines.h"
#include "linemap/map_io.h"
#include "tests/testing/reference_geometry.h"
#include "tests/testing/test_support.h"

namespace linemap {
namespace {

LineFidelity BruteFidelity(const EdgeMap& edges, const std::vector<LineSegment>& segments) {
  LineFidelity f;
  double sum = 0;
  std::size_t within = 0;
  for (int row = 0; row < edges.height; ++row) {
    for (int col = 0; col < edges.width; ++col) {
      if (!edges.is_edge[row * edges.width + col]) continue;
      double best = std::numeric_limits<double>::infinity();
      for (const LineSegment& s : segments)
        best = std::min(best, testing::ReferencePointSegmentDistance(col, row, s));
      ++f.edge_cells;
      sum += best;
      f.displ_max_cells = std::max(f.displ_max_cells, best);
      if (best <= 1.0) ++within;
    }
  }
  f.displ_ave_cells = sum / f.edge_cells;
  f.share_within_1 = static_cast<double>(within) / f.edge_cells;
  return f;
}

void ExpectSameFidelity(const LineFidelity& got, const LineFidelity& want) {
  EXPECT_EQ(got.edge_cells, want.edge_cells);
  EXPECT_NEAR(got.displ_ave_cells, want.displ_ave_cells, 1e-9);
  EXPECT_NEAR(got.displ_max_cells, want.displ_max_cells, 1e-9);
  EXPECT_NEAR(got.share_within_1, want.share_within_1, 1e-12);
}

TEST(LineFidelityTest, HandWorkedExample) {
  // Edge cells (0,0), (4,0), (2,3) and one segment from (0,0) to (4,0):
  // distances 0, 0, 3 -> mean 1, max 3, two of three within 1.
  EdgeMap edges;
  edges.width = 5;
  edges.height = 4;
  edges.is_edge.assign(20, 0);
  edges.is_edge[0] = edges.is_edge[4] = edges.is_edge[3 * 5 + 2] = 1;
  edges.edge_count = 3;
  const LineFidelity f = MeasureLineFidelity(edges, {{0, 0, 4, 0}});
  EXPECT_EQ(f.edge_cells, 3u);
  EXPECT_DOUBLE_EQ(f.displ_ave_cells, 1.0);
  EXPECT_DOUBLE_EQ(f.displ_max_cells, 3.0);
  EXPECT_NEAR(f.share_within_1, 2.0 / 3.0, 1e-15);
}

TEST(LineFidelityTest, MatchesBruteForceOnRandomSegments) {
  // Random edge cells and random segments, some far off the map and some
  // degenerate, so that the index's tiles, rings and clamping are all used.
  std::mt19937 rng(12345);
  for (int trial = 0; trial < 20; ++trial) {
    EdgeMap edges;
    edges.width = 37 + trial * 11;
    edges.height = 23 + trial * 7;
    edges.is_edge.assign(static_cast<std::size_t>(edges.width) * edges.height, 0);
    std::bernoulli_distribution edge(0.05);
    for (auto& e : edges.is_edge) e = edge(rng) ? 1 : 0;
    edges.edge_count = std::count(edges.is_edge.begin(), edges.is_edge.end(), 1);
    std::uniform_real_distribution<double> x(-40, edges.width + 40), y(-40, edges.height + 40);
    std::vector<LineSegment> segments;
    const int count = 1 + trial % 7;
    for (int i = 0; i < count; ++i) segments.push_back({x(rng), y(rng), x(rng), y(rng)});
    if (trial % 3 == 0) segments.push_back({x(rng), y(rng), 0, 0});
    ExpectSameFidelity(MeasureLineFidelity(edges, segments), BruteFidelity(edges, segments));
  }
}

TEST(LineFidelityTest, MatchesBruteForceOnRmLineOfABundledMap) {
  StatusOr<Grid> grid = LoadRosMap(testing::BundledMapsDir() + "/nav2/depot.yaml");
  ASSERT_TRUE(grid.ok()) << grid.status().message();
  LineExtractionOptions options;
  options.method = LineMethod::kRmLine;
  StatusOr<LineExtraction> lines = ExtractLines(*grid, options);
  ASSERT_TRUE(lines.ok());
  ASSERT_GT(lines->segments.size(), 10u);
  ExpectSameFidelity(MeasureLineFidelity(lines->edges, lines->segments),
                     BruteFidelity(lines->edges, lines->segments));
}

TEST(LineFidelityTest, NoEdgeCellsGivesZeros) {
  EdgeMap edges;
  edges.width = 3;
  edges.height = 3;
  edges.is_edge.assign(9, 0);
  const LineFidelity f = MeasureLineFidelity(edges, {});
  EXPECT_EQ(f.edge_cells, 0u);
  EXPECT_EQ(f.displ_ave_cells, 0.0);
}

}  // namespace
}  // namespace linemap
