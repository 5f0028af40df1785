// EncodeLmap's progress reports within a tolerance, where the rounds of
// checks make a save of a few Mcells take seconds.
#include <gtest/gtest.h>

#include <utility>
#include <vector>

#include "linemap/codec.h"
#include "linemap/map_io.h"
#include "tests/testing/test_support.h"

namespace linemap::testing {
namespace {

Grid Depot() {
  StatusOr<Grid> depot = LoadRosMap(BundledMapsDir() + "/nav2/depot.yaml");
  EXPECT_TRUE(depot.ok());
  return depot.ok() ? *std::move(depot) : Grid();
}

TEST(EncoderProgressTest, ASaveWithinAToleranceReportsEveryRound) {
  const Grid grid = Depot();
  for (const int t : {1, 3}) {
    SCOPED_TRACE(t);
    std::vector<double> reports;
    EncodeOptions options;
    options.tolerance_cells = t;
    options.progress = [&reports](double done) { reports.push_back(done); };
    ASSERT_TRUE(EncodeLmap(grid, options).ok());
    // Before the rounds, a few rounds, the file within the tolerance, then
    // the exact file it is compared with.
    ASSERT_GE(reports.size(), 5u);
    EXPECT_GT(reports.front(), 0.0);
    for (std::size_t i = 1; i < reports.size(); ++i) EXPECT_GT(reports[i], reports[i - 1]);
    EXPECT_EQ(reports.back(), 1.0);
    EXPECT_LT(reports[reports.size() - 2], 1.0);
  }
}

TEST(EncoderProgressTest, AnExactSaveOfOneSectionReportsOnceWhenComplete) {
  std::vector<double> reports;
  EncodeOptions options;
  options.progress = [&reports](double done) { reports.push_back(done); };
  ASSERT_TRUE(EncodeLmap(Depot(), options).ok());
  EXPECT_EQ(reports, std::vector<double>{1.0});
}

}  // namespace
}  // namespace linemap::testing
