// `linemap eval ORIGINAL FILE.lmap`: the layer fidelity figures (DisPL_ave,
// shares within 1 cell of a wall or inside furniture) against a brute-force
// reference written here: every edge cell against every wall segment, and
// an even-odd point-in-polygon test for the furniture fill.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "linemap/lmap_vectors.h"
#include "linemap/map_io.h"
#include "tests/testing/test_support.h"

namespace linemap {
namespace {

using testing::CliResult;
using testing::RunCli;

struct Reference {
  std::size_t edge_cells = 0;
  double displ_ave = 0, displ_max = 0;
  std::size_t within_1 = 0, in_furniture = 0, covered = 0;
};

double PointSegmentDistance(double px, double py, CellIndex a, CellIndex b) {
  const double dx = b.col - a.col, dy = b.row - a.row;
  const double len2 = dx * dx + dy * dy;
  double t = len2 > 0 ? ((px - a.col) * dx + (py - a.row) * dy) / len2 : 0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(px - (a.col + t * dx), py - (a.row + t * dy));
}

// The chain's own cells, or a centre strictly inside the polygon through the
// chain's cell centres by the even-odd ray test.
bool InsideOutline(const std::vector<CellIndex>& chain, int col, int row) {
  bool inside = false;
  for (std::size_t i = 0, j = chain.size() - 1; i < chain.size(); j = i++) {
    if (chain[i].col == col && chain[i].row == row) return true;
    const CellIndex a = chain[i], b = chain[j];
    if ((a.row > row) != (b.row > row) &&
        col < a.col + static_cast<double>(row - a.row) * (b.col - a.col) / (b.row - a.row)) {
      inside = !inside;
    }
  }
  return inside;
}

Reference BruteForce(const Grid& g, const LmapVectors& v) {
  Reference ref;
  double sum = 0;
  auto is = [&](int c, int r, Cell cell) { return g.Contains(c, r) && g.at(c, r) == cell; };
  for (int r = 0; r < g.height(); ++r) {
    for (int c = 0; c < g.width(); ++c) {
      if (g.at(c, r) != Cell::kOccupied) continue;
      if (!is(c + 1, r, Cell::kFree) && !is(c - 1, r, Cell::kFree) && !is(c, r + 1, Cell::kFree) &&
          !is(c, r - 1, Cell::kFree)) {
        continue;
      }
      ++ref.edge_cells;
      double d = std::numeric_limits<double>::infinity();
      for (const WallPolyline& w : v.walls) {
        for (std::size_t i = 1; i < w.points.size(); ++i)
          d = std::min(d, PointSegmentDistance(c, r, w.points[i - 1], w.points[i]));
      }
      sum += d;
      ref.displ_max = std::max(ref.displ_max, d);
      bool in_furniture = false;
      for (const FurnitureObject& f : v.furniture) in_furniture |= InsideOutline(f.outline, c, r);
      ref.within_1 += d <= 1.0;
      ref.in_furniture += in_furniture;
      ref.covered += d <= 1.0 || in_furniture;
    }
  }
  ref.displ_ave = sum / static_cast<double>(ref.edge_cells);
  return ref;
}

// A room with walls of uneven thickness, a diagonal wall, a door gap,
// scattered small objects and unknown space outside: something of every
// layer, with edge cells both near walls and not.
std::string WriteSmallMap(const std::string& dir) {
  const int w = 90, h = 70;
  std::string pixels(static_cast<std::size_t>(w) * h, '\xcd');
  auto set = [&](int x, int y, char v) {
    if (x >= 0 && y >= 0 && x < w && y < h) pixels[static_cast<std::size_t>(y) * w + x] = v;
  };
  for (int y = 5; y < 65; ++y)
    for (int x = 5; x < 85; ++x) set(x, y, '\xfe');
  for (int x = 5; x < 85; ++x) {
    set(x, 5, 0);
    set(x, 64, 0);
    if (x % 7 == 0) set(x, 63, 0);  // a ragged wall
  }
  for (int y = 5; y < 65; ++y) {
    set(5, y, 0);
    if (y < 30 || y > 38) set(84, y, 0);  // a door
  }
  for (int i = 0; i < 25; ++i) set(20 + i, 20 + i / 2, 0);  // a slanted wall
  unsigned seed = 7;
  for (int k = 0; k < 12; ++k) {  // small objects of 1..9 cells
    seed = seed * 1103515245u + 12345u;
    const int x = 50 + static_cast<int>(seed >> 16) % 28, y = 12 + static_cast<int>(seed >> 8) % 45;
    const int s = 1 + k % 3;
    for (int dy = 0; dy < s; ++dy)
      for (int dx = 0; dx < s; ++dx) set(x + dx, y + dy, 0);
  }
  testing::WriteFile(dir + "/small.pgm",
                     "P5\n" + std::to_string(w) + " " + std::to_string(h) + "\n255\n" + pixels);
  testing::WriteFile(dir + "/small.yaml",
                     "image: small.pgm\nresolution: 0.05\norigin: [0, 0, 0]\nnegate: 0\n"
                     "occupied_thresh: 0.65\nfree_thresh: 0.196\n");
  return dir + "/small.yaml";
}

void ExpectEvalMatchesBruteForce(const std::string& map, const std::string& lmap,
                                 bool need_layers) {
  StatusOr<Grid> g = LoadRosMap(map);
  ASSERT_TRUE(g.ok());
  StatusOr<LmapVectors> v = LoadLmapVectors(lmap);
  ASSERT_TRUE(v.ok());
  if (need_layers) {
    ASSERT_GT(v->walls.size(), 0u);
    ASSERT_GT(v->furniture.size(), 0u);
  }
  const Reference ref = BruteForce(*g, *v);
  ASSERT_GT(ref.edge_cells, 0u);
  const CliResult r = RunCli({"eval", map, lmap, "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const YAML::Node j = YAML::Load(r.out);
  const double n = static_cast<double>(ref.edge_cells);
  EXPECT_EQ(j["edge_cells"].as<std::size_t>(), ref.edge_cells);
  EXPECT_NEAR(j["displ_ave_cells"].as<double>(), ref.displ_ave, 1e-9);
  EXPECT_NEAR(j["displ_ave_cm"].as<double>(), ref.displ_ave * g->meta.resolution * 100, 1e-9);
  EXPECT_NEAR(j["displ_max_cells"].as<double>(), ref.displ_max, 1e-9);
  EXPECT_NEAR(j["edge_share_within_1"].as<double>(), ref.within_1 / n, 1e-12);
  EXPECT_NEAR(j["edge_share_in_furniture"].as<double>(), ref.in_furniture / n, 1e-12);
  EXPECT_NEAR(j["edge_share_within_1_or_furniture"].as<double>(), ref.covered / n, 1e-12);
  // The cell-by-cell figures stay.
  EXPECT_EQ(j["cells_equal"].as<std::size_t>(), g->size());
  if (need_layers) {
    // The figures must tell walls and furniture apart on these maps.
    EXPECT_LT(ref.within_1, ref.covered);
    EXPECT_GT(ref.in_furniture, 0u);
  }
  const CliResult text = RunCli({"eval", map, lmap});
  ASSERT_EQ(text.exit_code, 0) << text.err;
  char want[96];
  std::snprintf(want, sizeof(want), "DisPL_ave:            %.4f cells (%.2f cm)", ref.displ_ave,
                ref.displ_ave * g->meta.resolution * 100);
  EXPECT_NE(text.out.find(want), std::string::npos) << want << "\n" << text.out;
}

TEST(CmdEvalLayersTest, SmallMapMatchesBruteForce) {
  const std::string dir = testing::MakeTempDir("eval_layers_small");
  const std::string map = WriteSmallMap(dir);
  ASSERT_EQ(RunCli({"encode", map, "-o", dir + "/s.lmap"}).exit_code, 0);
  ExpectEvalMatchesBruteForce(map, dir + "/s.lmap", /*need_layers=*/true);
}

TEST(CmdEvalLayersTest, DepotMatchesBruteForce) {
  const std::string dir = testing::MakeTempDir("eval_layers_depot");
  const std::string map = testing::BundledMapsDir() + "/nav2/depot.yaml";
  ASSERT_EQ(RunCli({"encode", map, "-o", dir + "/d.lmap"}).exit_code, 0);
  ExpectEvalMatchesBruteForce(map, dir + "/d.lmap", /*need_layers=*/true);
}

// A 1.0 lossy file (a fixture: 1.0 files are no longer written): its
// segments are the walls.
TEST(CmdEvalLayersTest, Version1FileMatchesBruteForce) {
  const std::string map = testing::BundledMapsDir() + "/nav2/depot.yaml";
  const std::string lmap = testing::SourceDir() + "/tests/data/lmap/depot_lossy.lmap";
  StatusOr<Grid> g = LoadRosMap(map);
  StatusOr<LmapVectors> v = LoadLmapVectors(lmap);
  ASSERT_TRUE(g.ok() && v.ok());
  ASSERT_EQ(v->major, 1);
  ASSERT_FALSE(v->walls.empty());
  const Reference ref = BruteForce(*g, *v);
  const CliResult r = RunCli({"eval", map, lmap, "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const YAML::Node j = YAML::Load(r.out);
  EXPECT_NEAR(j["displ_ave_cells"].as<double>(), ref.displ_ave, 1e-9);
  EXPECT_NEAR(j["edge_share_within_1"].as<double>(),
              ref.within_1 / static_cast<double>(ref.edge_cells), 1e-12);
}

// Without layers there is no distance to report, and nothing covers the
// edge cells.
TEST(CmdEvalLayersTest, RasterOnlyFileHasNoDistance) {
  const std::string dir = testing::MakeTempDir("eval_layers_raster");
  const std::string map = testing::BundledMapsDir() + "/navtut/lse_arena.yaml";
  ASSERT_EQ(RunCli({"encode", map, "--raster-only", "-o", dir + "/r.lmap"}).exit_code, 0);
  const CliResult r = RunCli({"eval", map, dir + "/r.lmap", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("\"displ_ave_cells\":null"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"edge_share_within_1\":null,"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"edge_share_within_1_or_furniture\":0}"), std::string::npos) << r.out;
  const CliResult text = RunCli({"eval", map, dir + "/r.lmap"});
  EXPECT_NE(text.out.find("DisPL_ave:            n/a (the file has no walls)"), std::string::npos)
      << text.out;
  // Not 0: no wall is missing, there are none.
  EXPECT_NE(text.out.find("within 1 of a wall:   n/a (the file has no walls)\n"), std::string::npos)
      << text.out;
}

}  // namespace
}  // namespace linemap
