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
  // The default limits, written out: 2^24 wall segments (and walls), 2^20
  // rooms and 2^20 furniture objects, 2^26 vertices and chain cells of the
  // rooms and of the objects.
  LayerCounts at;
  at.walls = std::uint64_t{1} << 20;
  at.segments = std::uint64_t{1} << 24;
  at.rooms = std::uint64_t{1} << 20;
  at.objects = std::uint64_t{1} << 20;
  EXPECT_TRUE(CheckLayerCountsWithinDefaultLimits(at).ok());
  at.room_vertices = at.room_chain_cells = std::uint64_t{1} << 26;
  at.object_vertices = at.object_chain_cells = std::uint64_t{1} << 26;
  EXPECT_TRUE(CheckLayerCountsWithinDefaultLimits(at).ok());
  for (int field = 0; field < 8; ++field) {
    LayerCounts over = at;
    std::uint64_t* const fields[] = {&over.walls,           &over.segments,
                                     &over.rooms,           &over.objects,
                                     &over.room_vertices,   &over.room_chain_cells,
                                     &over.object_vertices, &over.object_chain_cells};
    *fields[field] = field == 0 ? (std::uint64_t{1} << 24) + 1 : *fields[field] + 1;
    const Status s = CheckLayerCountsWithinDefaultLimits(over);
    ASSERT_FALSE(s.ok()) << field;
    EXPECT_EQ(s.code(), StatusCode::kResourceExhausted) << field;
    // No limit the caller set: only a save without the layers lifts it.
    EXPECT_EQ(s.limit(), Limit::kNone) << field;
    EXPECT_NE(s.message().find("--raster-only"), std::string::npos) << s.ToString();
  }
}

}  // namespace
}  // namespace linemap
