// `linemap decode --window / --window-cells / --room-at / --threads` through
// the built CLI: a window's PGM equals the same cells of the whole decode,
// its YAML origin puts it where it lay in the map, and windows that are
// empty or reach past the border are refused with exit 2 and nothing
// written.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "linemap/lmap_vectors.h"
#include "linemap/map_io.h"
#include "tests/testing/reference_geometry.h"
#include "tests/testing/test_support.h"

namespace linemap {
namespace {

using testing::CliResult;
using testing::RunCli;

struct Window {
  int c0, r0, c1, r1;
};

std::string CellsArg(const Window& w) {
  return std::to_string(w.c0) + "," + std::to_string(w.r0) + "," + std::to_string(w.c1) + "," +
         std::to_string(w.r1);
}

// The whole map's decode (through the CLI, read back by the map reader).
Grid DecodeWhole(const std::string& lmap, const std::string& dir) {
  const CliResult r = RunCli({"decode", lmap, "-o", dir + "/whole.yaml"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  StatusOr<Grid> g = LoadRosMap(dir + "/whole.yaml");
  EXPECT_TRUE(g.ok());
  return g.ok() ? *g : Grid();
}

// Decodes `window_args` to dir/w.yaml and checks it against the crop `w` of
// `whole`, and its origin against the whole map's cell corner (c0, r0).
void ExpectWindow(const std::string& lmap, const std::string& dir, const Grid& whole,
                  const std::vector<std::string>& window_args, const Window& w) {
  SCOPED_TRACE(lmap + " window " + CellsArg(w));
  std::vector<std::string> argv = {"decode", lmap, "-o", dir + "/w.yaml", "--no-sync"};
  argv.insert(argv.end(), window_args.begin(), window_args.end());
  const CliResult r = RunCli(argv);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  StatusOr<Grid> got = LoadRosMap(dir + "/w.yaml");
  ASSERT_TRUE(got.ok()) << got.status().message();
  ASSERT_EQ(got->width(), w.c1 - w.c0);
  ASSERT_EQ(got->height(), w.r1 - w.r0);
  std::size_t differ = 0;
  for (int r = w.r0; r < w.r1; ++r) {
    for (int c = w.c0; c < w.c1; ++c) differ += got->at(c - w.c0, r - w.r0) != whole.at(c, r);
  }
  EXPECT_EQ(differ, 0u);
  // map_server's origin: the lower-left corner of cell (0, 0), turned by the
  // yaw; the window's is the corner of cell (c0, r0) of the map.
  const MapMetadata& m = whole.meta;
  const double u = w.c0 * m.resolution, v = w.r0 * m.resolution;
  const double cs = std::cos(m.origin.yaw), sn = std::sin(m.origin.yaw);
  EXPECT_NEAR(got->meta.origin.x, m.origin.x + cs * u - sn * v, 1e-9);
  EXPECT_NEAR(got->meta.origin.y, m.origin.y + sn * u + cs * v, 1e-9);
  EXPECT_NEAR(got->meta.origin.yaw, m.origin.yaw, 1e-12);
  EXPECT_EQ(got->meta.resolution, m.resolution);
}

// Corners, single cells, whole rows and columns, the whole map, and random
// windows.
std::vector<Window> WindowsFor(int w, int h, unsigned seed) {
  std::vector<Window> out = {
      {0, 0, 1, 1}, {w - 1, h - 1, w, h},     {w - 1, 0, w, 1},        {0, h - 1, 1, h},
      {0, 0, w, h}, {0, h / 2, w, h / 2 + 1}, {w / 2, 0, w / 2 + 1, h}};
  std::mt19937 rng(seed);
  for (int k = 0; k < 8; ++k) {
    int a = std::uniform_int_distribution<int>(0, w - 1)(rng);
    int b = std::uniform_int_distribution<int>(0, w - 1)(rng);
    int c = std::uniform_int_distribution<int>(0, h - 1)(rng);
    int d = std::uniform_int_distribution<int>(0, h - 1)(rng);
    out.push_back({std::min(a, b), std::min(c, d), std::max(a, b) + 1, std::max(c, d) + 1});
  }
  return out;
}

TEST(CmdDecodeWindowTest, WindowCellsEqualTheCropOfTheWholeDecode) {
  const std::vector<std::string> maps = testing::FindYamlFiles(testing::BundledMapsDir());
  ASSERT_GE(maps.size(), 4u);
  unsigned seed = 1;
  for (const std::string& map : maps) {
    const std::string dir = testing::MakeTempDir("decode_window");
    // Small tiles, so that windows start, end and cross inside tiles; the
    // turned origin checks the YAML origin's rotation.
    const std::string lmap = dir + "/m.lmap";
    const CliResult enc = RunCli({"encode", map, "--tile-size", seed % 2 ? "16" : "64", "--origin",
                                  seed % 2 ? "-3.5,2.25,0.3" : "1,-2", "-o", lmap});
    ASSERT_EQ(enc.exit_code, 0) << enc.err;
    const Grid whole = DecodeWhole(lmap, dir);
    ASSERT_GT(whole.size(), 0u);
    for (const Window& w : WindowsFor(whole.width(), whole.height(), seed++)) {
      ExpectWindow(lmap, dir, whole, {"--window-cells", CellsArg(w)}, w);
    }
  }
}

// The cells whose centres lie in the box, found here by testing every
// column and row centre of the map.
Window CentresIn(const Grid& g, double x0, double y0, double x1, double y1) {
  Window w{g.width(), g.height(), -1, -1};
  for (int c = 0; c < g.width(); ++c) {
    const double x = g.meta.origin.x + (c + 0.5) * g.meta.resolution;
    if (x >= x0 - 1e-9 && x <= x1 + 1e-9) w.c0 = std::min(w.c0, c), w.c1 = std::max(w.c1, c + 1);
  }
  for (int r = 0; r < g.height(); ++r) {
    const double y = g.meta.origin.y + (r + 0.5) * g.meta.resolution;
    if (y >= y0 - 1e-9 && y <= y1 + 1e-9) w.r0 = std::min(w.r0, r), w.r1 = std::max(w.r1, r + 1);
  }
  return w;
}

std::string Metres(double x0, double y0, double x1, double y1) {
  char text[128];
  std::snprintf(text, sizeof(text), "%.4f,%.4f,%.4f,%.4f", x0, y0, x1, y1);
  return text;
}

TEST(CmdDecodeWindowTest, WindowInMetresTakesTheCellsWhoseCentresLieInTheBox) {
  const std::string dir = testing::MakeTempDir("decode_window_m");
  const std::string lmap = dir + "/d.lmap";
  ASSERT_EQ(RunCli({"encode", testing::BundledMapsDir() + "/nav2/depot.yaml", "--origin",
                    "-10.3,4.7", "--tile-size", "32", "-o", lmap})
                .exit_code,
            0);
  const Grid whole = DecodeWhole(lmap, dir);
  const double ox = whole.meta.origin.x, oy = whole.meta.origin.y, res = whole.meta.resolution;
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> fx(ox, ox + whole.width() * res);
  std::uniform_real_distribution<double> fy(oy, oy + whole.height() * res);
  std::vector<std::array<double, 4>> boxes = {
      // Edges exactly on cell centres are inside: cells 0..19 x 0..9.
      {ox + 0.5 * res, oy + 0.5 * res, ox + 19.5 * res, oy + 9.5 * res},
      // One cell, by a box around its centre, and by a zero-size box on it.
      {ox + 100.4 * res, oy + 50.4 * res, ox + 100.6 * res, oy + 50.6 * res},
      {ox + 7.5 * res, oy + 3.5 * res, ox + 7.5 * res, oy + 3.5 * res},
      // The whole map's extent.
      {ox, oy, ox + whole.width() * res, oy + whole.height() * res}};
  for (int k = 0; k < 8; ++k) {
    double a = fx(rng), b = fx(rng), c = fy(rng), d = fy(rng);
    boxes.push_back({std::min(a, b), std::min(c, d), std::max(a, b), std::max(c, d)});
  }
  for (const auto& b : boxes) {
    // The box is passed as printed, so the reference uses the printed values.
    const std::string arg = Metres(b[0], b[1], b[2], b[3]);
    double x0, y0, x1, y1;
    ASSERT_EQ(std::sscanf(arg.c_str(), "%lf,%lf,%lf,%lf", &x0, &y0, &x1, &y1), 4);
    const Window w = CentresIn(whole, x0, y0, x1, y1);
    if (w.c1 < 0 || w.r1 < 0) continue;  // a random box between centres
    ExpectWindow(lmap, dir, whole, {"--window", arg}, w);
  }
  const Window first = CentresIn(whole, boxes[0][0], boxes[0][1], boxes[0][2], boxes[0][3]);
  EXPECT_EQ(first.c1 - first.c0, 20);
  EXPECT_EQ(first.r1 - first.r0, 10);
}

// A map turned a quarter turn: map-frame x runs along -rows, y along
// columns, so the box x in [-1, -0.5], y in [0.5, 1] m holds the centres of
// rows 10..19 and columns 10..19 (0.05 m cells).
TEST(CmdDecodeWindowTest, WindowInMetresOnATurnedMap) {
  const std::string dir = testing::MakeTempDir("decode_window_yaw");
  const std::string lmap = dir + "/a.lmap";
  ASSERT_EQ(RunCli({"encode", testing::BundledMapsDir() + "/navtut/lse_arena.yaml", "--origin",
                    "0,0,1.5707963267948966", "-o", lmap})
                .exit_code,
            0);
  const Grid whole = DecodeWhole(lmap, dir);
  ExpectWindow(lmap, dir, whole, {"--window", "-1,0.5,-0.5,1"}, {10, 10, 20, 20});
}

// Refused with exit 2, one line naming the problem, nothing written.
void ExpectRefused(const std::string& lmap, const std::string& dir,
                   const std::vector<std::string>& window_args, const std::string& says) {
  std::vector<std::string> argv = {"decode", lmap, "-o", dir + "/out/w.yaml"};
  argv.insert(argv.end(), window_args.begin(), window_args.end());
  const CliResult r = RunCli(argv);
  SCOPED_TRACE(window_args.back() + ": " + r.err);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1);
  EXPECT_NE(r.err.find(says), std::string::npos);
  EXPECT_TRUE(testing::ListDir(dir + "/out").empty());
}

TEST(CmdDecodeWindowTest, EmptyOrOutOfMapWindowsAreRefused) {
  const std::string dir = testing::MakeTempDir("decode_window_bad");
  std::filesystem::create_directories(dir + "/out");
  const std::string lmap = dir + "/a.lmap";
  // The arena: 80 x 60 cells of 0.05 m, origin 0,0.
  ASSERT_EQ(RunCli({"encode", testing::BundledMapsDir() + "/navtut/lse_arena.yaml", "-o", lmap})
                .exit_code,
            0);
  for (const char* cells : {"0,0,81,60", "0,0,80,61", "-1,0,10,10", "0,-1,10,10", "80,0,81,1",
                            "5,5,5,6", "5,5,6,5", "6,5,5,6", "100,100,200,200"}) {
    ExpectRefused(lmap, dir, {"--window-cells", cells}, "not inside the map's 80 x 60 cells");
  }
  ExpectRefused(lmap, dir, {"--window-cells", "0,0,1.5,2"}, "whole cell indices");
  ExpectRefused(lmap, dir, {"--window-cells", "0,0,1"}, "4 comma-separated numbers");
  // Centres run from 0.025 to 3.975 m (x) and 2.975 m (y).
  ExpectRefused(lmap, dir, {"--window", "3.9,0,4.03,1"}, "past the map's border");
  ExpectRefused(lmap, dir, {"--window", "-0.03,0,1,1"}, "past the map's border");
  ExpectRefused(lmap, dir, {"--window", "0,2,1,3.1"}, "past the map's border");
  ExpectRefused(lmap, dir, {"--window", "50,50,60,60"}, "past the map's border");
  ExpectRefused(lmap, dir, {"--window", "1.01,1,1.02,2"}, "holds no cell centre");
  ExpectRefused(lmap, dir, {"--window", "2,1,1,2"}, "X0 must not exceed X1");
  ExpectRefused(lmap, dir, {"--window", "0,0,nan,1"}, "--window");
  ExpectRefused(lmap, dir, {"--window", "0,0,1,1", "--window-cells", "0,0,1,1"}, "give one of");
  ExpectRefused(lmap, dir, {"--window", "0,0,1,1", "--room-at", "1,1"}, "give one of");
  // Past the map by less than half a cell holds no outside centre: accepted.
  const CliResult edge =
      RunCli({"decode", lmap, "-o", dir + "/e.yaml", "--window", "-0.02,-0.02,4.02,3.02"});
  EXPECT_EQ(edge.exit_code, 0) << edge.err;
  EXPECT_NE(edge.out.find("80 x 60 cells"), std::string::npos) << edge.out;
}

// --room-at X,Y writes the window LoadLmapRoomAt gives for the cell holding
// the point: the same cells as the whole decode there, origin at the
// window's corner; points off the map or outside every room are refused.
TEST(CmdDecodeWindowTest, RoomAtWritesTheRoomsWindow) {
  const std::string dir = testing::MakeTempDir("decode_room_at");
  std::filesystem::create_directories(dir + "/out");
  const std::string lmap = dir + "/d.lmap";
  ASSERT_EQ(
      RunCli({"encode", testing::BundledMapsDir() + "/nav2/depot.yaml", "-o", lmap}).exit_code, 0);
  const Grid whole = DecodeWhole(lmap, dir);
  StatusOr<LmapVectors> vectors = LoadLmapVectors(lmap);
  ASSERT_TRUE(vectors.ok()) << vectors.status().message();
  // Cells of several rooms, and one outside every room's border; the room
  // expected at each is the test's own (spec 8.2 written out, smallest area).
  std::set<std::uint32_t> rooms_seen;
  std::optional<CellIndex> roomless;
  for (int r = 3; r < whole.height(); r += 29) {
    for (int c = 5; c < whole.width(); c += 31) {
      const RoomOutline* room = testing::ReferenceRoomAt(vectors->rooms, c, r);
      if (room == nullptr) {
        roomless = CellIndex{c, r};
        continue;
      }
      if (!rooms_seen.insert(room->id).second) continue;
      const BoundingBox box = BoxOfCells(room->chain);
      const Window w{box.min_col, box.min_row, box.max_col + 1, box.max_row + 1};
      // The point: the cell's centre, a little off it.
      const double x = whole.meta.origin.x + (c + 0.3) * whole.meta.resolution;
      const double y = whole.meta.origin.y + (r + 0.6) * whole.meta.resolution;
      char point[64];
      std::snprintf(point, sizeof(point), "%.6f,%.6f", x, y);
      ExpectWindow(lmap, dir, whole, {"--room-at", point}, w);
      const CliResult out = RunCli({"decode", lmap, "-o", dir + "/w.yaml", "--room-at", point});
      EXPECT_NE(out.out.find(", room " + std::to_string(room->id) + " ("), std::string::npos)
          << out.out;
    }
  }
  EXPECT_GE(rooms_seen.size(), 3u);
  ASSERT_TRUE(roomless.has_value());
  char point[64];
  std::snprintf(point, sizeof(point), "%.6f,%.6f", (roomless->col + 0.5) * 0.05,
                (roomless->row + 0.5) * 0.05);
  ExpectRefused(lmap, dir, {"--room-at", point}, "outside every room's border");
  ExpectRefused(lmap, dir, {"--room-at", "-0.1,1"}, "lies outside the map's 604 x 307 cells");
  ExpectRefused(lmap, dir, {"--room-at", "30.3,1"}, "lies outside the map's 604 x 307 cells");
  // The map's right edge bounds its last column's squares: a point on it is
  // off the map, one just inside it in the last column.
  ExpectRefused(lmap, dir, {"--room-at", "30.2,1"}, "lies outside the map's 604 x 307 cells");
  ExpectRefused(lmap, dir, {"--room-at", "1"}, "2 comma-separated numbers");
}

// kth (260 x 781 cells of 0.05 m, origin -7, -17.5), encoded once per test.
std::string EncodedKth(const std::string& dir) {
  const std::string lmap = dir + "/kth.lmap";
  const CliResult r =
      RunCli({"encode", testing::BundledMapsDir() + "/strands/kth/map.yaml", "-o", lmap});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return lmap;
}

// --room-at on a cell's left edge typed in decimal: -6.9 m is column 2's
// left edge ((-6.9 + 7) / 0.05 = 2 cell widths from the map's), -17.175 m
// the middle of row 6 (0.325 / 0.05 = 6.5), so the cell is (2, 6), the room
// the test's own transcription of spec 8.2 finds there. Plain division put
// the point in column 1 (outside every room's border), while -6.899999999
// (inside column 2) found the room. Then the same on other decimal left
// edges of the corridor, against the reference's room at each.
TEST(CmdDecodeWindowTest, RoomAtOnACellsLeftEdgeTypedInDecimalIsInThatCell) {
  const std::string dir = testing::MakeTempDir("decode_room_at_edge");
  std::filesystem::create_directories(dir + "/out");
  const std::string lmap = EncodedKth(dir);
  StatusOr<LmapVectors> vectors = LoadLmapVectors(lmap);
  ASSERT_TRUE(vectors.ok()) << vectors.status().message();
  const RoomOutline* room = testing::ReferenceRoomAt(vectors->rooms, 2, 6);
  ASSERT_NE(room, nullptr);
  for (const char* point : {"-6.9,-17.175", "-6.899999999,-17.175"}) {
    const CliResult r = RunCli({"decode", lmap, "-o", dir + "/e.yaml", "--room-at", point});
    ASSERT_EQ(r.exit_code, 0) << point << ": " << r.err;
    EXPECT_NE(r.out.find(", room " + std::to_string(room->id) + " ("), std::string::npos)
        << point << ": " << r.out;
  }
  // Column k's left edge is -7 + 0.05 k m, written from whole hundredths;
  // row 400's middle is -17.5 + 400.5 * 0.05 = 2.525 m.
  int checked = 0;
  for (int k = 100; k < 160; k += 3) {
    const RoomOutline* want = testing::ReferenceRoomAt(vectors->rooms, k, 400);
    const int hundredths = -700 + 5 * k;
    char point[64];
    std::snprintf(point, sizeof(point), "%s%d.%02d,2.525", hundredths < 0 ? "-" : "",
                  std::abs(hundredths) / 100, std::abs(hundredths) % 100);
    SCOPED_TRACE(point);
    if (want == nullptr) {
      ExpectRefused(lmap, dir, {"--room-at", point},
                    "encloses cell (" + std::to_string(k) + ", 400)");
      continue;
    }
    const CliResult r = RunCli({"decode", lmap, "-o", dir + "/e.yaml", "--room-at", point});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find(", room " + std::to_string(want->id) + " ("), std::string::npos) << r.out;
    ++checked;
  }
  EXPECT_GE(checked, 5);
}

// Refusals of windows far off the map give the cells the box covers: a
// huge X leaves the rows alone (y 0..1 m: rows 349.5..369.5, so [350, 370);
// x = 0: column 139.5, so from 140). --window-cells with a whole index
// past an int says it is out of range, not that it is not whole.
TEST(CmdDecodeWindowTest, RefusalsOfHugeWindowsGiveTheTrueCells) {
  const std::string dir = testing::MakeTempDir("decode_window_huge");
  std::filesystem::create_directories(dir + "/out");
  const std::string lmap = EncodedKth(dir);
  ExpectRefused(lmap, dir, {"--window=-1e18,0,0,1"}, "covers cells [-2e+19, 140) x [350, 370)");
  ExpectRefused(lmap, dir, {"--window=0,0,9.3e15,1"}, "covers cells [140, 1.86e+17) x [350, 370)");
  ExpectRefused(lmap, dir, {"--window-cells", "0,0,2147483648,1"},
                "--window-cells index 2147483648 is out of range");
  ExpectRefused(lmap, dir, {"--window-cells", "-3000000000,0,1,1"},
                "--window-cells index -3000000000 is out of range");
  ExpectRefused(lmap, dir, {"--window-cells", "0,0,2.5,1"}, "whole cell indices");
  // The largest int is whole and in range: refused as past the map.
  ExpectRefused(lmap, dir, {"--window-cells", "0,0,2147483647,1"},
                "not inside the map's 260 x 781 cells");
}

// The tiles decode on any number of threads to the same files; a 1.0 file
// (decoded whole, then cropped) gives its window too.
TEST(CmdDecodeWindowTest, ThreadsAndVersion1Files) {
  const std::string dir = testing::MakeTempDir("decode_window_threads");
  const std::string lmap = dir + "/w.lmap";
  const std::string willow =
      testing::BundledMapsDir() + "/turtlebot_apps/willow-2010-02-18-0.10.yaml";
  ASSERT_EQ(RunCli({"encode", willow, "--tile-size", "64", "-o", lmap}).exit_code, 0);
  std::string first;
  for (const char* threads : {"1", "2", "3", "0"}) {
    ASSERT_EQ(RunCli({"decode", lmap, "-o", dir + "/t.yaml", "--threads", threads}).exit_code, 0);
    const std::string pgm = testing::ReadFile(dir + "/t.pgm");
    if (first.empty()) first = pgm;
    EXPECT_EQ(pgm, first) << threads;
  }
  EXPECT_EQ(RunCli({"decode", lmap, "-o", dir + "/t.yaml", "--threads", "-1"}).exit_code, 2);
  EXPECT_EQ(RunCli({"decode", lmap, "-o", dir + "/t.yaml", "--threads", "x"}).exit_code, 2);

  const std::string v1 = testing::SourceDir() + "/tests/data/lmap/lse_arena_lossy.lmap";
  const Grid whole = DecodeWhole(v1, dir);
  ExpectWindow(v1, dir, whole, {"--window-cells", "3,7,50,44"}, {3, 7, 50, 44});
  ExpectWindow(v1, dir, whole, {"--window", "0.5,0.5,1,2"}, {10, 10, 20, 40});
}

// On a map turned by its origin's yaw, a window inside the box around the
// map can still reach past its grid. The message used to give two corner
// cells' centres as the map's extent ("from 1.00995,2.03393 to 20.1339,
// 29.9156 m", which holds the window): it now says the window is taken in
// map-frame metres, which cells the grid has, and the box around the turned
// map, computed here from its four corners.
TEST(CmdDecodeWindowTest, RefusalOnATurnedMapStatesItsExtent) {
  const std::string dir = testing::MakeTempDir("decode_window_turned_extent");
  const std::string lmap = dir + "/rot.lmap";
  ASSERT_EQ(RunCli({"encode", testing::BundledMapsDir() + "/nav2/depot.yaml", "-o", lmap,
                    "--origin", "1,2,0.5"})
                .exit_code,
            0);
  const CliResult r = RunCli({"decode", lmap, "-o", dir + "/r.yaml", "--window", "18,4,20,6"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find("past the map's border"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("map-frame metres"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("columns 0..603, rows 0..306"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("1.00995,2.03393"), std::string::npos) << r.err;
  // 604 x 307 cells of 0.05 m from (1, 2), turned by 0.5 rad.
  const double c = std::cos(0.5), s = std::sin(0.5), w = 604 * 0.05, h = 307 * 0.05;
  const double xs[] = {1, 1 + c * w, 1 - s * h, 1 + c * w - s * h};
  const double ys[] = {2, 2 + s * w, 2 + c * h, 2 + s * w + c * h};
  char extent[128];
  std::snprintf(extent, sizeof(extent), "x %g..%g m, y %g..%g m", *std::min_element(xs, xs + 4),
                *std::max_element(xs, xs + 4), *std::min_element(ys, ys + 4),
                *std::max_element(ys, ys + 4));
  EXPECT_NE(r.err.find(extent), std::string::npos) << extent << "\n" << r.err;
  EXPECT_EQ(testing::ListDir(dir), std::vector<std::string>{"rot.lmap"});
}

}  // namespace
}  // namespace linemap
