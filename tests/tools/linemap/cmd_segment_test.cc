// The `linemap segment` command, end to end through the built CLI.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "tests/testing/test_support.h"

namespace linemap {
namespace {

std::string Arena() { return testing::BundledMapsDir() + "/navtut/lse_arena.yaml"; }

// The arena: a small room (bottom left in the picture) opens onto the rest
// through a gap of about 1.2 m, a pocket behind a wall stub through one of
// 0.60 m (the stub in column 40 ends at row 46, the top wall is row 59:
// rows 47..58 free, 12 cells; it used to be reported as 2 c - 1 = 11 cells,
// 0.55 m), so the default method finds three rooms.
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
  EXPECT_NE(json.find("{\"rooms\":[1,3],\"width_m\":0.6"), std::string::npos) << json;
}

// --doors from 0.7 m: the 0.6 m gap to the pocket is no doorway any more.
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

// A 60 x 40 room of 0.05 m cells walled on every side, with a table of 4 x
// 3 cells in it: image columns 30..33, image rows 10..12, which are grid
// rows 39 - 12 .. 39 - 10 = 27..29 (row 0 at the bottom).
std::string TableRoom(const std::string& dir) {
  std::string pixels;
  for (int y = 0; y < 40; ++y) {
    for (int x = 0; x < 60; ++x) {
      const bool wall = x == 0 || y == 0 || x == 59 || y == 39;
      const bool table = x >= 30 && x <= 33 && y >= 10 && y <= 12;
      pixels += wall || table ? '\0' : '\xfe';
    }
  }
  testing::WriteFile(dir + "/table.pgm", "P5\n60 40\n255\n" + pixels);
  return dir + "/table.pgm";
}

// The blob's bbox, [x0, y0, x1, y1], from the first blob of a JSON file
// (`key`: "blobs" of the plain JSON) or of the GeoJSON's furniture feature.
std::vector<double> FirstBlobBox(const std::string& path, bool geojson) {
  const YAML::Node doc = YAML::LoadFile(path);
  YAML::Node box;
  if (geojson) {
    for (const YAML::Node& f : doc["features"]) {
      if (f["properties"]["layer"].as<std::string>() == "furniture") {
        box = f["properties"]["bbox"];
        break;
      }
    }
  } else {
    box = doc["blobs"][0]["bbox"];
  }
  std::vector<double> out;
  for (const YAML::Node& v : box) out.push_back(v.as<double>());
  return out;
}

// A blob's bbox is the axis-aligned box in map-frame metres around its
// cells: with a yaw in the origin, around the table's turned corners (it
// used to be two corners taken into metres, with x0 > x1 at yaw 3). The
// table covers cell units [29.5, 33.5] x [26.5, 29.5], i.e. u in [1.5, 1.7]
// m and v in [1.35, 1.5] m from the origin along the map's axes; the
// expected box is that of the four corners origin + R(yaw) (u, v), worked
// out here, for both methods and both formats.
TEST(CmdSegmentTest, BlobBoxIsTheAxisAlignedBoxAroundTheTurnedCells) {
  const std::string dir = testing::MakeTempDir("cmd_segment_bbox");
  const std::string map = TableRoom(dir);
  for (const double yaw : {0.0, 0.5, 3.0, -1.2}) {
    const double ox = -7, oy = -17.5;
    double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
    for (const double u : {1.5, 1.7}) {
      for (const double v : {1.35, 1.5}) {
        const double x = ox + std::cos(yaw) * u - std::sin(yaw) * v;
        const double y = oy + std::sin(yaw) * u + std::cos(yaw) * v;
        x0 = std::min(x0, x);
        y0 = std::min(y0, y);
        x1 = std::max(x1, x);
        y1 = std::max(y1, y);
      }
    }
    const std::string origin = "-7,-17.5," + std::to_string(yaw);
    struct Run {
      std::vector<std::string> args;
      bool geojson;
    };
    const std::vector<Run> runs = {{{"-o", dir + "/r.json"}, false},
                                   {{"--geojson", "-o", dir + "/r.geojson"}, true},
                                   {{"--method", "paper", "-o", dir + "/p.json"}, false}};
    for (const Run& run : runs) {
      std::vector<std::string> argv = {"segment", map, "--origin", origin};
      argv.insert(argv.end(), run.args.begin(), run.args.end());
      SCOPED_TRACE(origin + " " + run.args.back());
      const testing::CliResult r = testing::RunCli(argv);
      ASSERT_EQ(r.exit_code, 0) << r.err;
      const std::vector<double> box = FirstBlobBox(run.args.back(), run.geojson);
      ASSERT_EQ(box.size(), 4u);
      EXPECT_NEAR(box[0], x0, 1e-9);
      EXPECT_NEAR(box[1], y0, 1e-9);
      EXPECT_NEAR(box[2], x1, 1e-9);
      EXPECT_NEAR(box[3], y1, 1e-9);
      EXPECT_LE(box[0], box[2]);
      EXPECT_LE(box[1], box[3]);
    }
  }
}

// --doors and --max-room-area belong to the rooms method: with the paper's
// (--method paper, or --pose / --paper-border, which imply it) they are
// refused, naming the option, as --pose is with --method rooms.
TEST(CmdSegmentTest, RoomsOptionsAreRefusedWithThePapersMethod) {
  const std::string dir = testing::MakeTempDir("cmd_segment_rooms_only");
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"--method", "paper", "--doors", "0.6,1.0"}, "--doors"},
      {{"--pose", "1,1", "--doors", "0.6,1.0"}, "--doors"},
      {{"--paper-border", "--max-room-area", "20"}, "--max-room-area"},
      {{"--method", "paper", "--max-room-area", "0"}, "--max-room-area"}};
  for (const auto& [options, named] : cases) {
    std::vector<std::string> argv = {"segment", Arena(), "-o", dir + "/q.json"};
    argv.insert(argv.end(), options.begin(), options.end());
    const testing::CliResult r = testing::RunCli(argv);
    SCOPED_TRACE(options.back());
    EXPECT_EQ(r.exit_code, 2) << r.out;
    EXPECT_NE(r.err.find(named + " is an option of --method rooms"), std::string::npos) << r.err;
    EXPECT_FALSE(testing::FileExists(dir + "/q.json"));
  }
  // With the rooms method they still work.
  EXPECT_EQ(testing::RunCli({"segment", Arena(), "--method", "rooms", "--doors", "0.6,1.0",
                             "--max-room-area", "20", "-o", dir + "/ok.json"})
                .exit_code,
            0);
}

// --pose moves a robot standing off free space to a free cell at most 3
// cells away (and refuses one farther): the help says so, with the unit.
// A pose on the table room's table is taken.
TEST(CmdSegmentTest, PoseSnapsToFreeSpaceWithinThreeCellsAsTheHelpSays) {
  const testing::CliResult help = testing::RunCli({"segment", "--help"});
  ASSERT_EQ(help.exit_code, 0);
  EXPECT_NE(help.out.find("at most 3 cells away in column and row (0.15 m at 0.05 m/cell"),
            std::string::npos)
      << help.out;
  const std::string dir = testing::MakeTempDir("cmd_segment_pose_snap");
  const std::string map = TableRoom(dir);
  // The table's centre (31.5, 28) cells: metres (31.5 + 0.5) * 0.05 = 1.6,
  // (28 + 0.5) * 0.05 = 1.425, 2 cells from the free cells around it.
  const testing::CliResult on_table =
      testing::RunCli({"segment", map, "--pose", "1.6,1.425", "-o", dir + "/a.json"});
  EXPECT_EQ(on_table.exit_code, 0) << on_table.err;
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
