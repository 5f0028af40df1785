// The encode, decode, info, export and eval commands, run as a user would.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "linemap/map_io.h"
#include "tests/testing/test_support.h"

namespace linemap {
namespace {

using testing::RunCli;

const std::string kArena = testing::BundledMapsDir() + "/navtut/lse_arena.yaml";

TEST(CodecCliTest, EncodeDecodeRoundTripLossless) {
  const std::string dir = testing::MakeTempDir("cli_roundtrip");
  auto enc = RunCli({"encode", kArena, "-o", dir + "/a.lmap", "--lossless"});
  ASSERT_EQ(enc.exit_code, 0) << enc.err;
  EXPECT_NE(enc.out.find("4800 cells"), std::string::npos) << enc.out;
  EXPECT_NE(enc.out.find("png-9"), std::string::npos) << enc.out;
  auto dec = RunCli({"decode", dir + "/a.lmap", "-o", dir + "/a.yaml"});
  ASSERT_EQ(dec.exit_code, 0) << dec.err;
  EXPECT_TRUE(testing::FileExists(dir + "/a.pgm"));
  auto original = LoadRosMap(kArena);
  auto decoded = LoadRosMap(dir + "/a.yaml");
  ASSERT_TRUE(original.ok() && decoded.ok());
  EXPECT_EQ(decoded->cells(), original->cells());
  EXPECT_EQ(decoded->width(), original->width());
  // The frame too: the same resolution and origin in the YAML.
  EXPECT_EQ(decoded->meta.resolution, original->meta.resolution);
  EXPECT_EQ(decoded->meta.origin.x, original->meta.origin.x);
  EXPECT_EQ(decoded->meta.origin.y, original->meta.origin.y);
  EXPECT_EQ(decoded->meta.origin.yaw, original->meta.origin.yaw);
}

TEST(CodecCliTest, NoSyncStillReplacesFilesWhole) {
  const std::string dir = testing::MakeTempDir("cli_nosync");
  auto enc = RunCli({"encode", kArena, "-o", dir + "/a.lmap", "--lossless", "--no-sync"});
  ASSERT_EQ(enc.exit_code, 0) << enc.err;
  // Decoding twice over the same output replaces both files.
  for (int i = 0; i < 2; ++i) {
    auto dec = RunCli({"decode", dir + "/a.lmap", "-o", dir + "/a.yaml", "--no-sync"});
    ASSERT_EQ(dec.exit_code, 0) << dec.err;
  }
  auto original = LoadRosMap(kArena);
  auto decoded = LoadRosMap(dir + "/a.yaml");
  ASSERT_TRUE(original.ok() && decoded.ok());
  EXPECT_EQ(decoded->cells(), original->cells());
  // No temporary file is left behind.
  EXPECT_EQ(testing::ListDir(dir), (std::vector<std::string>{"a.lmap", "a.pgm", "a.yaml"}));
}

TEST(CodecCliTest, InfoListsChunksAndEvalReportsExactness) {
  const std::string dir = testing::MakeTempDir("cli_info");
  ASSERT_EQ(RunCli({"encode", kArena, "-o", dir + "/a.lmap", "--lossless"}).exit_code, 0);
  auto info = RunCli({"info", dir + "/a.lmap"});
  ASSERT_EQ(info.exit_code, 0) << info.err;
  EXPECT_NE(info.out.find("LMHD"), std::string::npos) << info.out;
  EXPECT_NE(info.out.find("CELL"), std::string::npos) << info.out;
  EXPECT_NE(info.out.find("LAYR"), std::string::npos) << info.out;
  EXPECT_NE(info.out.find("lossless"), std::string::npos) << info.out;
  auto eval = RunCli({"eval", kArena, dir + "/a.lmap", "--json"});
  ASSERT_EQ(eval.exit_code, 0) << eval.err;
  EXPECT_NE(eval.out.find("\"cells_equal\":4800"), std::string::npos) << eval.out;
  EXPECT_NE(eval.out.find("\"leaks\":0"), std::string::npos) << eval.out;
}

TEST(CodecCliTest, ExportWritesTheThreeFormats) {
  const std::string dir = testing::MakeTempDir("cli_export");
  const std::string depot = testing::BundledMapsDir() + "/nav2/depot.yaml";
  ASSERT_EQ(RunCli({"encode", depot, "-o", dir + "/d.lmap"}).exit_code, 0);
  for (const char* ext : {".csv", ".geojson", ".svg"}) {
    auto r = RunCli({"export", dir + "/d.lmap", "-o", dir + "/d" + ext});
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  const std::string csv = testing::ReadFile(dir + "/d.csv");
  EXPECT_EQ(csv.rfind("layer,x1,y1,x2,y2\nwall,", 0), 0u) << csv.substr(0, 80);
  EXPECT_NE(csv.find("\nroom_border,"), std::string::npos);
  EXPECT_NE(csv.find("\nfurniture,"), std::string::npos);
  EXPECT_NE(testing::ReadFile(dir + "/d.geojson").find("\"LineString\""), std::string::npos);
  EXPECT_NE(testing::ReadFile(dir + "/d.svg").find("<polyline"), std::string::npos);
  auto bad = RunCli({"export", dir + "/d.lmap", "-o", dir + "/d.txt"});
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_FALSE(testing::FileExists(dir + "/d.txt"));
}

TEST(CodecCliTest, BadInputGivesOneLineAndExitTwo) {
  const std::string dir = testing::MakeTempDir("cli_bad");
  testing::WriteFile(dir + "/empty.lmap", "");
  testing::WriteFile(dir + "/bad.lmap", "\x8aLMAP\r\n\x1a\x01\x00garbage");
  for (const std::string& input : {dir + "/missing.lmap", dir + "/empty.lmap", dir + "/bad.lmap",
                                   testing::SourceDir() + "/tests/data/lmap/bad_crc.lmap"}) {
    auto r = RunCli({"decode", input, "-o", dir + "/out.yaml"});
    EXPECT_EQ(r.exit_code, 2) << input << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(testing::FileExists(dir + "/out.yaml"));
  }
  auto no_out = RunCli({"encode", kArena});
  EXPECT_EQ(no_out.exit_code, 2);
}

}  // namespace
}  // namespace linemap
