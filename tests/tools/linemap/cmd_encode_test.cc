// `linemap encode` through the built CLI: the output may not be the input
// (nor the image its YAML names), must end in .lmap, and options that cannot
// hold are refused with one line naming the file, exit 2, nothing written.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "linemap/codec.h"
#include "linemap/map_io.h"
#include "tests/testing/test_support.h"

namespace linemap {
namespace {

namespace fs = std::filesystem;
using testing::CliResult;
using testing::ListDir;
using testing::MakeTempDir;
using testing::ReadFile;
using testing::RunCli;

// A copy of nav2's depot map (YAML naming depot.pgm beside it) in `dir`.
std::string CopyDepot(const std::string& dir) {
  const std::string src = testing::BundledMapsDir() + "/nav2/depot";
  fs::copy_file(src + ".yaml", dir + "/depot.yaml");
  fs::copy_file(src + ".pgm", dir + "/depot.pgm");
  return dir + "/depot.yaml";
}

// Runs `argv`, which must fail with exit 2 and one line on stderr holding
// every string of `named`, leaving `dir` exactly as it was.
void ExpectRefused(const std::vector<std::string>& argv, const std::string& dir,
                   const std::vector<std::string>& named) {
  std::vector<std::pair<std::string, std::string>> before;
  for (const std::string& name : ListDir(dir))
    before.emplace_back(name, ReadFile(dir + "/" + name));
  const CliResult r = RunCli(argv);
  std::string where;
  for (const std::string& a : argv) where += a + " ";
  where += "\nstderr: " + r.err;
  EXPECT_EQ(r.exit_code, 2) << where;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << where;
  for (const std::string& n : named)
    EXPECT_NE(r.err.find(n), std::string::npos) << n << ": " << where;
  std::vector<std::pair<std::string, std::string>> after;
  for (const std::string& name : ListDir(dir)) after.emplace_back(name, ReadFile(dir + "/" + name));
  EXPECT_TRUE(after == before) << "the folder changed: " << where;
}

TEST(CmdEncodeTest, RefusesToOverwriteTheInputMapOrItsImage) {
  const std::string dir = MakeTempDir("encode_self");
  const std::string yaml = CopyDepot(dir);
  const std::string pgm = dir + "/depot.pgm";
  // The reviewer's case: -o the image the YAML names (and the YAML itself).
  ExpectRefused({"encode", yaml, "-o", pgm}, dir, {"depot.pgm", ".lmap"});
  ExpectRefused({"encode", yaml, "-o", yaml}, dir, {"depot.yaml", ".lmap"});
  // Names ending in .lmap that are the image all the same: a hard link and
  // a symlink.
  ASSERT_EQ(::link(pgm.c_str(), (dir + "/hard.lmap").c_str()), 0);
  ASSERT_EQ(::symlink("depot.pgm", (dir + "/soft.lmap").c_str()), 0);
  ExpectRefused({"encode", yaml, "-o", dir + "/hard.lmap"}, dir, {"hard.lmap", "depot.pgm"});
  ExpectRefused({"encode", yaml, "-o", dir + "/soft.lmap"}, dir, {"soft.lmap", "depot.pgm"});
  // A bare image read through its .lmap-named hard link is the input map.
  ExpectRefused({"encode", pgm, "-o", dir + "/hard.lmap"}, dir, {"hard.lmap", "input map"});
  fs::remove(dir + "/hard.lmap");
  fs::remove(dir + "/soft.lmap");
  // An .lmap input re-encoded onto itself, by any spelling of its name.
  ASSERT_EQ(RunCli({"encode", yaml, "-o", dir + "/d.lmap"}).exit_code, 0);
  ExpectRefused({"encode", dir + "/d.lmap", "-o", dir + "/d.lmap"}, dir, {"d.lmap", "input map"});
  ExpectRefused({"encode", dir + "/d.lmap", "-o", dir + "/./d.lmap"}, dir, {"d.lmap"});
}

// --threads reads the same way in encode and decode: 0..4096, one message.
TEST(CmdEncodeTest, ThreadsOutOfRangeAreRefusedAlikeByEncodeAndDecode) {
  const std::string dir = MakeTempDir("encode_threads");
  const std::string map = testing::BundledMapsDir() + "/navtut/lse_arena.yaml";
  ASSERT_EQ(RunCli({"encode", map, "-o", dir + "/a.lmap"}).exit_code, 0);
  for (const char* threads : {"-1", "4097", "two", "1.5"}) {
    for (const std::vector<std::string>& args :
         {std::vector<std::string>{"encode", map, "-o", dir + "/b.lmap", "--threads", threads},
          std::vector<std::string>{"decode", dir + "/a.lmap", "-o", dir + "/b.yaml", "--threads",
                                   threads}}) {
      const CliResult r = RunCli(args);
      EXPECT_EQ(r.exit_code, 2) << args[0] << " " << threads;
      EXPECT_NE(r.err.find("--threads takes a whole number 0..4096 (0: one per core), not '" +
                           std::string(threads) + "'"),
                std::string::npos)
          << r.err;
    }
  }
  EXPECT_EQ(ListDir(dir), std::vector<std::string>{"a.lmap"});
}

TEST(CmdEncodeTest, OutputNameMustEndInLmap) {
  const std::string dir = MakeTempDir("encode_suffix");
  const std::string yaml = CopyDepot(dir);
  ExpectRefused({"encode", yaml, "-o", dir + "/out.bin"}, dir, {"out.bin", "must end in .lmap"});
  ExpectRefused({"encode", yaml, "-o", dir + "/lmap"}, dir, {"lmap"});
  const CliResult upper = RunCli({"encode", yaml, "-o", dir + "/OUT.LMAP"});
  EXPECT_EQ(upper.exit_code, 0) << upper.err;
  EXPECT_TRUE(testing::FileExists(dir + "/OUT.LMAP"));
}

TEST(CmdEncodeTest, WritesThroughACurrentMapSymlinkAndRefusesReadOnlyFiles) {
  const std::string dir = MakeTempDir("encode_link");
  const std::string yaml = CopyDepot(dir);
  testing::WriteFile(dir + "/v1.lmap", "old");
  ASSERT_EQ(::symlink("v1.lmap", (dir + "/current.lmap").c_str()), 0);
  const CliResult r = RunCli({"encode", yaml, "-o", dir + "/current.lmap"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::is_symlink(dir + "/current.lmap"));
  EXPECT_EQ(ReadFile(dir + "/v1.lmap").substr(1, 4), "LMAP");
  // A read-only target is left alone: refused before the encode as an
  // output that cannot be written at all (exit 2, as a directory), one line.
  testing::WriteFile(dir + "/ro.lmap", "read-only map");
  ASSERT_EQ(::chmod((dir + "/ro.lmap").c_str(), 0444), 0);
  const CliResult ro = RunCli({"encode", yaml, "-o", dir + "/ro.lmap"});
  EXPECT_EQ(ro.exit_code, 2) << ro.err;
  EXPECT_NE(ro.err.find("ro.lmap"), std::string::npos) << ro.err;
  EXPECT_NE(ro.err.find("read-only"), std::string::npos) << ro.err;
  EXPECT_EQ(ReadFile(dir + "/ro.lmap"), "read-only map");
  ::chmod((dir + "/ro.lmap").c_str(), 0644);
}

// The former lossy 1.0 file is no longer written: --lossy says what
// replaced it, and its options are unknown. --lossless names the default,
// --tolerance 0, and gives its bytes.
TEST(CmdEncodeTest, LossyIsRemovedAndLosslessIsToleranceZero) {
  const std::string dir = MakeTempDir("encode_modes");
  const std::string yaml = CopyDepot(dir);
  ExpectRefused({"encode", yaml, "-o", dir + "/x.lmap", "--lossy"}, dir,
                {"--lossy", "removed", "--tolerance T"});
  ExpectRefused({"encode", yaml, "-o", dir + "/x.lmap", "--tolerance", "1", "--lossy"}, dir,
                {"--lossy", "removed"});
  for (const char* option : {"--simplify-free", "--rooms", "--no-segments"}) {
    ExpectRefused({"encode", yaml, "-o", dir + "/x.lmap", option}, dir, {"unknown option", option});
  }
  ExpectRefused({"encode", yaml, "-o", dir + "/x.lmap", "--lossless", "--tolerance", "2"}, dir,
                {"--lossless", "--tolerance"});
  ASSERT_EQ(RunCli({"encode", yaml, "-o", dir + "/default.lmap", "--no-sync"}).exit_code, 0);
  for (const char* exact : {"--lossless", "--tolerance=0"}) {
    const CliResult r = RunCli({"encode", yaml, "-o", dir + "/exact.lmap", exact, "--no-sync"});
    ASSERT_EQ(r.exit_code, 0) << exact << ": " << r.err;
    EXPECT_EQ(ReadFile(dir + "/exact.lmap"), ReadFile(dir + "/default.lmap")) << exact;
  }
  const CliResult both =
      RunCli({"encode", yaml, "-o", dir + "/exact.lmap", "--lossless", "--tolerance", "0"});
  EXPECT_EQ(both.exit_code, 0) << both.err;
  EXPECT_NE(RunCli({"info", dir + "/default.lmap"}).out.find("version 2."), std::string::npos);
}

// --max-tolerance-cells bounds the maps saved within a tolerance (depot has
// 185,428 cells): over it, one line naming the map, its size and the
// option, exit 2, nothing written; 0 lifts it.
TEST(CmdEncodeTest, ToleranceOverTheCellLimitIsRefused) {
  const std::string dir = MakeTempDir("encode_tolerance_limit");
  const std::string yaml = CopyDepot(dir);
  ExpectRefused(
      {"encode", yaml, "-o", dir + "/x.lmap", "--tolerance", "1", "--max-tolerance-cells", "1000"},
      dir, {"depot.yaml", "185428 cells", "--max-tolerance-cells"});
  const CliResult r = RunCli({"encode", yaml, "-o", dir + "/x.lmap", "--tolerance", "1",
                              "--max-tolerance-cells", "0", "--no-sync"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
}

// --pose must fall on the map; its lower edge (0,0 with origin 0,0) is on it.
TEST(CmdEncodeTest, PoseOffTheMapIsRefused) {
  const std::string dir = MakeTempDir("encode_pose");
  const std::string yaml = CopyDepot(dir);  // 604 x 307 cells at 0.05 m, origin 0,0
  ExpectRefused({"encode", yaml, "-o", dir + "/x.lmap", "--pose", "500,5"}, dir,
                {"depot.yaml", "outside the map", "500.000,5.000"});
  ExpectRefused({"encode", yaml, "-o", dir + "/x.lmap", "--pose", "-0.01,5,1.5"}, dir,
                {"depot.yaml", "outside the map"});
  ExpectRefused({"encode", yaml, "-o", dir + "/x.lmap", "--pose", "30.2,5"}, dir,
                {"depot.yaml", "outside the map"});
  // An all-free map: the corner on the lower edge is its cell (0, 0).
  std::string pgm = "P5\n40 20\n255\n" + std::string(40 * 20, '\xfe');
  testing::WriteFile(dir + "/free.pgm", pgm);
  for (const char* pose : {"0,0", "0,0,1.57", "1.99,0.99"}) {
    const CliResult r =
        RunCli({"encode", dir + "/free.pgm", "-o", dir + "/f.lmap", "--pose", pose});
    EXPECT_EQ(r.exit_code, 0) << pose << ": " << r.err;
  }
}

// `exact` in the JSON says whether the file decodes to the map, which the
// test checks by decoding it: within a tolerance depot is simplified, while
// lse_arena (a clean 80 x 60 arena) gains nothing and keeps its exact file.
TEST(CmdEncodeTest, JsonSaysWhetherAToleranceFileIsExact) {
  const std::string dir = MakeTempDir("encode_exact");
  const std::string depot = CopyDepot(dir);
  const std::string arena = testing::BundledMapsDir() + "/navtut/lse_arena.yaml";
  for (const auto& [map, t] :
       std::vector<std::pair<std::string, std::string>>{{depot, "1"}, {arena, "4"}, {depot, "0"}}) {
    const std::string out = dir + "/t" + t + ".lmap";
    const CliResult r = RunCli({"encode", map, "-o", out, "--tolerance", t, "--json"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    StatusOr<Grid> decoded = LoadLmap(out);
    StatusOr<Grid> original = LoadRosMap(map);
    ASSERT_TRUE(decoded.ok() && original.ok()) << map;
    const bool decodes_exactly = decoded->cells() == original->cells();
    const bool says_exact = r.out.find("\"exact\":true") != std::string::npos;
    EXPECT_EQ(says_exact, decodes_exactly) << map << " T = " << t << ": " << r.out;
    EXPECT_EQ(says_exact, t != "1") << map << " T = " << t;
    // The T the file keeps its guarantees at, or null for an exact file.
    const std::string named = says_exact ? "null" : t;
    EXPECT_NE(r.out.find("\"tolerance_cells\":" + named + ","), std::string::npos) << r.out;
  }
  const CliResult text = RunCli({"encode", depot, "-o", dir + "/t2.lmap", "--tolerance", "2"});
  EXPECT_NE(
      text.out.find(" bytes (within a tolerance of 2 cells, with walls, rooms and furniture)\n"),
      std::string::npos)
      << text.out;
  const CliResult raster =
      RunCli({"encode", depot, "-o", dir + "/r1.lmap", "--tolerance", "1", "--raster-only"});
  EXPECT_NE(raster.out.find(" bytes (within a tolerance of 1 cell, cells only)\n"),
            std::string::npos)
      << raster.out;
}

// An .lmap saved again (to make it --compact, say) keeps what its metadata
// says: a file saved within 2 cells, copied exactly, still names T = 2
// (its cells are not the robot's map: checked against the original, only
// the guarantees within 2 cells hold), and its creator and time stay. It
// cannot be simplified again: the guarantees against the original would not
// add up.
TEST(CmdEncodeTest, AnLmapSavedAgainKeepsItsToleranceAndMetadata) {
  const std::string dir = MakeTempDir("encode_again");
  const std::string depot = CopyDepot(dir);
  ASSERT_EQ(RunCli({"encode", depot, "-o", dir + "/t2.lmap", "--tolerance", "2", "--metadata",
                    "--time", "2026-01-01T00:00:00Z"})
                .exit_code,
            0);
  const CliResult again =
      RunCli({"encode", dir + "/t2.lmap", "-o", dir + "/copy.lmap", "--compact", "--json"});
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_NE(again.out.find("\"exact\":true,\"tolerance_cells\":2,"), std::string::npos)
      << again.out;
  StatusOr<LmapContents> copy = LoadLmapContents(dir + "/copy.lmap");
  StatusOr<Grid> simplified = LoadLmap(dir + "/t2.lmap");
  ASSERT_TRUE(copy.ok() && simplified.ok());
  EXPECT_EQ(copy->grid.cells(), simplified->cells());
  EXPECT_FALSE(copy->lossless);
  EXPECT_EQ(ToleranceCellsOf(copy->major, copy->lossless, copy->metadata), 2);
  const auto has = [&copy](const std::string& key, const std::string& value) {
    return std::find(copy->metadata.begin(), copy->metadata.end(),
                     std::pair<std::string, std::string>{key, value}) != copy->metadata.end();
  };
  EXPECT_TRUE(has("time", "2026-01-01T00:00:00Z"));
  EXPECT_TRUE(has("frame_id", "map"));
  const CliResult text = RunCli({"encode", dir + "/t2.lmap", "-o", dir + "/copy2.lmap"});
  EXPECT_NE(text.out.find("(exact copy of a map saved within a tolerance of 2 cells, which it "
                          "names, with walls, rooms and furniture)\n"),
            std::string::npos)
      << text.out;
  EXPECT_EQ(RunCli({"eval", depot, dir + "/copy.lmap", "--check"}).exit_code, 0);
  const CliResult twice =
      RunCli({"encode", dir + "/t2.lmap", "-o", dir + "/t3.lmap", "--tolerance", "1"});
  EXPECT_EQ(twice.exit_code, 2);
  EXPECT_NE(twice.err.find("was saved within a tolerance of 2 cells"), std::string::npos)
      << twice.err;
  // A file simplified without naming its T (written before files named it,
  // or a lossy 1.0 file) cannot be copied as exact, nor said to keep a T.
  for (const char* old : {"willow_v2_2_tolerance_1.lmap", "lse_arena_lossy.lmap"}) {
    const CliResult r = RunCli(
        {"encode", testing::SourceDir() + "/tests/data/lmap/" + old, "-o", dir + "/old.lmap"});
    EXPECT_EQ(r.exit_code, 2) << old;
    EXPECT_NE(r.err.find("a copy could not say which guarantees hold"), std::string::npos) << r.err;
    EXPECT_FALSE(testing::FileExists(dir + "/old.lmap"));
  }
  // An exact file saved again is exact and names no T.
  ASSERT_EQ(RunCli({"encode", depot, "-o", dir + "/exact.lmap"}).exit_code, 0);
  const CliResult exact =
      RunCli({"encode", dir + "/exact.lmap", "-o", dir + "/exact2.lmap", "--json"});
  EXPECT_NE(exact.out.find("\"exact\":true,\"tolerance_cells\":null,"), std::string::npos)
      << exact.out;
}

// --compact writes an exact version 2.3 file no larger than the default
// one (each tile keeps the smallest of more codings).
TEST(CmdEncodeTest, CompactFileIsExactVersionTwoThreeAndNoLarger) {
  const std::string dir = MakeTempDir("encode_compact");
  const std::string yaml = CopyDepot(dir);
  ASSERT_EQ(RunCli({"encode", yaml, "-o", dir + "/d.lmap"}).exit_code, 0);
  const CliResult r = RunCli({"encode", yaml, "-o", dir + "/c.lmap", "--compact"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(RunCli({"info", dir + "/c.lmap"}).out.find("version 2.3"), std::string::npos);
  StatusOr<Grid> decoded = LoadLmap(dir + "/c.lmap");
  StatusOr<Grid> original = LoadRosMap(yaml);
  ASSERT_TRUE(decoded.ok() && original.ok());
  EXPECT_EQ(*decoded, *original);
  EXPECT_LT(ReadFile(dir + "/c.lmap").size(), ReadFile(dir + "/d.lmap").size());
}

// Without the PNG ratio (--no-png-ratio, or a map above 2^26 cells) an
// exact file is coded as the image is read (SaveRosMapAsLmap): the bytes
// are those of the loaded map's file, and --json says the same.
TEST(CmdEncodeTest, FileCodedAsTheImageIsReadIsTheLoadedMapsFile) {
  const std::string dir = MakeTempDir("encode_rows");
  StatusOr<Grid> depot = LoadRosMap(CopyDepot(dir));
  ASSERT_TRUE(depot.ok());
  // 4300 x 620 cells: three layer sections, read a block row at a time.
  const Grid grid = testing::TiledMap(*depot, 4300, 620);
  ASSERT_TRUE(SaveRosMap(dir + "/wide.yaml", grid, Durability::kUnsynced).ok());
  const CliResult rows =
      RunCli({"encode", dir + "/wide.yaml", "-o", dir + "/rows.lmap", "--no-png-ratio", "--json"});
  ASSERT_EQ(rows.exit_code, 0) << rows.err;
  EXPECT_NE(rows.out.find("\"cells\":2666000"), std::string::npos) << rows.out;
  const CliResult loaded = RunCli({"encode", dir + "/wide.yaml", "-o", dir + "/grid.lmap"});
  ASSERT_EQ(loaded.exit_code, 0) << loaded.err;
  EXPECT_NE(loaded.out.find("png-9:"), std::string::npos) << loaded.out;
  EXPECT_EQ(ReadFile(dir + "/rows.lmap"), ReadFile(dir + "/grid.lmap"));
  StatusOr<Grid> decoded = LoadLmap(dir + "/rows.lmap");
  ASSERT_TRUE(decoded.ok());
  EXPECT_EQ(decoded->cells(), grid.cells());
}

TEST(CmdEncodeTest, HelpShowsTheOptionalYaw) {
  const CliResult r = RunCli({"encode", "--help"});
  ASSERT_EQ(r.exit_code, 0);
  EXPECT_NE(r.out.find("--origin X,Y[,YAW]"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("[--pose X,Y[,YAW]]"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("[--tolerance T]"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("--lossy"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("X,Y,YAW"), std::string::npos) << r.out;
}

// An ISO 8601 time (--time takes no other text) whose second has a
// fraction of `n` digits that deflate cannot shrink much (a fixed
// pseudo-random sequence), to grow the file byte by byte.
std::string Filler(int n) {
  std::string text = "2024-05-01T12:00:00.";
  std::uint32_t state = 12345;
  for (int i = 0; i < n; ++i) {
    state = state * 1103515245u + 12345u;
    text += static_cast<char>('0' + (state >> 16) % 10);
  }
  return text;
}

// The ratio's words within half a percent of 1, where "%.2fx" printed
// "1.00x smaller" for 0.9978. Depot's file is some 2 % under its PNG; a
// --time text of the right length brings it to 5 bytes under, then 5 over.
TEST(CmdEncodeTest, RatioNearOneIsNotPrintedAsOneX) {
  const std::string dir = MakeTempDir("encode_ratio_near_one");
  const std::string yaml = CopyDepot(dir);
  const auto run = [&](int n) {
    return RunCli({"encode", yaml, "-o", dir + "/t.lmap", "--no-sync", "--time", Filler(n)});
  };
  const CliResult probe = run(1);
  ASSERT_EQ(probe.exit_code, 0) << probe.err;
  const auto figure = [](const std::string& out, const std::string& before) {
    const std::size_t at = out.find(before);
    return at == std::string::npos ? -1L : std::stol(out.substr(at + before.size()));
  };
  const long bytes = figure(probe.out, "t.lmap, ");
  const long png = figure(probe.out, "png-9:   ");
  ASSERT_GT(bytes, 0) << probe.out;
  ASSERT_GT(png, bytes + 5) << probe.out;
  for (const long delta : {-5L, 5L}) {
    SCOPED_TRACE(delta);
    bool found = false;
    // One more character of --time, one more byte (about: the chunk's
    // length fields may grow too).
    const int target = static_cast<int>(1 + png + delta - bytes);
    char words[48];
    std::snprintf(words, sizeof(words), "(%.2f %% %s)", 100.0 * 5 / static_cast<double>(png),
                  delta < 0 ? "smaller" : "larger");
    for (int n = target - 3; n <= target + 3 && !found; ++n) {
      const CliResult r = run(n);
      ASSERT_EQ(r.exit_code, 0) << r.err;
      if (figure(r.out, "t.lmap, ") != png + delta) continue;
      found = true;
      EXPECT_EQ(r.out.find("1.00x"), std::string::npos) << r.out;
      EXPECT_NE(r.out.find(words), std::string::npos) << words << "\n" << r.out;
    }
    EXPECT_TRUE(found) << "no --time length gave " << png + delta << " bytes";
  }
}

// The format's `time` is ISO 8601 text: a control character (a newline
// would split `info`'s one-field-per-line output) is refused, exit 2.
TEST(CmdEncodeTest, TimeWithAControlCharacterIsRefused) {
  const std::string dir = MakeTempDir("encode_time_control");
  const std::string yaml = CopyDepot(dir);
  for (const std::string& time : {std::string("a\nb"), std::string("2024\t01"), std::string("x\r"),
                                  std::string("e\x1b[31m"), std::string("del\x7f")}) {
    ExpectRefused({"encode", yaml, "-o", dir + "/x.lmap", "--time", time}, dir,
                  {"--time", "control character"});
  }
  const CliResult ok =
      RunCli({"encode", yaml, "-o", dir + "/x.lmap", "--time", "2024-05-01T12:00:00Z"});
  EXPECT_EQ(ok.exit_code, 0) << ok.err;
}

// Nor is a text that is no ISO 8601 date or time (a reader of the `time`
// key parses it), while the forms map savers write pass.
TEST(CmdEncodeTest, TimeThatIsNotIso8601IsRefused) {
  const std::string dir = MakeTempDir("encode_time_iso");
  const std::string yaml = CopyDepot(dir);
  for (const char* time : {"yesterday", "2026-13-01", "2026-01-01 12:00", "2026-1-1", "12:00",
                           "2026-01-01T25:00", "2026-01-01T12:00:00+2", "\xff\xfe", "2026-02-29",
                           "2100-02-29", "2026-04-31", "2026-02-30T12:00Z"}) {
    ExpectRefused({"encode", yaml, "-o", dir + "/x.lmap", "--time", time}, dir,
                  {"--time", "is not an ISO 8601 date or date-time"});
  }
  for (const char* time : {"2026-01-01", "2026-01-01T12:00", "2026-01-01T12:00:00Z",
                           "2026-01-01T12:00:00.125+02:00", "2026-01-01T12:00:00-0500",
                           "2026-01-01T23:59:60Z", "2024-02-29", "2000-02-29", "2026-12-31"}) {
    EXPECT_EQ(RunCli({"encode", yaml, "-o", dir + "/x.lmap", "--time", time}).exit_code, 0) << time;
  }
}

}  // namespace
}  // namespace linemap
