// The `linemap plan` command end to end: exit codes, messages, --json keys,
// --svg output.
#include <gtest/gtest.h>

#include <string>

#include "tests/testing/test_support.h"

namespace linemap::testing {
namespace {

std::string Arena() { return BundledMapsDir() + "/navtut/lse_arena.yaml"; }

// A 2 m x 1 m room at 0.05 m/cell split by a wall at x = 1.00..1.05 m.
std::string SplitRoom(const std::string& dir) {
  const int width = 40, height = 20;
  std::string pgm = "P5\n40 20\n255\n";
  for (int r = 0; r < height; ++r) {
    for (int c = 0; c < width; ++c) pgm += static_cast<char>(c == 20 ? 0 : 254);
  }
  WriteFile(dir + "/split.pgm", pgm);
  WriteFile(dir + "/split.yaml",
            "image: split.pgm\nresolution: 0.05\norigin: [0.0, 0.0, 0.0]\nnegate: 0\n"
            "occupied_thresh: 0.65\nfree_thresh: 0.196\n");
  return dir + "/split.yaml";
}

TEST(CmdPlanTest, PrintsCommandsAndWaypoints) {
  const CliResult r = RunCli({"plan", Arena(), "--from", "0.5,0.5", "--to", "3.5,2.5"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("trajectory 1:"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("  move "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("waypoints:"), std::string::npos) << r.out;
}

TEST(CmdPlanTest, JsonHasTheIssueKeys) {
  const CliResult r =
      RunCli({"plan", Arena(), "--from", "0.5,0.5,1.57", "--to", "3.5,2.5", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* key : {"{\"found\":true", "\"length_m\":", "\"commands\":[{\"turn_deg\":",
                          "{\"move_m\":", "\"waypoints\":[[", "\"alternatives\":", "\"ms\":"}) {
    EXPECT_NE(r.out.find(key), std::string::npos) << key << " in " << r.out;
  }
}

TEST(CmdPlanTest, SvgIsWritten) {
  const std::string dir = MakeTempDir("plan-svg");
  const CliResult r = RunCli({"plan", Arena(), "--from", "0.5,0.5", "--to", "3.5,2.5",
                              "--robot-width", "0.3", "--robot-length", "0.5", "--margin", "0.02",
                              "--dmin", "0.2", "--dmax", "2", "--svg", dir + "/out.svg"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string svg = ReadFile(dir + "/out.svg");
  EXPECT_EQ(svg.rfind("<svg", 0), 0u);
  EXPECT_NE(svg.find("<polyline"), std::string::npos);
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
}

// A start or goal off the map is bad input (exit 2); one in an obstacle or
// too near one gets no plan (exit 1).
TEST(CmdPlanTest, BadStartsAndGoalsExitTwoOffTheMapElseOne) {
  CliResult r = RunCli({"plan", Arena(), "--from", "0.5,0.5", "--to", "13.5,2.5"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("outside the map"), std::string::npos) << r.err;
  r = RunCli({"plan", Arena(), "--from", "-1,0.5", "--to", "3.5,2.5"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("start -1.000,0.500 is outside the map"), std::string::npos) << r.err;
  r = RunCli({"plan", Arena(), "--from", "0.01,0.01", "--to", "3.5,2.5"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("in an obstacle"), std::string::npos) << r.err;
  r = RunCli({"plan", Arena(), "--from", "0.08,1.5", "--to", "3.5,2.5"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("safe distance"), std::string::npos) << r.err;
}

// A start on the map's lower edge (0,0 with origin 0,0) is in cell 0, not
// outside the map; the border cell is then too close to the map's edge.
TEST(CmdPlanTest, LowerMapEdgeIsOnTheMap) {
  const std::string dir = MakeTempDir("plan-edge");
  const std::string map = SplitRoom(dir);
  CliResult r = RunCli({"plan", map, "--from", "0,0", "--to", "0.5,0.5"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err.find("outside the map"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("safe distance"), std::string::npos) << r.err;
  r = RunCli({"plan", map, "--from", "0.5,0.5", "--to", "0,0"});
  EXPECT_EQ(r.err.find("outside the map"), std::string::npos) << r.err;
  r = RunCli({"plan", map, "--from", "-0.001,0", "--to", "0.5,0.5"});
  EXPECT_NE(r.err.find("outside the map"), std::string::npos) << r.err;
  r = RunCli({"plan", map, "--from", "2.0,0.5", "--to", "0.5,0.5"});  // the upper edge
  EXPECT_NE(r.err.find("outside the map"), std::string::npos) << r.err;
}

// An unreachable goal is the planner's answer (exit 1, no trajectory); the
// SVG still shows why: the map and the safe zone, without a path.
TEST(CmdPlanTest, UnreachableGoalExitsOneAndDrawsTheSafeZoneOnly) {
  const std::string dir = MakeTempDir("plan-split");
  const std::string map = SplitRoom(dir);
  const CliResult r = RunCli(
      {"plan", map, "--from", "0.5,0.5", "--to", "1.5,0.5", "--json", "--svg", dir + "/plan.svg"});
  EXPECT_EQ(r.exit_code, 1);
  const std::string svg = testing::ReadFile(dir + "/plan.svg");
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
  EXPECT_EQ(svg.find("<polyline"), std::string::npos) << "no trajectory to draw";
  EXPECT_NE(svg.find("<circle"), std::string::npos) << "start and goal";
  EXPECT_NE(svg.find("fill=\"#e6f4ea\""), std::string::npos) << "the safe zone";
  EXPECT_NE(r.err.find("cannot be reached"), std::string::npos) << r.err;
  // Every key of a plan found, empty (as the Python module's plan()).
  for (const char* part :
       {"{\"found\":false,\"error\":\"the goal cannot be reached from the start through the "
        "safe zone\",\"length_m\":null,\"commands\":[],\"waypoints\":[],\"alternatives\":0,",
        "\"stages_ms\":{", "\"trajectories\":[]}"}) {
    EXPECT_NE(r.out.find(part), std::string::npos) << part << "\n" << r.out;
  }
  const CliResult same_side = RunCli({"plan", map, "--from", "0.5,0.5", "--to", "0.5,0.7"});
  EXPECT_EQ(same_side.exit_code, 0) << same_side.err;
}

TEST(CmdPlanTest, BadUsageExitsTwo) {
  EXPECT_EQ(RunCli({"plan", Arena(), "--from", "0.5,0.5"}).exit_code, 2);
  EXPECT_EQ(RunCli({"plan", Arena(), "--from", "0.5", "--to", "1,1"}).exit_code, 2);
  EXPECT_EQ(RunCli({"plan", Arena(), "--from", "0.5,0.5", "--to", "3.5,2.5", "--robot-width", "-1"})
                .exit_code,
            2);
  EXPECT_EQ(
      RunCli({"plan", Arena(), "--from", "0.5,0.5", "--to", "3.5,2.5", "--dmin", "9"}).exit_code,
      2);
}

}  // namespace
}  // namespace linemap::testing
