// The huge-map goals table from hand-made scaling rows: spreads and window
// speed-ups worked out here.
#include "tools/bench/report.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "tools/bench/runner.h"

namespace linemap::bench {
namespace {

ScalingRow Row(double mcells, double encode, double decode, std::optional<double> window) {
  ScalingRow row;
  row.mcells = mcells;
  row.lmap_encode_ms_per_mcell = row.lmap_encode_fastest_ms_per_mcell = encode;
  row.lmap_decode_ms_per_mcell = row.lmap_decode_fastest_ms_per_mcell = decode;
  row.lmap_window_speedup = window;
  return row;
}

TEST(ScalingGoalsTableTest, VerdictsFollowTheSpreadsAndEveryWindow) {
  // Encode 40 / 32 - 1 = 25 % (at the goal: PASS); decode 2.0 / 1.5 - 1 =
  // 33 % (FAIL); a window 1.8x at 1 Mcell fails the every-size goal.
  const NamedTable slow_window =
      ScalingGoalsTable({Row(1.0, 32, 1.5, 1.8), Row(16.8, 40, 2.0, 25.0)});
  const auto& rows = slow_window.table.rows();
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0][1], "25 % (of the fastest runs: 25 %)");
  EXPECT_EQ(rows[0][2], "PASS");
  EXPECT_EQ(rows[1][1], "33 % (of the fastest runs: 33 %)");
  EXPECT_EQ(rows[1][2], "FAIL");
  EXPECT_EQ(rows[2][1], "1.8x at 1.0, 25.0x at 16.8 Mcells");
  EXPECT_EQ(rows[2][2], "FAIL");
  // Every window fast: PASS; one failed (its cells not the crop): FAIL.
  EXPECT_EQ(ScalingGoalsTable({Row(67.1, 40, 2, 22.6), Row(282.7, 44, 2, 29.1)}).table.rows()[2][2],
            "PASS");
  const NamedTable failed =
      ScalingGoalsTable({Row(67.1, 40, 2, 22.6), Row(282.7, 44, 2, std::nullopt)});
  EXPECT_EQ(failed.table.rows()[2][1], "22.6x at 67.1, failed at 282.7 Mcells");
  EXPECT_EQ(failed.table.rows()[2][2], "FAIL");
}

}  // namespace
}  // namespace linemap::bench
