// Option parsing shared by the commands (cli.cc, map_input.cc,
// lmap_cli_util.cc), through the built CLI: counts and sizes are whole
// numbers, and the help shows which parts of a pose are optional.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "tests/testing/test_support.h"

namespace linemap {
namespace {

using testing::CliResult;
using testing::RunCli;

// --max-cells (every command that reads a map, and the .lmap commands),
// --max-segments, --max-objects and --max-file-bytes take 1 .. 2^64 - 1 in decimal digits: no
// exponent, fraction, sign or overflow (1e30 used to become "a limit of 0 cells", 1.5 became 1).
TEST(CliTest, LimitsAreWholeNumbers) {
  const std::string map = testing::BundledMapsDir() + "/navtut/lse_arena.yaml";
  const std::string lmap = testing::SourceDir() + "/tests/data/lmap/lse_arena_lossy.lmap";
  const std::string out = testing::MakeTempDir("cli_limits_parse") + "/o.yaml";
  const std::vector<std::vector<std::string>> commands = {
      {"info", map, "--max-cells"},
      {"info", lmap, "--max-cells"},
      {"decode", lmap, "-o", out, "--max-cells"},
      {"decode", lmap, "-o", out, "--max-file-bytes"},
      {"info", lmap, "--max-segments"},
      {"decode", lmap, "-o", out, "--max-objects"},
  };
  for (std::vector<std::string> argv : commands) {
    const std::string option = argv.back();
    for (const char* bad : {"1e30", "1.5", "-1", "0", "+5", " 5", "", "0x10", "5k",
                            "18446744073709551616", "99999999999999999999999"}) {
      argv.push_back(bad);
      const CliResult r = RunCli(argv);
      argv.pop_back();
      SCOPED_TRACE(argv[0] + " " + option + " '" + bad + "': " + r.err);
      EXPECT_EQ(r.exit_code, 2);
      EXPECT_NE(r.err.find(option), std::string::npos);
      EXPECT_NE(r.err.find("18446744073709551615"), std::string::npos);  // the range
      EXPECT_EQ(r.err.find("limit of 0"), std::string::npos);
    }
    for (const char* good : {"18446744073709551615", "4800"}) {
      argv.push_back(good);
      const CliResult r = RunCli(argv);
      argv.pop_back();
      EXPECT_EQ(r.exit_code, 0) << argv[0] << " " << option << " " << good << ": " << r.err;
    }
  }
  // 4799 cells is one too few for the 80 x 60 arena.
  EXPECT_EQ(RunCli({"info", map, "--max-cells", "4799"}).exit_code, 2);
}

// Two free points of the depot map (map-frame metres), for plan.
constexpr const char* kDepotFrom = "5,5";
constexpr const char* kDepotTo = "25,10";

// Every command that reads an .lmap file holds it to --max-segments and
// --max-objects: depot_v2.lmap has 437 wall segments and 33 furniture
// objects in 8 rooms (as `linemap info --json` lists them), so it reads at
// those limits and is refused, naming the limit, one below.
TEST(CliTest, LayerLimitsApplyToEveryCommandReadingAnLmap) {
  const std::string lmap = testing::SourceDir() + "/tests/data/lmap/depot_v2.lmap";
  const std::string dir = testing::MakeTempDir("cli_layer_limits");
  const std::vector<std::vector<std::string>> commands = {
      {"info", lmap},
      {"decode", lmap, "-o", dir + "/d.yaml"},
      {"export", lmap, "-o", dir + "/e.csv"},
      {"eval", lmap, lmap},
      {"lines", lmap, "-o", dir + "/l.csv"},
      {"segment", lmap, "-o", dir + "/s.json"},
      {"encode", lmap, "-o", dir + "/re.lmap"},
      {"plan", lmap, "--from", kDepotFrom, "--to", kDepotTo},
      // The windows read the layer sections that reach them, yet the limits
      // count the file's.
      {"decode", lmap, "-o", dir + "/w.yaml", "--window-cells", "0,0,50,50"},
      {"decode", lmap, "-o", dir + "/r.yaml", "--room-at", "15.1,7.6"},
      {"export", lmap, "-o", dir + "/w.csv", "--window", "5,2,12.5,9"},
  };
  struct Limit {
    const char* option;
    int count;
    const char* message;
  };
  for (const Limit& limit : {Limit{"--max-segments", 437, "exceed the segment limit of 436"},
                             Limit{"--max-objects", 33, "exceed the object limit of 32"}}) {
    for (std::vector<std::string> argv : commands) {
      argv.insert(argv.end(), {limit.option, std::to_string(limit.count - 1)});
      const CliResult refused = RunCli(argv);
      SCOPED_TRACE(argv[0] + " " + limit.option + ": " + refused.err);
      EXPECT_EQ(refused.exit_code, 2);
      EXPECT_NE(refused.err.find(limit.message), std::string::npos);
      EXPECT_NE(refused.err.find("depot_v2.lmap"), std::string::npos);
      argv.back() = std::to_string(limit.count);
      EXPECT_EQ(RunCli(argv).exit_code, 0);
    }
  }
}

// The layer limits count an .lmap file's layers: with maps that have none
// (a map YAML, a bare image) every command that reads a map refuses them
// (exit 2, naming the option and the map, nothing written) rather than
// ignoring them, as an .lmap file refuses the options that read images.
// eval takes them when either of its maps is an .lmap file, and holds that
// one to them.
TEST(CliTest, LayerLimitsWithoutAnLmapAreRefused) {
  const std::string yaml = testing::BundledMapsDir() + "/nav2/depot.yaml";
  const std::string image = testing::BundledMapsDir() + "/nav2/depot.pgm";
  const std::string lmap = testing::SourceDir() + "/tests/data/lmap/depot_v2.lmap";
  const std::string dir = testing::MakeTempDir("cli_layer_limits_no_lmap");
  for (const std::string& map : {yaml, image}) {
    const std::vector<std::vector<std::string>> commands = {
        {"info", map},
        {"lines", map, "-o", dir + "/l.csv"},
        {"segment", map, "-o", dir + "/s.json"},
        {"plan", map, "--from", kDepotFrom, "--to", kDepotTo, "--svg", dir + "/p.svg"},
        {"encode", map, "-o", dir + "/e.lmap"},
        // Saved as it is read, without loading the grid.
        {"encode", map, "-o", dir + "/f.lmap", "--no-png-ratio"},
        {"decode", map, "-o", dir + "/d.yaml"},
        {"export", map, "-o", dir + "/x.csv"},
        {"eval", map, yaml},
    };
    for (const char* option : {"--max-segments", "--max-objects"}) {
      for (std::vector<std::string> argv : commands) {
        argv.insert(argv.end(), {option, "1000"});
        const CliResult r = RunCli(argv);
        SCOPED_TRACE(argv[0] + " " + map + " " + option + ": " + r.err);
        EXPECT_EQ(r.exit_code, 2);
        EXPECT_NE(r.err.find(std::string(option) + " limits the vector layers of .lmap files"),
                  std::string::npos);
        EXPECT_NE(r.err.find("'" + map + "'"), std::string::npos);
        EXPECT_EQ(r.out, "");
      }
    }
    EXPECT_TRUE(testing::ListDir(dir).empty());
  }
  // Without the limits the same maps are read.
  EXPECT_EQ(RunCli({"info", image}).exit_code, 0);
  EXPECT_EQ(RunCli({"eval", image, yaml}).exit_code, 0);
  for (const std::vector<std::string>& maps :
       {std::vector<std::string>{yaml, lmap}, std::vector<std::string>{lmap, yaml}}) {
    SCOPED_TRACE(maps[0] + " " + maps[1]);
    EXPECT_EQ(RunCli({"eval", maps[0], maps[1], "--max-segments", "437"}).exit_code, 0);
    const CliResult over = RunCli({"eval", maps[0], maps[1], "--max-segments", "436"});
    EXPECT_EQ(over.exit_code, 2);
    EXPECT_NE(over.err.find("exceed the segment limit of 436"), std::string::npos) << over.err;
  }
}

TEST(CliTest, HelpShowsTheYawAsOptional) {
  for (const char* command : {"info", "encode", "lines", "segment", "plan", "eval"}) {
    const CliResult r = RunCli({command, "--help"});
    ASSERT_EQ(r.exit_code, 0) << command;
    EXPECT_NE(r.out.find("--origin X,Y[,YAW]"), std::string::npos) << command << ": " << r.out;
    EXPECT_EQ(r.out.find("X,Y,YAW"), std::string::npos) << command << ": " << r.out;
  }
}

// Every option naming a file (or folder) a command writes, after the
// arguments the command needs.
struct OutputCase {
  std::vector<std::string> argv;
  std::string option;
};

std::vector<OutputCase> OutputOptions() {
  const std::string map = testing::BundledMapsDir() + "/navtut/lse_arena.yaml";
  const std::string lmap = testing::SourceDir() + "/tests/data/lmap/lse_arena_lossy.lmap";
  return {
      {{"lines", map}, "-o"},
      {{"segment", map}, "-o"},
      {{"encode", map}, "-o"},
      {{"decode", lmap}, "-o"},
      {{"export", lmap}, "-o"},
      {{"plan", map, "--from", "0.5,0.5", "--to", "3.5,2.5"}, "--svg"},
      {{"bench", "/nonexistent/linemap-corpus"}, "--md"},
      {{"bench", "/nonexistent/linemap-corpus"}, "--csv"},
      {{"bench", "/nonexistent/linemap-corpus"}, "--svg-dir"},
  };
}

// An extension each command accepts for the option.
std::string GoodExtension(const OutputCase& c) {
  const std::string& command = c.argv[0];
  if (command == "lines" || command == "export" || c.option == "--csv") return ".csv";
  if (command == "segment") return ".json";
  if (command == "encode") return ".lmap";
  if (command == "decode") return ".yaml";
  if (command == "plan") return ".svg";
  if (c.option == "--md") return ".md";
  return "";  // --svg-dir: a folder
}

// A second output option used to replace the first without a word: the
// command wrote one file and the user expected two (or the first).
TEST(CliTest, AnOutputOptionGivenTwiceIsRefused) {
  const std::string dir = testing::MakeTempDir("cli_output_twice");
  for (const OutputCase& c : OutputOptions()) {
    const std::string ext = GoodExtension(c);
    for (const bool inline_value : {false, true}) {
      std::vector<std::string> argv = c.argv;
      if (inline_value) {
        argv.push_back(c.option + "=" + dir + "/first" + ext);
      } else {
        argv.insert(argv.end(), {c.option, dir + "/first" + ext});
      }
      argv.insert(argv.end(), {c.option, dir + "/second" + ext});
      const CliResult r = RunCli(argv);
      SCOPED_TRACE(argv[0] + " " + c.option + ": " + r.err);
      EXPECT_EQ(r.exit_code, 2);
      EXPECT_NE(r.err.find(c.option + " given twice"), std::string::npos);
      EXPECT_TRUE(testing::ListDir(dir).empty());
    }
  }
}

// A file holds what its extension says, or the command refuses the name
// before any work (lines wrote CSV to x.json, plan SVG to x.png).
TEST(CliTest, AnOutputNameWithTheWrongExtensionIsRefused) {
  const std::string dir = testing::MakeTempDir("cli_output_extension");
  const std::string map = testing::BundledMapsDir() + "/navtut/lse_arena.yaml";
  const std::string lmap = testing::SourceDir() + "/tests/data/lmap/lse_arena_lossy.lmap";
  const std::string corrupt = testing::SourceDir() + "/tests/data/bad/lmap_decode/bad_crc.lmap";
  struct Case {
    std::vector<std::string> argv;
    std::string path;
    std::string expected;  // the extension the message names
  };
  const std::vector<Case> cases = {
      {{"lines", map, "-o", dir + "/x.json"}, dir + "/x.json", ".csv"},
      {{"lines", map, "-o", dir + "/csv"}, dir + "/csv", ".csv"},
      {{"plan", map, "--from", "0.5,0.5", "--to", "3.5,2.5", "--svg", dir + "/x.png"},
       dir + "/x.png",
       ".svg"},
      {{"segment", map, "-o", dir + "/x.csv"}, dir + "/x.csv", ".json"},
      // GeoJSON only with --geojson; plain JSON is not GeoJSON.
      {{"segment", map, "-o", dir + "/x.geojson"}, dir + "/x.geojson", ".json"},
      {{"segment", map, "--geojson", "-o", dir + "/x.csv"}, dir + "/x.csv", ".geojson"},
      {{"bench", "/nonexistent/linemap-corpus", "--md", dir + "/x.txt"}, dir + "/x.txt", ".md"},
      {{"bench", "/nonexistent/linemap-corpus", "--csv", dir + "/x.txt"}, dir + "/x.txt", ".csv"},
      // These refused a wrong name already; export picks its format by
      // the extension and refuses one it does not know.
      {{"encode", map, "-o", dir + "/x.png"}, dir + "/x.png", ".lmap"},
      {{"decode", lmap, "-o", dir + "/x.pgm"}, dir + "/x.pgm", ".yaml"},
      // Refused before the file is read: a corrupt one is not reported.
      {{"decode", corrupt, "-o", dir + "/x.pgm"}, dir + "/x.pgm", ".yaml"},
      {{"export", lmap, "-o", dir + "/x.txt"}, dir + "/x.txt", ".csv"},
  };
  for (const Case& c : cases) {
    const CliResult r = RunCli(c.argv);
    SCOPED_TRACE(c.argv[0] + " " + c.path + ": " + r.err);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("'" + c.path + "'"), std::string::npos);
    EXPECT_NE(r.err.find(c.expected), std::string::npos);
    EXPECT_TRUE(testing::ListDir(dir).empty());
  }
}

TEST(CliTest, AnOutputNameWithTheRightExtensionIsWritten) {
  const std::string dir = testing::MakeTempDir("cli_output_extension_ok");
  const std::string map = testing::BundledMapsDir() + "/navtut/lse_arena.yaml";
  const std::vector<std::vector<std::string>> commands = {
      {"lines", map, "-o", dir + "/LINES.CSV"},  // any case, as encode's .lmap
      {"plan", map, "--from", "0.5,0.5", "--to", "3.5,2.5", "--svg", dir + "/plan.svg"},
      {"segment", map, "-o", dir + "/rooms.json"},
      {"segment", map, "--geojson", "-o", dir + "/rooms.geo.json"},
      {"encode", map, "-o", dir + "/ARENA.LMAP"},
  };
  for (const std::vector<std::string>& argv : commands) {
    const CliResult r = RunCli(argv);
    EXPECT_EQ(r.exit_code, 0) << argv[0] << " " << argv.back() << ": " << r.err;
    EXPECT_TRUE(testing::FileExists(argv.back())) << argv.back();
  }
  // export picks the format by the extension, in any case too.
  for (const char* name : {"/walls.SVG", "/walls.Csv", "/walls.GeoJSON"}) {
    const std::vector<std::string> argv = {"export", dir + "/ARENA.LMAP", "-o", dir + name};
    const CliResult r = RunCli(argv);
    EXPECT_EQ(r.exit_code, 0) << argv[0] << " " << argv.back() << ": " << r.err;
    EXPECT_TRUE(testing::FileExists(argv.back())) << argv.back();
  }
}

}  // namespace
}  // namespace linemap
