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

// --max-cells (every command that reads a map, and the .lmap commands) and
// --max-file-bytes take 1 .. 2^64 - 1 in decimal digits: no exponent, fraction,
// sign or overflow (1e30 used to become "a limit of 0 cells", 1.5 became 1).
TEST(CliTest, LimitsAreWholeNumbers) {
  const std::string map = testing::BundledMapsDir() + "/navtut/lse_arena.yaml";
  const std::string lmap = testing::SourceDir() + "/tests/data/lmap/lse_arena_lossy.lmap";
  const std::string out = testing::MakeTempDir("cli_limits_parse") + "/o.yaml";
  const std::vector<std::vector<std::string>> commands = {
      {"info", map, "--max-cells"},
      {"info", lmap, "--max-cells"},
      {"decode", lmap, "-o", out, "--max-cells"},
      {"decode", lmap, "-o", out, "--max-file-bytes"},
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

TEST(CliTest, HelpShowsTheYawAsOptional) {
  for (const char* command : {"info", "encode", "lines", "segment", "plan", "eval"}) {
    const CliResult r = RunCli({command, "--help"});
    ASSERT_EQ(r.exit_code, 0) << command;
    EXPECT_NE(r.out.find("--origin X,Y[,YAW]"), std::string::npos) << command << ": " << r.out;
    EXPECT_EQ(r.out.find("X,Y,YAW"), std::string::npos) << command << ": " << r.out;
  }
}

}  // namespace
}  // namespace linemap
