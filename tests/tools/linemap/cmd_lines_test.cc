// `linemap lines` end to end on a map written by the test.
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "linemap/grid.h"
#include "linemap/map_io.h"
#include "tests/codec/lines/test_maps.h"
#include "tests/testing/test_support.h"

namespace linemap {
namespace {

using testing::RunCli;

// Saves `grid` as dir/NAME.yaml (+ .pgm) and returns the YAML's path.
std::string SaveMap(const std::string& dir, const std::string& name, const Grid& grid) {
  const std::string yaml = dir + "/" + name + ".yaml";
  EXPECT_TRUE(SaveRosMap(yaml, grid).ok());
  return yaml;
}

// One wall along row 3, cols 2..17, at 0.1 m/cell with origin (1, 2).
std::string WriteWallMap(const std::string& dir) {
  Grid grid(20, 7, Cell::kFree);
  grid.meta.resolution = 0.1;
  grid.meta.origin = {1.0, 2.0, 0.0};
  testing::FillBox(&grid, 2, 3, 17, 3, Cell::kOccupied);
  return SaveMap(dir, "wall", grid);
}

TEST(CmdLinesTest, WritesSegmentsInMapMetres) {
  const std::string dir = testing::MakeTempDir("lines_cli_csv");
  const std::string yaml = WriteWallMap(dir);
  const testing::CliResult r =
      RunCli({"lines", yaml, "--method", "rmline", "-o", dir + "/lines.csv"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // x = 1 + (col + 0.5) * 0.1, y = 2 + (3 + 0.5) * 0.1.
  EXPECT_EQ(testing::ReadFile(dir + "/lines.csv"),
            "layer,x1,y1,x2,y2\nsegment,1.250000,2.350000,2.750000,2.350000\n");
  EXPECT_NE(r.out.find("lines:      1"), std::string::npos) << r.out;
}

TEST(CmdLinesTest, JsonHasTheFiveFigures) {
  const std::string dir = testing::MakeTempDir("lines_cli_json");
  const testing::CliResult r = RunCli({"lines", WriteWallMap(dir), "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* key : {"\"lines\":1,", "\"displ_cm\":0,", "\"displ_cells\":0,",
                          "\"displ_max_cells\":0,", "\"ms\":"}) {
    EXPECT_NE(r.out.find(key), std::string::npos) << key << " in " << r.out;
  }
}

TEST(CmdLinesTest, DefaultMethodIsLinemapAndReportsFurnitureCells) {
  const std::string dir = testing::MakeTempDir("lines_cli_default");
  const testing::CliResult r = RunCli({"lines", WriteWallMap(dir), "--epsilon", "1.5"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("furniture:  0 edge cells"), std::string::npos) << r.out;
  const testing::CliResult rm = RunCli({"lines", WriteWallMap(dir), "--method", "rmline"});
  ASSERT_EQ(rm.exit_code, 0) << rm.err;
  EXPECT_EQ(rm.out.find("furniture:"), std::string::npos) << rm.out;
}

// A wall rising one row every 4 columns (rows 0..2 + col / 4 filled, free
// above), at 0.05 m/cell.
std::string WriteStaircaseMap(const std::string& dir) {
  Grid grid(60, 20, Cell::kFree);
  for (int col = 0; col < 60; ++col) {
    testing::FillBox(&grid, col, 0, col, 2 + col / 4, Cell::kOccupied);
  }
  return SaveMap(dir, "stairs", grid);
}

TEST(CmdLinesTest, StraightWallsDrawsASlantedWallAsOneSegment) {
  const std::string dir = testing::MakeTempDir("lines_cli_steps");
  const std::string yaml = WriteStaircaseMap(dir);
  const testing::CliResult steps = RunCli({"lines", yaml, "--json"});
  const testing::CliResult straight = RunCli({"lines", yaml, "--json", "--straight-walls"});
  ASSERT_EQ(steps.exit_code, 0) << steps.err;
  ASSERT_EQ(straight.exit_code, 0) << straight.err;
  EXPECT_EQ(steps.out.find("\"lines\":1,"), std::string::npos) << steps.out;
  EXPECT_NE(straight.out.find("\"lines\":1,"), std::string::npos) << straight.out;
}

// Two rooms apart: a wall across row 4 of a 20 x 9 map (0.1 m/cell, origin
// (1, 2)), and in the upper room a short wall on row 7, cols 3..10.
std::string WriteTwoRoomMap(const std::string& dir) {
  Grid grid(20, 9, Cell::kFree);
  grid.meta.resolution = 0.1;
  grid.meta.origin = {1.0, 2.0, 0.0};
  testing::FillBox(&grid, 0, 4, 19, 4, Cell::kOccupied);
  testing::FillBox(&grid, 3, 7, 10, 7, Cell::kOccupied);
  return SaveMap(dir, "two_rooms", grid);
}

TEST(CmdLinesTest, PoseSelectsTheComponent) {
  const std::string dir = testing::MakeTempDir("lines_cli_pose");
  const std::string yaml = WriteTwoRoomMap(dir);
  // (1.35, 2.15) m is cell (3, 1), in the lower room: only the dividing
  // wall's 20 cells face it. (1.35, 2.85) m is cell (3, 8), in the upper
  // room, which also sees the short wall's 8 cells; so do both rooms
  // without a pose.
  for (const auto& [pose, figures] : std::vector<std::pair<std::string, std::string>>{
           {"1.35,2.15", "\"lines\":1,"}, {"1.35,2.85", "\"lines\":2,"}, {"", "\"lines\":2,"}}) {
    std::vector<std::string> argv = {"lines", yaml, "--json"};
    if (!pose.empty()) argv.insert(argv.end(), {"--pose", pose});
    const testing::CliResult r = RunCli(argv);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find(figures), std::string::npos) << pose << ": " << r.out;
    const std::string edges = pose == "1.35,2.15" ? "\"edge_cells\":20," : "\"edge_cells\":28,";
    EXPECT_NE(r.out.find(edges), std::string::npos) << pose << ": " << r.out;
  }
}

// A pose typed on a cell's lower edge is in that cell, as --room-at and
// --window take it: 2.4 m is the lower edge of row 4 (free, above the wall
// on row 3), though (2.4 - 2) / 0.1 - 0.5 is 3.4999999999999991 in doubles,
// which rounding put on the wall ("not on a free cell").
TEST(CmdLinesTest, PoseOnACellsLowerEdgeIsInThatCell) {
  const std::string dir = testing::MakeTempDir("lines_cli_pose_edge");
  const std::string yaml = WriteWallMap(dir);
  const testing::CliResult r = RunCli({"lines", yaml, "--pose", "1.55,2.4", "--json"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  // Its upper edge, 2.5 m, is the next row's: still free.
  EXPECT_EQ(RunCli({"lines", yaml, "--pose", "1.55,2.5", "--json"}).exit_code, 0);
  // And 2.399 m is on the wall.
  EXPECT_EQ(RunCli({"lines", yaml, "--pose", "1.55,2.399", "--json"}).exit_code, 2);
  // A map's upper edge belongs to no cell: on a free 6 x 3 map at 0.05
  // m/cell it is 0.15 m, off the map, though 0.15 / 0.05 - 0.5 is
  // 2.4999999999999996 in doubles, which rounding put in the top row.
  Grid small(6, 3, Cell::kFree);
  const std::string edge = SaveMap(dir, "small", small);
  const testing::CliResult top = RunCli({"lines", edge, "--pose", "0.125,0.15", "--json"});
  EXPECT_EQ(top.exit_code, 2);
  EXPECT_NE(top.err.find("off the map"), std::string::npos) << top.err;
  EXPECT_EQ(RunCli({"lines", edge, "--pose", "0.125,0.1499", "--json"}).exit_code, 0);
}

TEST(CmdLinesTest, BadInputExitsWithTwoAndWritesNothing) {
  const std::string dir = testing::MakeTempDir("lines_cli_bad");
  const std::string yaml = WriteWallMap(dir);
  const std::string out = dir + "/never.csv";
  EXPECT_EQ(RunCli({"lines", yaml, "--method", "hough", "-o", out}).exit_code, 2);
  EXPECT_EQ(RunCli({"lines", yaml, "--method", "rmline", "--dtheta", "0", "-o", out}).exit_code, 2);
  EXPECT_EQ(RunCli({"lines", yaml, "--epsilon", "0.2", "-o", out}).exit_code, 2);
  EXPECT_EQ(RunCli({"lines", yaml, "--max-added-cost", "-1", "-o", out}).exit_code, 2);
  EXPECT_EQ(RunCli({"lines", yaml, "--pose", "100,100", "-o", out}).exit_code, 2);
  // (2.25, 2.35) m is cell (12, 3), on the wall.
  EXPECT_EQ(RunCli({"lines", yaml, "--pose", "2.25,2.35", "-o", out}).exit_code, 2);
  EXPECT_EQ(RunCli({"lines", dir + "/missing.yaml", "-o", out}).exit_code, 2);
  EXPECT_FALSE(testing::FileExists(out));
}

// An option of the other method would change nothing: it is refused, naming
// the method it belongs to (encode alike for its extractor).
TEST(CmdLinesTest, OptionsOfTheOtherMethodAreRefused) {
  const std::string dir = testing::MakeTempDir("lines_cli_method");
  const std::string yaml = WriteWallMap(dir);
  for (const auto& [argv, message] : std::vector<std::pair<std::vector<std::string>, std::string>>{
           {{"lines", yaml, "--dtheta", "5"},
            "--dtheta is an option of the rmline extractor, not of linemap"},
           {{"lines", yaml, "--ds", "0.25"},
            "--ds is an option of the rmline extractor, not of linemap"},
           {{"lines", yaml, "--method", "rmline", "--epsilon", "2"},
            "--epsilon is an option of the linemap extractor, not of rmline"},
           {{"lines", yaml, "--method", "rmline", "--straight-walls"},
            "--straight-walls is an option of the linemap extractor, not of rmline"},
           {{"lines", yaml, "--method", "rmline", "--max-added-cost", "1"},
            "--max-added-cost is an option of the linemap extractor, not of rmline"},
           {{"encode", yaml, "-o", dir + "/x.lmap", "--method", "rmline", "--epsilon", "2"},
            "--epsilon is an option of the linemap extractor, not of rmline"},
           {{"encode", yaml, "-o", dir + "/x.lmap", "--method", "rmline", "--straight-walls"},
            "--straight-walls is an option of the linemap extractor, not of rmline"}}) {
    const testing::CliResult r = RunCli(argv);
    EXPECT_EQ(r.exit_code, 2) << message;
    EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
  }
  EXPECT_EQ(RunCli({"lines", yaml, "--method", "rmline", "--dtheta", "5"}).exit_code, 0);
  EXPECT_FALSE(testing::FileExists(dir + "/x.lmap"));
}

}  // namespace
}  // namespace linemap
