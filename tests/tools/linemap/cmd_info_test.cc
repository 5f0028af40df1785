// The built `linemap` binary: info, --help, --version, and bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "linemap/codec.h"
#include "linemap/lmap_vectors.h"
#include "linemap/map_io.h"
#include "tests/testing/test_support.h"

namespace linemap {
namespace {

using testing::CliResult;
using testing::ListDir;
using testing::MakeTempDir;
using testing::RunCli;
using testing::WriteFile;

TEST(CmdInfoTest, JsonHasTheDocumentedKeys) {
  const std::string dir = MakeTempDir("cli");
  // 3 x 2 map: top row O F U, bottom row F F O.
  WriteFile(dir + "/m.pgm",
            std::string("P5 3 2 255\n") + std::string("\x00\xfe\xcd\xfe\xfe\x00", 6));
  WriteFile(dir + "/m.yaml",
            "image: m.pgm\nresolution: 0.1\norigin: [1.5, -2.0, 0.0]\nnegate: 0\n"
            "occupied_thresh: 0.65\nfree_thresh: 0.196\n");
  const CliResult r = RunCli({"info", dir + "/m.yaml", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("\"width\":3,\"height\":2,\"resolution\":0.1,\"origin\":[1.5,-2,0],"
                       "\"free\":3,\"occupied\":2,\"unknown\":1"),
            std::string::npos)
      << r.out;
}

// A 2.0 file: the counts of its layers (read here through LoadLmapVectors,
// the raster-free reader) in text and JSON, and its chunks.
TEST(CmdInfoTest, LmapCountsTheVectorLayers) {
  const std::string dir = MakeTempDir("cli_info_layers");
  ASSERT_EQ(
      RunCli({"encode", testing::BundledMapsDir() + "/nav2/depot.yaml", "-o", dir + "/d.lmap"})
          .exit_code,
      0);
  StatusOr<LmapVectors> v = LoadLmapVectors(dir + "/d.lmap");
  ASSERT_TRUE(v.ok());
  std::size_t segments = 0;
  for (const WallPolyline& w : v->walls) segments += w.points.size() - 1;
  ASSERT_GT(v->walls.size(), 0u);
  ASSERT_GT(v->rooms.size(), 0u);
  ASSERT_GT(v->furniture.size(), 0u);
  ASSERT_GT(segments, v->walls.size());  // some walls are polylines of several segments
  const std::string counts = "\"walls\":" + std::to_string(v->walls.size()) +
                             ",\"wall_segments\":" + std::to_string(segments) +
                             ",\"rooms\":" + std::to_string(v->rooms.size()) +
                             ",\"furniture\":" + std::to_string(v->furniture.size()) + ",";
  const CliResult json = RunCli({"info", dir + "/d.lmap", "--json"});
  ASSERT_EQ(json.exit_code, 0) << json.err;
  EXPECT_NE(json.out.find(counts), std::string::npos) << counts << "\n" << json.out;
  EXPECT_NE(json.out.find("\"version\":\"2."), std::string::npos) << json.out;
  EXPECT_NE(json.out.find("{\"type\":\"LAYR\","), std::string::npos) << json.out;
  EXPECT_EQ(json.out.find("\"segments\""), std::string::npos) << json.out;  // 1.0 keys only
  // The pixel fields the file keeps, as `info` prints them for the map YAML.
  const CliResult yaml = RunCli({"info", testing::BundledMapsDir() + "/nav2/depot.yaml", "--json"});
  const std::size_t mode = yaml.out.find("\"mode\":");
  ASSERT_NE(mode, std::string::npos) << yaml.out;
  const std::string pixels = yaml.out.substr(mode, yaml.out.find('}', mode) - mode);
  EXPECT_NE(pixels.find("\"free_thresh\":"), std::string::npos) << pixels;
  EXPECT_NE(json.out.find(pixels), std::string::npos) << pixels << "\n" << json.out;
  const CliResult text = RunCli({"info", dir + "/d.lmap"});
  ASSERT_EQ(text.exit_code, 0) << text.err;
  const std::string line = "layers:     " + std::to_string(v->walls.size()) + " walls (" +
                           std::to_string(segments) + " segments), " +
                           std::to_string(v->rooms.size()) + " rooms, " +
                           std::to_string(v->furniture.size()) + " furniture\n";
  EXPECT_NE(text.out.find(line), std::string::npos) << line << text.out;
  EXPECT_NE(text.out.find("chunk:      CELL"), std::string::npos) << text.out;
}

// What the first line says a file is: exact, within a tolerance of the T
// it names (2.x cells in blocks; a file of 2.2 written before files named T
// says only that), or the former lossy 1.0 file (a fixture: 1.0 is no longer
// written).
TEST(CmdInfoTest, FirstLineSaysHowExactTheFileIs) {
  const std::string dir = MakeTempDir("cli_info_fidelity");
  const std::string map =
      testing::SourceDir() + "/tests/data/maps/turtlebot_apps/" + "willow-2010-02-18-0.10.yaml";
  ASSERT_EQ(RunCli({"encode", map, "-o", dir + "/exact.lmap"}).exit_code, 0);
  ASSERT_EQ(RunCli({"encode", map, "-o", dir + "/t2.lmap", "--tolerance", "2"}).exit_code, 0);
  const std::string fixtures = testing::SourceDir() + "/tests/data/lmap/";
  const std::pair<std::string, std::string> cases[] = {
      {dir + "/exact.lmap", ", lossless)\n"},
      {dir + "/t2.lmap", ", within a tolerance of 2 cells (0.2 m))\n"},
      {fixtures + "willow_v2_3_tolerance_1.lmap", ", within a tolerance of 1 cell (0.1 m))\n"},
      {fixtures + "willow_v2_2_tolerance_1.lmap", "(.lmap version 2.2, within a tolerance)\n"},
      {fixtures + "depot_lossy.lmap", "(.lmap version 1.0, lossy)\n"},
  };
  for (const auto& [file, label] : cases) {
    const CliResult r = RunCli({"info", file});
    ASSERT_EQ(r.exit_code, 0) << file << ": " << r.err;
    EXPECT_NE(r.out.substr(0, r.out.find('\n') + 1).find(label), std::string::npos) << file << "\n"
                                                                                    << r.out;
  }
}

TEST(CmdInfoTest, TextOutputOnABundledMap) {
  const CliResult r = RunCli({"info", testing::BundledMapsDir() + "/navtut/lse_arena.yaml"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("80 x 60 cells"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("resolution: 0.05 m/cell"), std::string::npos) << r.out;
}

// A UTM-sized origin is printed to the last digit given (six significant
// digits put y 3.2 m away), for a map and for its .lmap.
TEST(CmdInfoTest, TextGivesTheOriginInFull) {
  const std::string dir = MakeTempDir("cli_info_origin");
  const std::string map = testing::BundledMapsDir() + "/navtut/lse_arena.yaml";
  const std::vector<std::string> origin = {"--origin", "500123.456,4649776.789,0.123456789",
                                           "--resolution", "0.025"};
  std::vector<std::string> info = {"info", map};
  info.insert(info.end(), origin.begin(), origin.end());
  std::vector<std::string> encode = {"encode", map, "-o", dir + "/utm.lmap"};
  encode.insert(encode.end(), origin.begin(), origin.end());
  ASSERT_EQ(RunCli(encode).exit_code, 0);
  for (const CliResult& r : {RunCli(info), RunCli({"info", dir + "/utm.lmap"})}) {
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("resolution: 0.025 m/cell\norigin:     x 500123.456 m, y 4649776.789 m, "
                         "yaw 0.123456789 rad\n"),
              std::string::npos)
        << r.out;
  }
}

// A file saved --raster-only has no layers, which info says, rather than
// counting zero walls as if the map had none.
TEST(CmdInfoTest, RasterOnlyFileHasNoLayers) {
  const std::string dir = MakeTempDir("cli_info_raster");
  const std::string map = testing::BundledMapsDir() + "/navtut/lse_arena.yaml";
  ASSERT_EQ(RunCli({"encode", map, "-o", dir + "/r.lmap", "--raster-only"}).exit_code, 0);
  const CliResult r = RunCli({"info", dir + "/r.lmap"});
  EXPECT_NE(r.out.find("layers:     none (cells only)\n"), std::string::npos) << r.out;
  EXPECT_NE(RunCli({"info", dir + "/r.lmap", "--json"}).out.find("\"layers\":false,\"walls\":0,"),
            std::string::npos);
  ASSERT_EQ(RunCli({"encode", map, "-o", dir + "/l.lmap"}).exit_code, 0);
  EXPECT_NE(RunCli({"info", dir + "/l.lmap"}).out.find(" walls ("), std::string::npos);
  EXPECT_NE(RunCli({"info", dir + "/l.lmap", "--json"}).out.find("\"layers\":true,"),
            std::string::npos);
  // A 1.0 file's SEGS chunk is a layer chunk too.
  EXPECT_NE(RunCli({"info", testing::SourceDir() + "/tests/data/lmap/depot_lossy.lmap", "--json"})
                .out.find("\"layers\":true,"),
            std::string::npos);
}

TEST(CmdInfoTest, BareImageTakesCommandLineOverrides) {
  const std::string dir = MakeTempDir("cli");
  WriteFile(dir + "/m.pgm", std::string("P5 2 1 255\n") + std::string("\x00\xcd", 2));
  const CliResult r = RunCli({"info", dir + "/m.pgm", "--json", "--resolution", "0.2", "--origin",
                              "1,2,0.5", "--free-thresh", "0.25"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("\"resolution\":0.2,\"origin\":[1,2,0.5],\"free\":1,\"occupied\":1,"
                       "\"unknown\":0"),
            std::string::npos)
      << r.out;
}

// The map options read images and YAMLs: given with an .lmap file (which
// keeps its own values) they are refused, not silently dropped; a threshold
// override that puts free at or above occupied is refused too.
TEST(CmdInfoTest, MapOptionsThatCannotApplyAreRefused) {
  const std::string dir = MakeTempDir("cli_map_options");
  const std::string depot = testing::BundledMapsDir() + "/nav2/depot.yaml";
  ASSERT_EQ(RunCli({"encode", depot, "-o", dir + "/d.lmap", "--no-png-ratio"}).exit_code, 0);
  const std::vector<std::vector<std::string>> refused = {
      {"info", dir + "/d.lmap", "--resolution", "0.1"},
      {"info", dir + "/d.lmap", "--negate"},
      {"encode", dir + "/d.lmap", "-o", dir + "/e.lmap", "--origin", "1,2"},
      {"lines", dir + "/d.lmap", "--mode", "raw"},
      {"eval", dir + "/d.lmap", depot, "--free-thresh", "0.2"}};
  for (const std::vector<std::string>& args : refused) {
    const CliResult r = RunCli(args);
    SCOPED_TRACE(args[0] + " " + args[2] + ": " + r.err);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("keeps its own resolution, origin and cells"), std::string::npos);
    EXPECT_NE(r.err.find(dir + "/d.lmap"), std::string::npos);
  }
  EXPECT_FALSE(testing::FileExists(dir + "/e.lmap"));
  EXPECT_EQ(RunCli({"info", dir + "/d.lmap", "--max-cells", "1000000"}).exit_code, 0);
  const CliResult order = RunCli({"info", depot, "--free-thresh", "0.9"});
  EXPECT_EQ(order.exit_code, 2);
  EXPECT_NE(order.err.find("free threshold 0.9 must be below the occupied threshold 0.65"),
            std::string::npos)
      << order.err;
  const CliResult range = RunCli({"info", depot, "--occupied-thresh", "1.5"});
  EXPECT_EQ(range.exit_code, 2);
  EXPECT_NE(range.err.find("occupied_thresh must be within 0..1"), std::string::npos) << range.err;
  const CliResult epsilon =
      RunCli({"encode", depot, "-o", dir + "/x.lmap", "--epsilon", "0.3", "--no-png-ratio"});
  EXPECT_EQ(epsilon.exit_code, 2);
  EXPECT_NE(epsilon.err.find("--epsilon must be at least 0.5 cells"), std::string::npos)
      << epsilon.err;
}

TEST(CmdInfoTest, HelpAndVersion) {
  CliResult r = RunCli({"--version"});
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_EQ(r.out.rfind("linemap ", 0), 0u);
  r = RunCli({"--help"});
  EXPECT_EQ(r.exit_code, 0);
  for (const char* command :
       {"info", "encode", "decode", "lines", "segment", "export", "eval", "plan", "bench"}) {
    EXPECT_NE(r.out.find(std::string("  ") + command), std::string::npos) << command;
    const CliResult help = RunCli({command, "--help"});
    EXPECT_EQ(help.exit_code, 0) << command;
    EXPECT_NE(help.out.find(std::string("Usage: linemap ") + command), std::string::npos);
  }
  EXPECT_EQ(RunCli({}).exit_code, 2);
  EXPECT_EQ(RunCli({"frobnicate"}).exit_code, 2);
  EXPECT_EQ(RunCli({"info"}).exit_code, 2);
  EXPECT_EQ(RunCli({"info", "a.yaml", "--no-such-option"}).exit_code, 2);
  EXPECT_EQ(RunCli({"info", "a.yaml", "--resolution"}).exit_code, 2);
}

TEST(CmdInfoTest, BadInputGivesOneLineNamingTheFileAndExitTwo) {
  const std::string dir = MakeTempDir("cli");
  WriteFile(dir + "/img.pgm", std::string("P5 1 1 255\n") + std::string("\x00", 1));
  WriteFile(dir + "/no_image.yaml", "resolution: 0.05\norigin: [0, 0, 0]\n");
  WriteFile(dir + "/negative.yaml", "image: img.pgm\nresolution: -0.05\norigin: [0, 0, 0]\n");
  WriteFile(dir + "/empty_room.yaml", "image: empty.pgm\nresolution: 0.1\norigin: [0, 0, 0]\n");
  WriteFile(dir + "/notamap.png", "this is text, not an image");
  WriteFile(dir + "/empty.pgm", "");
  const std::vector<std::string> before = ListDir(dir);
  const std::vector<std::string> bad = {"missing.yaml",    "no_image.yaml", "negative.yaml",
                                        "empty_room.yaml", "notamap.png",   "empty.pgm"};
  for (const std::string& name : bad) {
    const CliResult r = RunCli({"info", dir + "/" + name});
    EXPECT_EQ(r.exit_code, 2) << name;
    EXPECT_NE(r.err.find(name), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
  }
  const CliResult r = RunCli({"info", dir});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("directory"), std::string::npos) << r.err;
  EXPECT_EQ(ListDir(dir), before);
}

TEST(CmdInfoTest, SharedEmptyRoomYamlNamesAMissingImage) {
  const std::string shared = testing::SharedMapsDir();
  if (shared.empty()) GTEST_SKIP() << "../shared/maps is absent";
  const CliResult r = RunCli({"info", shared + "/nav2/empty_room.yaml"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("empty.pgm"), std::string::npos) << r.err;
}

// The metadata `encode --metadata --time --pose` stores, which the text
// output printed and --json left out, is in the JSON as the object
// "metadata"; a file without any has {}.
TEST(CmdInfoTest, JsonHoldsTheMetadata) {
  const std::string dir = MakeTempDir("cli_info_metadata");
  const std::string depot = testing::BundledMapsDir() + "/nav2/depot.yaml";
  ASSERT_EQ(RunCli({"encode", depot, "-o", dir + "/m.lmap", "--metadata", "--time",
                    "2024-05-01T12:00:00Z", "--pose", "5,5,0.5"})
                .exit_code,
            0);
  const CliResult text = RunCli({"info", dir + "/m.lmap"});
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("meta:       time = 2024-05-01T12:00:00Z\n"), std::string::npos)
      << text.out;
  const CliResult json = RunCli({"info", dir + "/m.lmap", "--json"});
  ASSERT_EQ(json.exit_code, 0) << json.err;
  EXPECT_NE(json.out.find("\"metadata\":{\"creator\":\"linemap "), std::string::npos) << json.out;
  for (const char* entry : {"\"time\":\"2024-05-01T12:00:00Z\"", "\"frame_id\":\"map\"",
                            "\"robot_pose\":\"5 5 0.5\""}) {
    EXPECT_NE(json.out.find(entry), std::string::npos) << entry << "\n" << json.out;
  }
  ASSERT_EQ(RunCli({"encode", depot, "-o", dir + "/plain.lmap"}).exit_code, 0);
  const CliResult plain = RunCli({"info", dir + "/plain.lmap", "--json"});
  EXPECT_NE(plain.out.find("\"metadata\":{}"), std::string::npos) << plain.out;
  EXPECT_NE(plain.out.find("\"tolerance_cells\":null"), std::string::npos) << plain.out;
  ASSERT_EQ(RunCli({"encode", depot, "-o", dir + "/t1.lmap", "--tolerance", "1"}).exit_code, 0);
  const CliResult t1 = RunCli({"info", dir + "/t1.lmap", "--json"});
  EXPECT_NE(t1.out.find("\"lossless\":false,\"tolerance_cells\":1,"), std::string::npos) << t1.out;
  EXPECT_NE(t1.out.find("\"metadata\":{\"tolerance\":\"1\"}"), std::string::npos) << t1.out;
  const CliResult help = RunCli({"info", "--help"});
  EXPECT_NE(help.out.find("metadata"), std::string::npos) << help.out;
  EXPECT_NE(help.out.find("robot_pose"), std::string::npos) << help.out;
}

// lse_arena saved with `options` (metadata text as another writer may store
// it) as m.lmap in a new folder tagged `tag`; the file's path.
std::string LseArenaFileWith(const EncodeOptions& options, const std::string& tag) {
  const std::string dir = MakeTempDir(tag);
  StatusOr<Grid> grid = LoadRosMap(testing::BundledMapsDir() + "/navtut/lse_arena.yaml");
  EXPECT_TRUE(grid.ok()) << grid.status().message();
  if (!grid.ok()) return dir + "/m.lmap";
  StatusOr<std::vector<std::uint8_t>> bytes = EncodeLmap(*grid, options);
  EXPECT_TRUE(bytes.ok()) << bytes.status().message();
  if (bytes.ok()) WriteFile(dir + "/m.lmap", std::string(bytes->begin(), bytes->end()));
  return dir + "/m.lmap";
}

// Metadata from another writer may hold control characters (the format
// does not check its text): info prints each entry on one line, escaped,
// and --json escapes them as JSON does.
TEST(CmdInfoTest, ControlCharactersInMetadataAreEscaped) {
  EncodeOptions options;
  options.time = "a\nb";
  options.creator = "tab\there \\ \x1b";
  const std::string lmap = LseArenaFileWith(options, "cli_info_metadata_escape");
  const CliResult text = RunCli({"info", lmap});
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("meta:       time = a\\nb\n"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("meta:       creator = tab\\there \\\\ \\x1b\n"), std::string::npos)
      << text.out;
  const CliResult json = RunCli({"info", lmap, "--json"});
  ASSERT_EQ(json.exit_code, 0) << json.err;
  EXPECT_NE(json.out.find("\"time\":\"a\\nb\""), std::string::npos) << json.out;
  EXPECT_EQ(std::count(json.out.begin(), json.out.end(), '\n'), 1) << json.out;
}

// JSON is UTF-8: metadata another tool wrote in Latin-1 (or any stray byte)
// must not make `info --json` print invalid JSON; well-formed UTF-8 passes.
TEST(CmdInfoTest, JsonReplacesBytesThatAreNotUtf8) {
  EncodeOptions options;
  // K\xfcche: Latin-1; then a lone continuation byte, an overlong '/', a
  // surrogate and a sequence cut short; then well-formed "K\u00fcche \u20ac".
  options.creator =
      "K\xfc"
      "che|\x80|\xc0\xaf|\xed\xa0\x80|\xe2\x82";
  options.frame_id =
      "K\xc3\xbc"
      "che \xe2\x82\xac";
  const CliResult json =
      RunCli({"info", LseArenaFileWith(options, "cli_info_metadata_utf8"), "--json"});
  ASSERT_EQ(json.exit_code, 0) << json.err;
  EXPECT_NE(json.out.find("\"creator\":\"K\\ufffdche|\\ufffd|\\ufffd\\ufffd|"
                          "\\ufffd\\ufffd\\ufffd|\\ufffd\\ufffd\""),
            std::string::npos)
      << json.out;
  EXPECT_NE(json.out.find("\"frame_id\":\"K\xc3\xbc"
                          "che \xe2\x82\xac\""),
            std::string::npos)
      << json.out;
}

}  // namespace
}  // namespace linemap
