// The wall layer against the RM-Line paper's measure: DisPL_ave, the mean
// distance from the map's edge cells (occupied, with a free 4-neighbour) to
// the nearest segment, computed here by brute force over every segment, for
// the walls a default file stores and for RM-Line's own lines.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>
#include <vector>

#include "linemap/codec.h"
#include "linemap/lines.h"
#include "linemap/lmap_vectors.h"
#include "linemap/map_io.h"
#include "tests/testing/test_support.h"

namespace linemap {
namespace {

struct Segment {
  double x1, y1, x2, y2;  // cells; cell (c, r) has its centre at (c, r)
};

double Distance(double px, double py, const Segment& s) {
  const double dx = s.x2 - s.x1, dy = s.y2 - s.y1;
  const double len2 = dx * dx + dy * dy;
  double t = len2 > 0 ? ((px - s.x1) * dx + (py - s.y1) * dy) / len2 : 0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(px - s.x1 - t * dx, py - s.y1 - t * dy);
}

bool IsEdge(const Grid& grid, int c, int r) {
  if (grid.at(c, r) != Cell::kOccupied) return false;
  const int dc[] = {1, -1, 0, 0}, dr[] = {0, 0, 1, -1};
  for (int k = 0; k < 4; ++k) {
    const int x = c + dc[k], y = r + dr[k];
    if (grid.Contains(x, y) && grid.at(x, y) == Cell::kFree) return true;
  }
  return false;
}

double MeanEdgeDistance(const Grid& grid, const std::vector<Segment>& segments) {
  double sum = 0;
  std::size_t n = 0;
  for (int r = 0; r < grid.height(); ++r) {
    for (int c = 0; c < grid.width(); ++c) {
      if (!IsEdge(grid, c, r)) continue;
      double best = std::numeric_limits<double>::infinity();
      for (const Segment& s : segments) best = std::min(best, Distance(c, r, s));
      sum += best;
      ++n;
    }
  }
  return n == 0 ? 0 : sum / static_cast<double>(n);
}

std::vector<Segment> FileWalls(const LmapVectors& vectors) {
  std::vector<Segment> out;
  for (const WallPolyline& wall : vectors.walls) {
    for (std::size_t i = 0; i + 1 < wall.points.size(); ++i) {
      const CellIndex a = wall.points[i], b = wall.points[i + 1];
      out.push_back({double(a.col), double(a.row), double(b.col), double(b.row)});
    }
    if (wall.points.size() == 1) {
      const CellIndex a = wall.points[0];
      out.push_back({double(a.col), double(a.row), double(a.col), double(a.row)});
    }
  }
  return out;
}

std::vector<Segment> RmLineLines(const Grid& grid) {
  LineExtractionOptions options;
  options.method = LineMethod::kRmLine;
  StatusOr<LineExtraction> lines = ExtractLines(grid, options);
  EXPECT_TRUE(lines.ok()) << lines.status().message();
  std::vector<Segment> out;
  if (!lines.ok()) return out;
  for (const LineSegment& s : lines->segments) out.push_back({s.x1, s.y1, s.x2, s.y2});
  return out;
}

// The bundled maps and those of ../shared/maps up to 600,000 cells: the
// brute force costs edge cells x segments, and the maps whose walls were
// farther than RM-Line's lines before the walls followed the pixel steps
// (f1tenth columbia, levinelobby and mtl, nav2/map and tb3_sandbox) are all
// that small.
std::vector<std::string> MapsToMeasure() {
  std::vector<std::string> maps = testing::FindYamlFiles(testing::BundledMapsDir());
  const std::string shared = testing::SharedMapsDir();
  if (!shared.empty()) {
    for (const std::string& path : testing::FindYamlFiles(shared)) maps.push_back(path);
    for (const std::string& path : testing::FindBareImages(shared)) maps.push_back(path);
  }
  return maps;
}

TEST(LayerExtractionTest, WallsAreNoFartherFromTheEdgeCellsThanRmLinesLines) {
  int measured = 0;
  for (const std::string& path : MapsToMeasure()) {
    StatusOr<Grid> grid = LoadRosMap(path);
    if (!grid.ok() || grid->size() > 600000) continue;
    StatusOr<std::vector<std::uint8_t>> bytes = EncodeLmap(*grid);
    ASSERT_TRUE(bytes.ok()) << path << ": " << bytes.status().message();
    StatusOr<LmapVectors> vectors = DecodeLmapVectors(*bytes);
    ASSERT_TRUE(vectors.ok()) << path;
    const std::vector<Segment> walls = FileWalls(*vectors);
    const std::vector<Segment> rmline = RmLineLines(*grid);
    if (walls.empty() || rmline.empty()) continue;  // a map with no walls
    const double file = MeanEdgeDistance(*grid, walls);
    const double reference = MeanEdgeDistance(*grid, rmline);
    EXPECT_LE(file, reference) << path << ": the file's walls " << file
                               << " cells from the edge cells on average, RM-Line's lines "
                               << reference;
    ++measured;
  }
  EXPECT_GE(measured, 3);
}

TEST(LayerExtractionTest, StraightWallsDrawFewerSegmentsFartherFromTheWalls) {
  // nav2/depot: slanted and two-cell walls, where the default walls follow
  // the steps and faces and StraightWalls() draws one segment each.
  StatusOr<Grid> grid = LoadRosMap(testing::BundledMapsDir() + "/nav2/depot.yaml");
  ASSERT_TRUE(grid.ok()) << grid.status().message();
  EncodeOptions straight;
  straight.straight_walls = true;
  StatusOr<std::vector<std::uint8_t>> a = EncodeLmap(*grid);
  StatusOr<std::vector<std::uint8_t>> b = EncodeLmap(*grid, straight);
  ASSERT_TRUE(a.ok() && b.ok());
  const std::vector<Segment> steps = FileWalls(*DecodeLmapVectors(*a));
  const std::vector<Segment> lines = FileWalls(*DecodeLmapVectors(*b));
  EXPECT_LT(lines.size(), steps.size());
  EXPECT_LT(MeanEdgeDistance(*grid, steps), MeanEdgeDistance(*grid, lines));
  EXPECT_TRUE(*DecodeLmap(*a) == *DecodeLmap(*b));  // both exact
}

// Single-segment polylines shorter than `min_cells` (Chebyshev) with no end
// on the map's border: segments that share no end with another (a piece at
// the border may go on in the next block of a large map, and stays).
int ShortLoneWalls(const LmapVectors& vectors, int min_cells) {
  const auto on_border = [&](CellIndex p) {
    return p.col == 0 || p.row == 0 || p.col == vectors.width - 1 || p.row == vectors.height - 1;
  };
  int n = 0;
  for (const WallPolyline& wall : vectors.walls) {
    if (wall.points.size() > 2) continue;
    const CellIndex a = wall.points.front(), b = wall.points.back();
    if (on_border(a) || on_border(b)) continue;
    n += std::max(std::abs(a.col - b.col), std::abs(a.row - b.row)) < min_cells;
  }
  return n;
}

TEST(LayerExtractionTest, WithinAToleranceLonePiecesShorterThanTwoTPlusOneAreLeftToTheCells) {
  StatusOr<Grid> grid = LoadRosMap(testing::BundledMapsDir() + "/nav2/depot.yaml");
  ASSERT_TRUE(grid.ok()) << grid.status().message();
  StatusOr<std::vector<std::uint8_t>> exact = EncodeLmap(*grid);
  ASSERT_TRUE(exact.ok());
  // The exact file keeps them (so the check below is not vacuous).
  EXPECT_GT(ShortLoneWalls(*DecodeLmapVectors(*exact), 7), 0);
  for (int t = 1; t <= 3; ++t) {
    EncodeOptions options;
    options.tolerance_cells = t;
    StatusOr<std::vector<std::uint8_t>> bytes = EncodeLmap(*grid, options);
    ASSERT_TRUE(bytes.ok());
    StatusOr<LmapVectors> vectors = DecodeLmapVectors(*bytes);
    ASSERT_TRUE(vectors.ok());
    EXPECT_FALSE(vectors->walls.empty()) << "T = " << t;
    EXPECT_EQ(ShortLoneWalls(*vectors, 2 * t + 1), 0) << "T = " << t;
  }
}

TEST(LayerExtractionTest, WithinAToleranceAWallAcrossALayerBlockBorderKeepsItsPieces) {
  // The layers of maps over 2048 cells a side are extracted in blocks of
  // 2048: a two-cell wall from column 2043 to 3000 has a 5-cell piece in the
  // first block, which is no lone piece (it goes on in the next block).
  Grid grid(4200, 60, Cell::kFree);
  for (int c = 2043; c <= 3000; ++c) {
    grid.set(c, 30, Cell::kOccupied);
    grid.set(c, 31, Cell::kOccupied);
  }
  EncodeOptions options;
  options.tolerance_cells = 3;
  StatusOr<std::vector<std::uint8_t>> bytes = EncodeLmap(grid, options);
  ASSERT_TRUE(bytes.ok()) << bytes.status().message();
  StatusOr<LmapVectors> vectors = DecodeLmapVectors(*bytes);
  ASSERT_TRUE(vectors.ok());
  const std::vector<Segment> walls = FileWalls(*vectors);
  for (int c = 2043; c <= 2047; ++c) {
    double nearest = std::numeric_limits<double>::infinity();
    for (const Segment& s : walls) nearest = std::min(nearest, Distance(c, 30, s));
    EXPECT_LE(nearest, 1.0) << "column " << c;
  }
}

}  // namespace
}  // namespace linemap
