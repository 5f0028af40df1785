// `linemap eval` through the built CLI: the map-reading options apply to the
// original only, and maps of different sizes are an error, not a perfect score.
#include <gtest/gtest.h>

#include <algorithm>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

#include "format/container.h"
#include "format/file_io.h"
#include "linemap/grid.h"
#include "linemap/map_io.h"
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

// The whole number after "key": in a JSON object printed on one line; -1
// when the key is not there.
long JsonCount(const std::string& json, const std::string& key) {
  const std::string quoted = "\"" + key + "\":";
  const std::size_t at = json.find(quoted);
  return at == std::string::npos ? -1 : std::stol(json.substr(at + quoted.size()));
}

// Each of `parts` ("key":value, as printed) is in the one-line JSON `json`.
void ExpectJsonHas(const std::string& json, std::initializer_list<const char*> parts) {
  for (const char* part : parts) {
    EXPECT_NE(json.find(part), std::string::npos) << part << " in " << json;
  }
}

// A 20 x 10 room (occupied border, free inside) with one obstacle cell at
// (obstacle_col, 5), saved as a ROS map.
std::string SaveRoom(const std::string& dir, const std::string& name, int obstacle_col) {
  Grid g(20, 10, Cell::kFree);
  for (int c = 0; c < 20; ++c) {
    g.set(c, 0, Cell::kOccupied);
    g.set(c, 9, Cell::kOccupied);
  }
  for (int r = 0; r < 10; ++r) {
    g.set(0, r, Cell::kOccupied);
    g.set(19, r, Cell::kOccupied);
  }
  g.set(obstacle_col, 5, Cell::kOccupied);
  const std::string path = dir + "/" + name + ".yaml";
  EXPECT_TRUE(SaveRosMap(path, g).ok());
  return path;
}

// The obstacle moved by 3 cells: Hausdorff 3 both ways (the border is
// further), and of the 53 wall-surface cells (18 + 18 + 8 + 8 along the
// border, corners excluded, and the obstacle) the obstacle alone has no
// decoded obstacle within 2. Within 3 cells every distance holds, but the
// plans do not: from (9, 5) to (11, 5) the original goes round the obstacle
// in 4 steps, the decode straight in 2.
TEST(CmdEvalTest, ToleranceReportsTheGuaranteesFigures) {
  const std::string dir = MakeTempDir("eval_tolerance");
  const std::string original = SaveRoom(dir, "a", 10);
  const std::string moved = SaveRoom(dir, "b", 13);
  const CliResult r = RunCli({"eval", original, moved, "--tolerance", "2", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ExpectJsonHas(
      r.out, {"\"hausdorff_original_to_decoded\":3", "\"hausdorff_decoded_to_original\":3",
              "\"wall_surface_cells\":53", "\"wall_surface_within_t\":52",
              "\"free_moved_beyond_t\":0", "\"tolerance_leaks\":0", "\"tolerance_holds\":false"});
  const CliResult same = RunCli({"eval", original, original, "--tolerance", "1"});
  ASSERT_EQ(same.exit_code, 0) << same.err;
  EXPECT_NE(same.out.find("guarantees:         hold"), std::string::npos) << same.out;
  const CliResult within = RunCli({"eval", original, moved, "--tolerance", "3", "--json"});
  ASSERT_EQ(within.exit_code, 0) << within.err;
  ExpectJsonHas(within.out,
                {"\"hausdorff_original_to_decoded\":3", "\"wall_surface_within_t\":53",
                 "\"free_moved_beyond_t\":0", "\"free_lost_beyond_t\":0", "\"tolerance_leaks\":0",
                 "\"tolerance_splits\":0", "\"tolerance_holds\":false"});
  EXPECT_GT(JsonCount(within.out, "local_plan_disagreements"), 0) << within.out;
  EXPECT_GT(JsonCount(within.out, "plan_disagreements"), 0) << within.out;
}

// Without --tolerance an .lmap file saved within one is checked at the T
// its metadata names, the figures being those --tolerance T prints; an
// exact file gets no tolerance check.
TEST(CmdEvalTest, ToleranceFileIsCheckedAtTheTItNames) {
  const std::string dir = MakeTempDir("eval_file_tolerance");
  const std::string depot = testing::BundledMapsDir() + "/nav2/depot.yaml";
  ASSERT_EQ(RunCli({"encode", depot, "-o", dir + "/t2.lmap", "--tolerance", "2"}).exit_code, 0);
  ASSERT_EQ(RunCli({"encode", depot, "-o", dir + "/exact.lmap"}).exit_code, 0);
  const CliResult named = RunCli({"eval", depot, dir + "/t2.lmap"});
  ASSERT_EQ(named.exit_code, 0) << named.err;
  EXPECT_NE(named.out.find("tolerance named by the file's metadata\n"), std::string::npos)
      << named.out;
  const CliResult given = RunCli({"eval", depot, dir + "/t2.lmap", "--tolerance", "2"});
  const std::string report = given.out.substr(given.out.find("tolerance:"));
  EXPECT_NE(report.find("tolerance:            2 cells"), std::string::npos) << given.out;
  EXPECT_NE(named.out.find(report), std::string::npos) << named.out << "\n---\n" << report;
  // Checked at another T: the file's own is said too.
  const CliResult other = RunCli({"eval", depot, dir + "/t2.lmap", "--tolerance", "1", "--json"});
  EXPECT_NE(other.out.find("\"tolerance_named_cells\":2"), std::string::npos) << other.out;
  EXPECT_NE(RunCli({"eval", depot, dir + "/t2.lmap", "--tolerance", "1"})
                .out.find("the file names 2 cells; checked at 1 cell (--tolerance)"),
            std::string::npos);
  // The files the other way round: the "original" was saved within 2 cells.
  const CliResult swapped = RunCli({"eval", dir + "/t2.lmap", depot});
  ASSERT_EQ(swapped.exit_code, 0) << swapped.err;
  EXPECT_NE(swapped.err.find("ORIGINAL '" + dir +
                             "/t2.lmap' was saved within a tolerance of 2 "
                             "cells: it is not the original map"),
            std::string::npos)
      << swapped.err;
  EXPECT_EQ(RunCli({"eval", depot, dir + "/t2.lmap"}).err, "");
  const CliResult json = RunCli({"eval", depot, dir + "/t2.lmap", "--json"});
  EXPECT_NE(json.out.find("\"tolerance_holds\":true"), std::string::npos) << json.out;
  EXPECT_NE(json.out.find("\"tolerance_from_file\":true"), std::string::npos) << json.out;
  const CliResult exact = RunCli({"eval", depot, dir + "/exact.lmap"});
  EXPECT_EQ(exact.out.find("tolerance"), std::string::npos) << exact.out;
  // A file naming a T the checks do not take (another writer's) says so.
  StatusOr<std::vector<std::uint8_t>> bytes = ReadFileBytes(dir + "/t2.lmap", 1 << 20);
  ASSERT_TRUE(bytes.ok());
  StatusOr<ContainerView> view = ParseContainer(*bytes, 1 << 20);
  ASSERT_TRUE(view.ok());
  ContainerWriter out(view->major, view->minor);
  for (const Chunk& chunk : view->chunks) {
    std::vector<std::uint8_t> payload(chunk.payload, chunk.payload + chunk.size);
    if (chunk.type == "meta")
      payload = {0, 1, 9, 't', 'o', 'l', 'e', 'r', 'a', 'n', 'c', 'e', 1, '7'};
    if (chunk.type != "LEND") out.AddChunk(chunk.type, payload);
  }
  const std::vector<std::uint8_t> seven = out.Finish();
  ASSERT_TRUE(
      WriteFileAtomic(dir + "/t7.lmap",
                      std::string_view(reinterpret_cast<const char*>(seven.data()), seven.size()))
          .ok());
  const CliResult beyond = RunCli({"eval", depot, dir + "/t7.lmap"});
  ASSERT_EQ(beyond.exit_code, 0) << beyond.err;
  EXPECT_NE(beyond.out.find("tolerance:            the file names 7 cells; not checked (eval "
                            "checks T = 0..4"),
            std::string::npos)
      << beyond.out;
  const CliResult beyond_json = RunCli({"eval", depot, dir + "/t7.lmap", "--json"});
  EXPECT_NE(beyond_json.out.find("\"tolerance_named_cells\":7"), std::string::npos)
      << beyond_json.out;
  EXPECT_EQ(beyond_json.out.find("tolerance_holds"), std::string::npos) << beyond_json.out;
  // --check: the file checked at its T keeps its promise; the one whose T
  // is not checked is held to exactness, which it breaks.
  const CliResult checked = RunCli({"eval", depot, dir + "/t2.lmap", "--check"});
  EXPECT_EQ(checked.exit_code, 0) << checked.out;
  EXPECT_NE(checked.out.find("check:                PASS (the guarantees within 2 cells hold)\n"),
            std::string::npos)
      << checked.out;
  const CliResult unchecked = RunCli({"eval", depot, dir + "/t7.lmap", "--check"});
  EXPECT_EQ(unchecked.exit_code, 1) << unchecked.out;
  EXPECT_NE(unchecked.out.find("check:                FAIL ("), std::string::npos) << unchecked.out;
  EXPECT_NE(unchecked.out.find(
                "no tolerance was checked (an exact copy was expected; --tolerance T checks the "
                "guarantees within T))\n"),
            std::string::npos)
      << unchecked.out;
  EXPECT_EQ(RunCli({"eval", depot, dir + "/exact.lmap", "--check"}).exit_code, 0);
}

// --check turns the verdict into the exit status (1: the promise is
// broken), on the room whose obstacle moves by 3 cells: 2 cells differ,
// and within 2 cells the obstacle's surface is lost (see above). Without
// --check the status is 0 whatever the figures.
TEST(CmdEvalTest, CheckExitsOneWhenTheSecondMapBreaksItsPromise) {
  const std::string dir = MakeTempDir("eval_check");
  const std::string original = SaveRoom(dir, "a", 10);
  const std::string moved = SaveRoom(dir, "b", 13);
  EXPECT_EQ(RunCli({"eval", original, moved}).exit_code, 0);
  const CliResult exact = RunCli({"eval", original, moved, "--check"});
  EXPECT_EQ(exact.exit_code, 1) << exact.err;
  EXPECT_NE(
      exact.out.find("check:                FAIL (2 cells differ and no tolerance was "
                     "checked (an exact copy was expected; --tolerance T checks the guarantees "
                     "within T))\n"),
      std::string::npos)
      << exact.out;
  const CliResult within = RunCli({"eval", original, moved, "--tolerance", "2", "--check"});
  EXPECT_EQ(within.exit_code, 1) << within.out;
  EXPECT_NE(within.out.find("FAIL (the guarantees within 2 cells are broken)"), std::string::npos)
      << within.out;
  const CliResult json = RunCli({"eval", original, moved, "--check", "--json"});
  EXPECT_EQ(json.exit_code, 1);
  ExpectJsonHas(json.out, {"\"check_passed\":false", "\"check\":\"2 cells differ"});
  const CliResult same = RunCli({"eval", original, original, "--check"});
  EXPECT_EQ(same.exit_code, 0) << same.out;
  EXPECT_NE(same.out.find("check:                PASS (every cell is equal)\n"), std::string::npos)
      << same.out;
  const CliResult same_json =
      RunCli({"eval", original, original, "--tolerance", "1", "--check", "--json"});
  EXPECT_EQ(same_json.exit_code, 0) << same_json.out;
  ExpectJsonHas(same_json.out, {"\"check_passed\":true"});
  // The same cells at another resolution: every wall elsewhere in metres.
  StatusOr<Grid> room = LoadRosMap(original);
  ASSERT_TRUE(room.ok());
  room->meta.resolution *= 2;
  ASSERT_TRUE(SaveRosMap(dir + "/coarse.yaml", *room).ok());
  const CliResult coarse = RunCli({"eval", original, dir + "/coarse.yaml", "--check"});
  EXPECT_EQ(coarse.exit_code, 1) << coarse.out;
  EXPECT_NE(coarse.out.find("same geometry:        NO (resolution 0.05 against 0.1 m/cell)\n"),
            std::string::npos)
      << coarse.out;
  EXPECT_NE(
      coarse.out.find("FAIL (the two maps' frames differ: resolution 0.05 against 0.1 m/cell)\n"),
      std::string::npos)
      << coarse.out;
}

TEST(CmdEvalTest, ToleranceOutsideTheRangeIsBadUsage) {
  const std::string dir = MakeTempDir("eval_tolerance_range");
  const std::string original = SaveRoom(dir, "a", 10);
  for (const std::string bad : {"5", "-1", "1.5", "two"}) {
    const CliResult r = RunCli({"eval", original, original, "--tolerance", bad});
    EXPECT_EQ(r.exit_code, 2) << bad;
    EXPECT_NE(r.err.find("0 to 4"), std::string::npos) << bad << ": " << r.err;
  }
}

}  // namespace
}  // namespace linemap
