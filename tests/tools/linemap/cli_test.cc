// Option parsing shared by the commands (cli.cc, map_input.cc,
// lmap_cli_util.cc), through the built CLI: counts and sizes are whole
// numbers, and the help shows which parts of a pose are optional.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "tests/testing/test_support.h"

namespace linemap {
namespace {

using testing::CliResult;
using testing::RunCli;

// --max-cells (every command that reads a map, and the .lmap commands),
// --max-segments, --max-objects and --max-file-bytes take 1 .. 2^64 - 1 in decimal digits: no
// exponent, fraction, sign or overflow (1e30 used to become "a limit of 0 cells", 1.5 became 1).
// A whole number past an int is out of range, not "not a whole number".
TEST(CliTest, IntOptionPastTheRangeSaysSo) {
  const std::string map = testing::BundledMapsDir() + "/navtut/lse_arena.yaml";
  const std::string out = testing::MakeTempDir("cli_int_range") + "/o.lmap";
  for (const char* big : {"2147483648", "-2147483649", "99999999999999"}) {
    const CliResult r = RunCli({"encode", map, "-o", out, "--section-size", big});
    EXPECT_EQ(r.exit_code, 2) << big;
    EXPECT_NE(r.err.find(std::string("--section-size is out of range (-2147483648 to "
                                     "2147483647), not '") +
                         big + "'"),
              std::string::npos)
        << r.err;
  }
  const CliResult fraction = RunCli({"encode", map, "-o", out, "--section-size", "1e3"});
  EXPECT_NE(fraction.err.find("--section-size expects a whole number, not '1e3'"),
            std::string::npos)
      << fraction.err;
}

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

// Every command that writes after its work refuses, before the work, an
// output it could not write: into a missing folder, over a read-only file,
// or a bench folder under a file. Exit 2 (bad usage, as an output that is a
// directory), one line naming the output, nothing created anywhere and the
// read-only file untouched. Before, encode ran the whole encode (minutes
// within a tolerance on a large map) and plan the whole plan, then exit 1.
TEST(CliTest, AnOutputThatCannotBeWrittenIsRefusedBeforeTheWork) {
  namespace fs = std::filesystem;
  const std::string dir = testing::MakeTempDir("cli_output_unwritable");
  const std::string map = testing::BundledMapsDir() + "/navtut/lse_arena.yaml";
  const std::string lmap = testing::SourceDir() + "/tests/data/lmap/lse_arena_lossy.lmap";
  const std::string corpus = testing::BundledMapsDir() + "/navtut";
  const std::string missing = dir + "/no_such_folder";
  testing::WriteFile(dir + "/file", "a file, not a folder\n");
  struct Case {
    std::vector<std::string> argv;  // the output last but for the ro_* name
    std::string read_only;          // a name in `dir` to make read-only, or ""
    std::string named;              // what the message must name
  };
  const std::vector<Case> cases = {
      {{"encode", map, "-o", missing + "/x.lmap"}, "", "no_such_folder"},
      {{"encode", map, "-o", missing + "/x.lmap", "--tolerance", "1"}, "", "no_such_folder"},
      {{"encode", map, "-o", dir + "/ro.lmap"}, "ro.lmap", "read-only"},
      {{"decode", lmap, "-o", missing + "/x.yaml"}, "", "no_such_folder"},
      {{"decode", lmap, "-o", dir + "/ro.yaml"}, "ro.yaml", "read-only"},
      // The image decode writes beside the YAML.
      {{"decode", lmap, "-o", dir + "/img.yaml"}, "img.pgm", "img.pgm"},
      {{"export", lmap, "-o", missing + "/x.svg"}, "", "no_such_folder"},
      {{"export", lmap, "-o", dir + "/ro.geojson"}, "ro.geojson", "read-only"},
      {{"lines", map, "-o", missing + "/x.csv"}, "", "no_such_folder"},
      {{"lines", map, "-o", dir + "/ro.csv"}, "ro.csv", "read-only"},
      {{"segment", map, "-o", missing + "/x.json"}, "", "no_such_folder"},
      {{"segment", map, "-o", dir + "/ro.json"}, "ro.json", "read-only"},
      {{"plan", map, "--from", "0.5,0.5", "--to", "3.5,2.5", "--svg", missing + "/x.svg"},
       "",
       "no_such_folder"},
      {{"plan", map, "--from", "0.5,0.5", "--to", "3.5,2.5", "--svg", dir + "/ro.svg"},
       "ro.svg",
       "read-only"},
      {{"bench", corpus, "--scaling-max", "0", "--md", missing + "/x.md"}, "", "no_such_folder"},
      {{"bench", corpus, "--scaling-max", "0", "--csv", dir + "/ro.csv"}, "ro.csv", "read-only"},
      {{"bench", corpus, "--scaling-max", "0", "--svg-dir", dir + "/file/svg"}, "", "file"},
  };
  for (const Case& c : cases) {
    if (!c.read_only.empty()) {
      testing::WriteFile(dir + "/" + c.read_only, "keep me\n");
      ASSERT_EQ(::chmod((dir + "/" + c.read_only).c_str(), 0444), 0);
    }
    const std::vector<std::string> before = testing::ListDir(dir);
    const CliResult r = RunCli(c.argv);
    std::string where;
    for (const std::string& a : c.argv) where += a + " ";
    SCOPED_TRACE(where + "\nstderr: " + r.err);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1);
    EXPECT_NE(r.err.find(c.named), std::string::npos);
    // Refused before the work: the encode, the plan and the bench print
    // their results only once done.
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(testing::ListDir(dir), before);
    EXPECT_FALSE(fs::exists(missing));
    if (!c.read_only.empty()) {
      EXPECT_EQ(testing::ReadFile(dir + "/" + c.read_only), "keep me\n");
      ::chmod((dir + "/" + c.read_only).c_str(), 0644);
      fs::remove(dir + "/" + c.read_only);
    }
  }
  // A folder without write permission (root writes anyway: not checked then).
  if (::geteuid() != 0) {
    fs::create_directories(dir + "/locked");
    ASSERT_EQ(::chmod((dir + "/locked").c_str(), 0555), 0);
    const CliResult r = RunCli({"encode", map, "-o", dir + "/locked/x.lmap"});
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("locked"), std::string::npos) << r.err;
    ::chmod((dir + "/locked").c_str(), 0755);
    EXPECT_TRUE(testing::ListDir(dir + "/locked").empty());
  }
  fs::remove_all(dir);
}

// The names of the commands (`linemap --help`) and, from each command's
// --help, its options that take a value.
std::vector<std::pair<std::string, std::vector<std::string>>> ValueOptionsOfEveryCommand() {
  std::vector<std::pair<std::string, std::vector<std::string>>> result;
  std::istringstream usage(RunCli({"--help"}).out);
  std::string line;
  bool in_commands = false;
  while (std::getline(usage, line)) {
    if (line == "Commands:") {
      in_commands = true;
      continue;
    }
    if (!in_commands || line.rfind("  ", 0) != 0) {
      if (in_commands && line.empty()) break;
      continue;
    }
    std::istringstream words(line);
    std::string command;
    words >> command;
    std::vector<std::string> options;
    std::istringstream help(RunCli({command, "--help"}).out);
    bool in_options = false;
    while (std::getline(help, line)) {
      if (line == "Options:") {
        in_options = true;
        continue;
      }
      if (!in_options || line.rfind("  -", 0) != 0) continue;
      std::istringstream parts(line);
      std::string name, value;
      parts >> name >> value;
      // A value is in capitals (OUT.lmap, X,Y[,YAW], rooms|paper); help
      // text starts in lower case.
      const bool takes_value =
          !value.empty() && (std::isupper(static_cast<unsigned char>(value[0])) != 0 ||
                             value.find('|') != std::string::npos);
      if (takes_value) options.push_back(name);
    }
    result.emplace_back(command, options);
  }
  return result;
}

// A repeated option used to take its last value without a word:
// `encode D -o t.lmap --tolerance 2 --tolerance 0` saved exact. Every
// option with a value, of every command, is refused given twice (exit 2,
// naming it), whatever the values and however given.
TEST(CliTest, EveryValueOptionGivenTwiceIsRefused) {
  const auto commands = ValueOptionsOfEveryCommand();
  ASSERT_GE(commands.size(), 9u);
  std::size_t checked = 0;
  for (const auto& [command, options] : commands) {
    EXPECT_FALSE(options.empty()) << command;
    for (const std::string& option : options) {
      for (const bool inline_first : {false, true}) {
        // An input that is not there: were the option taken, the command
        // would stop at once (bench on its default corpus would run for
        // minutes).
        std::vector<std::string> argv = {command, "/nonexistent/linemap-input"};
        if (inline_first) {
          argv.push_back(option + "=1");
        } else {
          argv.insert(argv.end(), {option, "1"});
        }
        argv.insert(argv.end(), {option, "2"});
        const CliResult r = RunCli(argv);
        SCOPED_TRACE(command + " " + option + ": " + r.err);
        EXPECT_EQ(r.exit_code, 2);
        EXPECT_NE(r.err.find(option + " given twice"), std::string::npos);
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 100u);
  // The audit's cases, with everything else right.
  const std::string dir = testing::MakeTempDir("cli_value_twice");
  const std::string depot = testing::BundledMapsDir() + "/nav2/depot.yaml";
  const CliResult tolerance =
      RunCli({"encode", depot, "-o", dir + "/t.lmap", "--tolerance", "2", "--tolerance", "0"});
  EXPECT_EQ(tolerance.exit_code, 2);
  EXPECT_NE(tolerance.err.find("--tolerance given twice ('2' and '0')"), std::string::npos)
      << tolerance.err;
  ASSERT_EQ(RunCli({"encode", depot, "-o", dir + "/d.lmap"}).exit_code, 0);
  const CliResult window = RunCli({"decode", dir + "/d.lmap", "-o", dir + "/w.yaml",
                                   "--window-cells", "0,0,10,10", "--window-cells", "0,0,20,20"});
  EXPECT_EQ(window.exit_code, 2);
  EXPECT_NE(window.err.find("--window-cells given twice"), std::string::npos) << window.err;
  EXPECT_EQ(testing::ListDir(dir), std::vector<std::string>{"d.lmap"});
  // A flag given twice is still taken.
  EXPECT_EQ(RunCli({"encode", depot, "-o", dir + "/c.lmap", "--compact", "--compact"}).exit_code,
            0);
}

// A refusal over a limit names the option that raises it (the library's
// messages name only the limit), whichever command it comes through.
TEST(CliTest, LimitErrorsNameTheOptionThatRaisesThem) {
  const std::string dir = testing::MakeTempDir("cli_limit_option");
  const std::string map = testing::BundledMapsDir() + "/navtut/lse_arena.yaml";
  const std::string lmap = testing::SourceDir() + "/tests/data/lmap/lse_arena_lossy.lmap";
  const std::vector<std::vector<std::string>> cells = {
      {"info", lmap, "--max-cells", "100"},
      {"info", map, "--max-cells", "100"},
      {"decode", lmap, "-o", dir + "/o.yaml", "--max-cells", "100"},
      {"export", lmap, "-o", dir + "/o.csv", "--max-cells", "100"},
      {"encode", map, "-o", dir + "/o.lmap", "--max-cells", "100"},
      {"lines", lmap, "--max-cells", "100"},
      {"segment", lmap, "-o", dir + "/o.json", "--max-cells", "100"},
      {"plan", lmap, "--from", "1,1", "--to", "2,2", "--max-cells", "100"},
      {"eval", map, lmap, "--max-cells", "100"},
  };
  for (const std::vector<std::string>& argv : cells) {
    const CliResult r = RunCli(argv);
    SCOPED_TRACE(argv[0] + " " + argv[1] + ": " + r.err);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("limit of 100 cells (--max-cells N raises the limit)\n"),
              std::string::npos);
  }
  const CliResult bytes = RunCli({"decode", lmap, "-o", dir + "/o.yaml", "--max-file-bytes", "10"});
  EXPECT_EQ(bytes.exit_code, 2);
  EXPECT_NE(bytes.err.find("--max-file-bytes"), std::string::npos) << bytes.err;
  EXPECT_TRUE(testing::ListDir(dir).empty());
}

// plan, segment and lines put the map's name in quotes, as every other
// command does.
TEST(CliTest, ErrorsAboutAMapQuoteItsName) {
  const std::string dir = testing::MakeTempDir("cli_quoted_name");
  const std::string map = testing::BundledMapsDir() + "/navtut/lse_arena.yaml";
  const std::vector<std::vector<std::string>> commands = {
      {"plan", map, "--from", "100,100", "--to", "1,1"},
      {"segment", map, "-o", dir + "/s.json", "--pose", "100,100"},
      {"segment", map, "-o", dir + "/s.json", "--doors", "2,1"},
      {"lines", map, "--pose", "100,100"},
  };
  for (const std::vector<std::string>& argv : commands) {
    const CliResult r = RunCli(argv);
    SCOPED_TRACE(argv[0] + ": " + r.err);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_EQ(r.err.rfind("linemap " + argv[0] + ": '" + map + "': ", 0), 0u);
  }
}

}  // namespace
}  // namespace linemap
