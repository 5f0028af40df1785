// The encoder writes no file that a decoder with the default limits
// refuses (codec/lmap/v2_file.h): the counts at the limits pass, one more
// of any of them is refused, naming the way out.
#include "codec/lmap/v2_file.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>

namespace linemap {
namespace {

TEST(V2FileTest, LayerCountsAboveTheDefaultLimitsAreRefused) {
  // The default limits, written out: 2^24 wall segments, 2^20 rooms and
  // 2^20 furniture objects.
  LayerCounts at;
  at.walls = std::uint64_t{1} << 20;
  at.segments = std::uint64_t{1} << 24;
  at.rooms = std::uint64_t{1} << 20;
  at.objects = std::uint64_t{1} << 20;
  EXPECT_TRUE(CheckLayerCountsWithinDefaultLimits(at).ok());
  for (int field = 0; field < 3; ++field) {
    LayerCounts over = at;
    (field == 0 ? over.segments : field == 1 ? over.rooms : over.objects) += 1;
    const Status s = CheckLayerCountsWithinDefaultLimits(over);
    ASSERT_FALSE(s.ok()) << field;
    EXPECT_EQ(s.code(), StatusCode::kResourceExhausted) << field;
    EXPECT_NE(s.message().find("--raster-only"), std::string::npos) << s.ToString();
  }
}

}  // namespace
}  // namespace linemap
