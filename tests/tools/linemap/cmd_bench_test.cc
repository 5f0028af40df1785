// `linemap bench` end to end on a one-map corpus (fast: no scaling table, no
// memory forks, one timed run).
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
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

TEST(CmdBenchTest, WritesCsvMarkdownAndSvgForAOneMapCorpus) {
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
  // The .lmap columns are the 2.0 default, --raster-only and --compact
  // files (no 1.0 file: none is written any more), and the goals are printed.
  for (const char* column :
       {",lmap2_bytes,", ",lmap2_raster_bytes,", ",lmap2_compact_bytes,", ",lmap2_cells_wrong,",
        ",lmap2_covered_share,",
        // libpng's times, now taken in turn with the 2.0 file's
        ",png_encode_ms,", ",png_decode_ms,", ",lmap2_encode_ms,", ",lmap2_decode_ms,"}) {
    EXPECT_NE(csv.find(column), std::string::npos) << column;
  }
  EXPECT_EQ(csv.find("lmap_lossless_bytes"), std::string::npos);
  EXPECT_EQ(csv.find("lmap1_"), std::string::npos);
  EXPECT_NE(r.out.find("== .lmap 2.0 goals =="), std::string::npos);
  EXPECT_NE(ReadFile(out + "/b.md").find("| map |"), std::string::npos);
  EXPECT_TRUE(FileExists(out + "/svg/lse_arena.svg"));
  EXPECT_TRUE(FileExists(out + "/svg/summary.svg"));
}

TEST(CmdBenchTest, ScalingTableHasARowPerSizeAndTheSpread) {
  const CliResult r = RunCli({"bench", OneMapCorpus(), "--scaling-max", "1", "--no-memory",
                              "--no-jbig", "--repeats", "1"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::size_t table = r.out.find("== Scaling ==");
  ASSERT_NE(table, std::string::npos) << r.out;
  // The 1024 x 1024 row (1.0 Mcells: 1,048,576 cells) has its 9
  // interleaved samples, then the two spread rows.
  const std::size_t row = r.out.find("\n1024 x 1024 ", table);
  ASSERT_NE(row, std::string::npos) << r.out.substr(table);
  const std::size_t mcells = r.out.find_first_not_of(' ', row + 13);
  EXPECT_EQ(r.out.compare(mcells, 4, "1.0 "), 0) << r.out.substr(row, 80);
  const std::size_t runs = r.out.find_first_not_of(' ', mcells + 4);
  EXPECT_EQ(r.out.compare(runs, 2, "9 "), 0) << r.out.substr(row, 80);
  EXPECT_NE(r.out.find("\nspread % ", table), std::string::npos);
  EXPECT_NE(r.out.find("\nspread % of the fastest runs ", table), std::string::npos);
}

// Finds `tool` in the test's own PATH, or "".
std::string Which(const std::string& tool) {
  const char* path = std::getenv("PATH");
  std::string dirs = path ? path : "/usr/bin:/bin";
  std::size_t start = 0;
  while (start <= dirs.size()) {
    const std::size_t end = std::min(dirs.find(':', start), dirs.size());
    const std::string candidate = dirs.substr(start, end - start) + "/" + tool;
    if (end > start && ::access(candidate.c_str(), X_OK) == 0) return candidate;
    start = end + 1;
  }
  return "";
}

// With a PATH that has every comparator but cjxl, the bench still runs, says
// which program is missing and leaves the JPEG XL column out.
TEST(CmdBenchTest, AMissingAnchorProgramIsNamedAndItsColumnLeftOut) {
  const std::string bin = MakeTempDir("bench-cli-path");
  for (const char* tool : {"sh", "pnmtopng", "pbmtojbg", "cwebp", "dwebp"}) {
    const std::string found = Which(tool);
    if (!found.empty()) std::filesystem::create_symlink(found, bin + "/" + tool);
  }
  const char* old_path = std::getenv("PATH");
  const std::string saved = old_path ? old_path : "";
  ::setenv("PATH", bin.c_str(), 1);
  const std::string out = MakeTempDir("bench-cli-out");
  const CliResult r = RunCli({"bench", OneMapCorpus(), "--scaling-max", "0", "--no-memory",
                              "--repeats", "1", "--csv", out + "/b.csv"});
  ::setenv("PATH", saved.c_str(), 1);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("JPEG XL: cjxl not found in PATH (Debian package libjxl-tools)"),
            std::string::npos)
      << r.out;
  // The header row of the sizes table (its caption names every codec).
  const std::size_t header = r.out.find("\nmap ", r.out.find("== Sizes (bytes) =="));
  ASSERT_NE(header, std::string::npos);
  const std::string columns = r.out.substr(header, r.out.find('\n', header + 1) - header);
  EXPECT_NE(columns.find("PNG-9"), std::string::npos) << columns;
  EXPECT_EQ(columns.find("JPEG XL"), std::string::npos) << columns;
  EXPECT_EQ(ReadFile(out + "/b.csv").find("jxl_bytes"), std::string::npos);
}

TEST(CmdBenchTest, BadUsageExitsTwo) {
  EXPECT_EQ(RunCli({"bench", "/nonexistent/linemap-corpus", "--scaling-max", "0"}).exit_code, 2);
  EXPECT_EQ(RunCli({"bench", "--repeats", "0"}).exit_code, 2);
  EXPECT_EQ(RunCli({"bench", "--no-such-option"}).exit_code, 2);
}

// --help lists 0, 1, 4, 16, 64 or 282 Mcells; 3 used to be taken (and stop
// the table at 1). Refused before the corpus is read.
TEST(CmdBenchTest, ScalingMaxOutsideTheTableIsRefused) {
  const std::string corpus = OneMapCorpus();
  for (const char* value : {"3", "2", "5", "63", "65", "128", "270", "283", "-1", "x"}) {
    const CliResult r =
        RunCli({"bench", corpus, "--scaling-max", value, "--no-memory", "--repeats", "1"});
    EXPECT_EQ(r.exit_code, 2) << value;
    EXPECT_NE(r.err.find("--scaling-max must be 0 (skip), 1, 4, 16, 64 or 282, not '" +
                         std::string(value) + "'"),
              std::string::npos)
        << value << ": " << r.err;
    EXPECT_EQ(r.out, "") << value;
  }
}

}  // namespace
}  // namespace linemap::testing
