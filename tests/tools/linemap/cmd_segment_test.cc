// The `linemap segment` command, end to end through the built CLI.
#include <gtest/gtest.h>

#include "tests/testing/test_support.h"

namespace linemap {
namespace {

std::string Arena() { return testing::BundledMapsDir() + "/navtut/lse_arena.yaml"; }

// The arena: a small room (bottom left in the picture) opens onto the rest
// through a gap of about 1.2 m, a pocket behind a wall stub through one of
// 0.55 m, so the default method finds three rooms.
TEST(CmdSegmentTest, WritesRoomsJsonAndPrintsCounts) {
  const std::string out = testing::MakeTempDir("cmd_segment_rooms") + "/arena.json";
  const testing::CliResult result = testing::RunCli({"segment", Arena(), "-o", out});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.out.find("rooms: 3 (3 rooms, 0 corridors)  doors: 2  blobs: 0"),
            std::string::npos)
      << result.out;
  const std::string json = testing::ReadFile(out);
  EXPECT_EQ(json.rfind("{\"resolution\":0.05,\"method\":\"rooms\",\"timings_ms\":{", 0), 0u)
      << json.substr(0, 80);
  // 4455 = the map's free cells (`linemap info`) = 2874 + 783 + 798.
  EXPECT_NE(json.find("\"rooms\":[{\"id\":1,\"kind\":\"room\",\"area_m2\":7.18"), std::string::npos)
      << json.substr(0, 300);
  EXPECT_NE(json.find("\"cells\":2874,\"free_cells\":2874,"), std::string::npos);
  EXPECT_NE(json.find("{\"id\":2,\"kind\":\"room\",\"area_m2\":1.9575"), std::string::npos);
  EXPECT_NE(json.find("\"cells\":783,\"free_cells\":783,"), std::string::npos);
  EXPECT_NE(json.find("\"cells\":798,\"free_cells\":798,"), std::string::npos);
  EXPECT_NE(json.find("\"doors\":[{\"rooms\":[1,2],"), std::string::npos);
  EXPECT_NE(json.find("{\"rooms\":[1,3],\"width_m\":0.55"), std::string::npos);
}

// --doors from 0.7 m: the 0.55 m gap to the pocket is no doorway any more.
TEST(CmdSegmentTest, DoorRangeAndMaxRoomArea) {
  const std::string dir = testing::MakeTempDir("cmd_segment_doors");
  const testing::CliResult narrow =
      testing::RunCli({"segment", Arena(), "--doors", "0.7,1.2", "-o", dir + "/a.json"});
  ASSERT_EQ(narrow.exit_code, 0) << narrow.err;
  EXPECT_NE(narrow.out.find("rooms: 2 (2 rooms, 0 corridors)  doors: 1"), std::string::npos)
      << narrow.out;
  const testing::CliResult reversed =
      testing::RunCli({"segment", Arena(), "--doors", "1.2,0.7", "-o", dir + "/b.json"});
  EXPECT_EQ(reversed.exit_code, 2);
  EXPECT_NE(reversed.err.find("min_door_width_m <= max_door_width_m"), std::string::npos)
      << reversed.err;
  EXPECT_FALSE(testing::FileExists(dir + "/b.json"));
  EXPECT_EQ(testing::RunCli({"segment", Arena(), "--max-room-area", "-1", "-o", dir + "/c.json"})
                .exit_code,
            2);
  EXPECT_EQ(
      testing::RunCli({"segment", Arena(), "--doors", "0.7", "-o", dir + "/d.json"}).exit_code, 2);
}

TEST(CmdSegmentTest, WritesPaperJsonAndPrintsCounts) {
  const std::string out = testing::MakeTempDir("cmd_segment") + "/arena.json";
  const testing::CliResult result =
      testing::RunCli({"segment", Arena(), "--method", "paper", "-o", out});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.out.find("rooms: 1"), std::string::npos) << result.out;
  const std::string json = testing::ReadFile(out);
  EXPECT_EQ(json.rfind("{\"resolution\":0.05,\"method\":\"paper\",\"timings_ms\":{\"layout\":", 0),
            0u)
      << json.substr(0, 80);
  // 4455 = the map's free cells (`linemap info`), all in one component.
  EXPECT_NE(json.find("\"rooms\":[{\"free_cells\":4455,"), std::string::npos);
  EXPECT_NE(json.find("\"closed_by_lee\":true"), std::string::npos);
  EXPECT_NE(json.find("\"blobs\":["), std::string::npos);
}

TEST(CmdSegmentTest, WritesRoomsGeoJson) {
  const std::string out = testing::MakeTempDir("cmd_segment_rooms_geo") + "/arena.geojson";
  const testing::CliResult result = testing::RunCli({"segment", Arena(), "--geojson", "-o", out});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const std::string json = testing::ReadFile(out);
  EXPECT_EQ(json.rfind("{\"type\":\"FeatureCollection\",\"features\":[", 0), 0u);
  EXPECT_NE(json.find("\"properties\":{\"layer\":\"room\",\"id\":1,\"area_m2\":7.18"),
            std::string::npos)
      << json.substr(0, 200);
  EXPECT_NE(json.find("\"kind\":\"room\"}"), std::string::npos);
  EXPECT_NE(json.find("\"layer\":\"door\",\"rooms\":[1,2]"), std::string::npos);
  EXPECT_NE(json.find("\"type\":\"Point\""), std::string::npos);
  // The refusals below have an output name the command accepts, so that
  // they are refused for the option named, not for the name.
  const std::string json_out = out.substr(0, out.size() - 8) + ".json";
  const testing::CliResult voronoi =
      testing::RunCli({"segment", Arena(), "--method", "voronoi", "-o", json_out});
  EXPECT_EQ(voronoi.exit_code, 2);
  EXPECT_NE(voronoi.err.find("--method must be"), std::string::npos) << voronoi.err;
  const testing::CliResult pose =
      testing::RunCli({"segment", Arena(), "--method", "rooms", "--pose", "1,1", "-o", json_out});
  EXPECT_EQ(pose.exit_code, 2);
  EXPECT_NE(pose.err.find("need --method paper"), std::string::npos) << pose.err;
}

TEST(CmdSegmentTest, WritesGeoJson) {
  const std::string out = testing::MakeTempDir("cmd_segment_geo") + "/arena.geojson";
  const testing::CliResult result =
      testing::RunCli({"segment", Arena(), "--pose", "1.0,1.0", "--geojson", "-o", out});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const std::string json = testing::ReadFile(out);
  EXPECT_EQ(json.rfind("{\"type\":\"FeatureCollection\",\"features\":[", 0), 0u);
  EXPECT_NE(json.find("\"layer\":\"room_border\""), std::string::npos);
  EXPECT_NE(json.find("\"type\":\"Polygon\""), std::string::npos);
}

TEST(CmdSegmentTest, BadUsageAndBadPose) {
  const std::string dir = testing::MakeTempDir("cmd_segment_bad");
  EXPECT_EQ(testing::RunCli({"segment", Arena()}).exit_code, 2);  // no -o
  const testing::CliResult outside =
      testing::RunCli({"segment", Arena(), "--pose", "-50,-50", "-o", dir + "/x.json"});
  EXPECT_EQ(outside.exit_code, 2);
  EXPECT_NE(outside.err.find("outside the map"), std::string::npos) << outside.err;
  EXPECT_FALSE(testing::FileExists(dir + "/x.json"));
  EXPECT_EQ(testing::RunCli({"segment", dir + "/missing.yaml", "-o", dir + "/y.json"}).exit_code,
            2);
}

// --pose on the map's lower edge (0,0 with origin 0,0) is in cell 0, as for
// `lines`; off the map the error names the map and gives metres.
TEST(CmdSegmentTest, PoseOnTheLowerEdgeAndOffTheMap) {
  const std::string dir = testing::MakeTempDir("cmd_segment_edge");
  testing::WriteFile(dir + "/free.pgm", "P5\n40 20\n255\n" + std::string(40 * 20, '\xfe'));
  const std::string map = dir + "/free.pgm";
  const testing::CliResult corner =
      testing::RunCli({"segment", map, "--pose", "0,0", "-o", dir + "/a.json"});
  EXPECT_EQ(corner.exit_code, 0) << corner.err;
  EXPECT_EQ(testing::RunCli({"lines", map, "--pose", "0,0"}).exit_code, 0);
  const testing::CliResult off =
      testing::RunCli({"segment", map, "--pose", "-1,0.5", "-o", dir + "/b.json"});
  EXPECT_EQ(off.exit_code, 2);
  EXPECT_NE(off.err.find("free.pgm': robot position -1.000,0.500 m is outside the map"),
            std::string::npos)
      << off.err;
  EXPECT_FALSE(testing::FileExists(dir + "/b.json"));
}

// One corridor is "1 corridor", one room "1 room".
TEST(CmdSegmentTest, CountsAreSingularForOne) {
  const std::string dir = testing::MakeTempDir("cmd_segment_singular");
  const testing::CliResult depot = testing::RunCli(
      {"segment", testing::BundledMapsDir() + "/nav2/depot.yaml", "-o", dir + "/d.json"});
  ASSERT_EQ(depot.exit_code, 0) << depot.err;
  EXPECT_NE(depot.out.find("rooms: 8 (7 rooms, 1 corridor)  doors: 0"), std::string::npos)
      << depot.out;
  // Doorways too narrow to split anything: the arena is one corridor.
  const testing::CliResult one =
      testing::RunCli({"segment", Arena(), "-o", dir + "/a.json", "--doors", "0.1,0.2"});
  ASSERT_EQ(one.exit_code, 0) << one.err;
  EXPECT_NE(one.out.find("rooms: 1 (0 rooms, 1 corridor)"), std::string::npos) << one.out;
}

}  // namespace
}  // namespace linemap
