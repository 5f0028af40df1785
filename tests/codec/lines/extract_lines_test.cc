// ExtractLineSegments (codec/lines/extract_lines.h) against ExtractLines():
// the same segments and the same errors, for both methods.
#include "codec/lines/extract_lines.h"

#include <gtest/gtest.h>

#include <cstddef>
#include <string>
#include <vector>

#include "linemap/lines.h"
#include "linemap/map_io.h"
#include "tests/testing/test_support.h"

namespace linemap {
namespace {

void ExpectSameSegments(const std::vector<LineSegment>& a, const std::vector<LineSegment>& b,
                        const std::string& what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (std::size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(a[k].x1, b[k].x1) << what << " segment " << k;
    EXPECT_EQ(a[k].y1, b[k].y1) << what << " segment " << k;
    EXPECT_EQ(a[k].x2, b[k].x2) << what << " segment " << k;
    EXPECT_EQ(a[k].y2, b[k].y2) << what << " segment " << k;
  }
}

TEST(ExtractLineSegmentsTest, SegmentsOfExtractLinesOnBundledMaps) {
  for (const char* name : {"/nav2/depot.yaml", "/navtut/lse_arena.yaml", "/strands/kth/map.yaml"}) {
    StatusOr<Grid> grid = LoadRosMap(testing::BundledMapsDir() + name);
    ASSERT_TRUE(grid.ok()) << name;
    for (const LineMethod method : {LineMethod::kLinemap, LineMethod::kRmLine}) {
      for (const bool straight : {false, true}) {
        LineExtractionOptions options = straight ? StraightWalls({}) : LineExtractionOptions{};
        options.method = method;
        StatusOr<LineExtraction> all = ExtractLines(*grid, options);
        StatusOr<std::vector<LineSegment>> segments = ExtractLineSegments(*grid, options);
        ASSERT_TRUE(all.ok()) << name;
        ASSERT_TRUE(segments.ok()) << name;
        ExpectSameSegments(*segments, all->segments, name);
      }
    }
  }
}

TEST(ExtractLineSegmentsTest, RefusesWhatExtractLinesRefuses) {
  Grid grid(8, 8, Cell::kOccupied);
  LineExtractionOptions options;
  options.robot = CellPoint{3, 3};  // not on a free cell
  StatusOr<std::vector<LineSegment>> segments = ExtractLineSegments(grid, options);
  ASSERT_FALSE(segments.ok());
  EXPECT_EQ(segments.status().message(), ExtractLines(grid, options).status().message());
  options.robot.reset();
  options.epsilon_cells = 0;
  segments = ExtractLineSegments(grid, options);
  ASSERT_FALSE(segments.ok());
  EXPECT_EQ(segments.status().message(), ExtractLines(grid, options).status().message());
}

}  // namespace
}  // namespace linemap
