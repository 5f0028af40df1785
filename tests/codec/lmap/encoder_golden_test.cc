// The encoder writes the committed 2.x fixtures byte for byte
// (tests/data/make_v2_test_files.sh made them): work on the encoder's speed
// must not move a byte, and a change that does shows here first (then the
// script makes the fixtures again, and the version log says why).
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "format/file_io.h"
#include "linemap/codec.h"
#include "linemap/map_io.h"
#include "tests/testing/test_support.h"

namespace linemap::testing {
namespace {

struct Golden {
  const char* fixture;
  const char* map;
  EncodeOptions options;
};

EncodeOptions With(void (*set)(EncodeOptions*)) {
  EncodeOptions options;
  set(&options);
  return options;
}

TEST(EncoderGoldenTest, WritesTheFixturesByteForByte) {
  const std::vector<Golden> goldens = {
      {"depot_v2.lmap", "nav2/depot.yaml", EncodeOptions{}},
      {"lse_arena_v2.lmap", "navtut/lse_arena.yaml", EncodeOptions{}},
      {"depot_v2_raster_only.lmap", "nav2/depot.yaml",
       With([](EncodeOptions* o) { o->vector_layers = false; })},
      {"depot_v2_tiles_64.lmap", "nav2/depot.yaml",
       With([](EncodeOptions* o) { o->tile_size_cells = 64; })},
      {"depot_v2_3_compact_tiles_64.lmap", "nav2/depot.yaml", With([](EncodeOptions* o) {
         o->compact = true;
         o->tile_size_cells = 64;
       })},
      {"depot_v2_2_sections_64.lmap", "nav2/depot.yaml", With([](EncodeOptions* o) {
         o->layer_section_cells = 64;
         o->tile_size_cells = 64;
       })},
      {"willow_v2_3_tolerance_1.lmap", "turtlebot_apps/willow-2010-02-18-0.10.yaml",
       With([](EncodeOptions* o) { o->tolerance_cells = 1; })},
  };
  for (const Golden& golden : goldens) {
    SCOPED_TRACE(golden.fixture);
    StatusOr<Grid> map = LoadRosMap(BundledMapsDir() + "/" + golden.map);
    ASSERT_TRUE(map.ok()) << map.status().message();
    StatusOr<std::vector<std::uint8_t>> encoded = EncodeLmap(*map, golden.options);
    ASSERT_TRUE(encoded.ok()) << encoded.status().message();
    StatusOr<std::vector<std::uint8_t>> fixture =
        ReadFileBytes(SourceDir() + "/tests/data/lmap/" + golden.fixture, 1 << 24);
    ASSERT_TRUE(fixture.ok()) << fixture.status().message();
    EXPECT_EQ(*encoded, *fixture);
  }
}

}  // namespace
}  // namespace linemap::testing
