// `linemap bench` end to end on a one-map corpus (fast: no scaling table, no
// memory forks, one timed run).
#include <gtest/gtest.h>

#include <filesystem>

#include "tests/testing/test_support.h"

namespace linemap::testing {
namespace {

std::string OneMapCorpus() {
  const std::string dir = MakeTempDir("bench-cli-corpus");
  for (const char* file : {"lse_arena.yaml", "lse_arena.pgm"}) {
    std::filesystem::copy_file(BundledMapsDir() + "/navtut/" + file, dir + "/" + file);
  }
  return dir;
}

TEST(BenchCliTest, WritesCsvMarkdownAndSvgForAOneMapCorpus) {
  const std::string corpus = OneMapCorpus();
  const std::string out = MakeTempDir("bench-cli-out");
  const CliResult r =
      RunCli({"bench", corpus, "--scaling-max", "0", "--no-memory", "--repeats", "1", "--csv",
              out + "/b.csv", "--md", out + "/b.md", "--svg-dir", out + "/svg"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("Medians over the corpus"), std::string::npos);
  EXPECT_EQ(r.err, "");  // no progress bar when stderr is not a terminal
  const std::string csv = ReadFile(out + "/b.csv");
  // The arena is 80 x 60 cells (tests/data/maps/MANIFEST.tsv).
  EXPECT_EQ(csv.rfind("map,path,", 0), 0u);
  EXPECT_NE(csv.find("\nlse_arena,"), std::string::npos);
  EXPECT_NE(csv.find(",4800.000000,"), std::string::npos);
  EXPECT_NE(ReadFile(out + "/b.md").find("| map |"), std::string::npos);
  EXPECT_TRUE(FileExists(out + "/svg/lse_arena.svg"));
  EXPECT_TRUE(FileExists(out + "/svg/summary.svg"));
}

TEST(BenchCliTest, ScalingTableHasARowPerSizeAndTheSpread) {
  const CliResult r = RunCli({"bench", OneMapCorpus(), "--scaling-max", "1", "--no-memory",
                              "--no-jbig", "--repeats", "1"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::size_t table = r.out.find("== Scaling ==");
  ASSERT_NE(table, std::string::npos) << r.out;
  // The 1-Mcell row has its 9 interleaved runs, then the spread row.
  EXPECT_NE(r.out.find("\n1            9 ", table), std::string::npos) << r.out.substr(table);
  EXPECT_NE(r.out.find("\nspread %", table), std::string::npos);
}

TEST(BenchCliTest, BadUsageExitsTwo) {
  EXPECT_EQ(RunCli({"bench", "/nonexistent/linemap-corpus", "--scaling-max", "0"}).exit_code, 2);
  EXPECT_EQ(RunCli({"bench", "--repeats", "0"}).exit_code, 2);
  EXPECT_EQ(RunCli({"bench", "--no-such-option"}).exit_code, 2);
}

}  // namespace
}  // namespace linemap::testing
