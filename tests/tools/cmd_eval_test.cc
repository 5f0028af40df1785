// `linemap eval` through the built CLI: the map-reading options apply to the
// original only, and maps of different sizes are an error, not a perfect score.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "tests/testing/test_support.h"

namespace linemap {
namespace {

using testing::CliResult;
using testing::MakeTempDir;
using testing::RunCli;

std::string Arena() { return testing::BundledMapsDir() + "/navtut/lse_arena.yaml"; }

// The arena read with --negate, encoded losslessly and decoded: the decoded
// YAML says negate 0 and its PGM holds the negated map, so only the original
// may be read with --negate.
TEST(CmdEvalTest, MapOptionsApplyToTheOriginalOnly) {
  const std::string dir = MakeTempDir("eval_negate");
  ASSERT_EQ(
      RunCli({"encode", Arena(), "--negate", "--lossless", "-o", dir + "/neg.lmap"}).exit_code, 0);
  ASSERT_EQ(RunCli({"decode", dir + "/neg.lmap", "-o", dir + "/neg.yaml"}).exit_code, 0);
  for (const std::string& decoded : {dir + "/neg.yaml", dir + "/neg.lmap"}) {
    const CliResult r = RunCli({"eval", Arena(), decoded, "--negate", "--json"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("\"cells\":4800,\"cells_equal\":4800,"), std::string::npos)
        << decoded << ": " << r.out;
  }
  // --max-cells still limits both files.
  const CliResult limited =
      RunCli({"eval", Arena(), dir + "/neg.yaml", "--negate", "--max-cells", "4800"});
  EXPECT_EQ(limited.exit_code, 0) << limited.err;
}

TEST(CmdEvalTest, DifferentSizesAreAnError) {
  const std::string depot = testing::BundledMapsDir() + "/nav2/depot.yaml";
  const CliResult r = RunCli({"eval", depot, Arena()});
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  for (const char* part : {"depot.yaml", "604 x 307", "lse_arena.yaml", "80 x 60"}) {
    EXPECT_NE(r.err.find(part), std::string::npos) << part << ": " << r.err;
  }
  EXPECT_EQ(RunCli({"eval", Arena(), depot, "--json"}).exit_code, 2);
}

}  // namespace
}  // namespace linemap
