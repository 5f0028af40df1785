// `linemap decode` through the built CLI: output names YAML would misread
// (the reviewer's '#', ': ', '[', '&' and a quote) give a YAML that `info`,
// `eval` and yaml-cpp read back with the right image.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <string>

#include "tests/testing/test_support.h"

namespace linemap {
namespace {

using testing::CliResult;
using testing::RunCli;

TEST(CmdDecodeTest, AwkwardOutputNamesLoadBack) {
  const std::string dir = testing::MakeTempDir("decode_names");
  const std::string arena = testing::BundledMapsDir() + "/navtut/lse_arena.yaml";
  ASSERT_EQ(RunCli({"encode", arena, "--lossless", "-o", dir + "/a.lmap"}).exit_code, 0);
  for (const std::string stem : {"my map #2", "map: v2", "[x]", "&a", "it's", "plain-name_1"}) {
    SCOPED_TRACE(stem);
    const std::string yaml = dir + "/" + stem + ".yaml";
    const CliResult decoded = RunCli({"decode", dir + "/a.lmap", "-o", yaml});
    ASSERT_EQ(decoded.exit_code, 0) << decoded.err;
    EXPECT_EQ(YAML::LoadFile(yaml)["image"].as<std::string>(), stem + ".pgm");
    const CliResult info = RunCli({"info", yaml, "--json"});
    EXPECT_EQ(info.exit_code, 0) << info.err;
    const CliResult eval = RunCli({"eval", arena, yaml, "--json"});
    ASSERT_EQ(eval.exit_code, 0) << eval.err;
    EXPECT_NE(eval.out.find("\"cells\":4800,\"cells_equal\":4800,"), std::string::npos) << eval.out;
  }
  EXPECT_EQ(testing::ReadFile(dir + "/plain-name_1.yaml").rfind("image: plain-name_1.pgm\n", 0),
            0u);
}

// An .lmap named like the files decode writes is refused, not replaced.
TEST(CmdDecodeTest, RefusesToOverwriteItsInput) {
  const std::string dir = testing::MakeTempDir("decode_self");
  const std::string arena = testing::BundledMapsDir() + "/navtut/lse_arena.yaml";
  ASSERT_EQ(RunCli({"encode", arena, "-o", dir + "/a.lmap"}).exit_code, 0);
  const std::string lmap = testing::ReadFile(dir + "/a.lmap");
  for (const std::string name : {"map.pgm", "map.yaml"}) {
    SCOPED_TRACE(name);
    testing::WriteFile(dir + "/" + name, lmap);
    const CliResult decoded = RunCli({"decode", dir + "/" + name, "-o", dir + "/map.yaml"});
    EXPECT_EQ(decoded.exit_code, 2) << decoded.out;
    EXPECT_NE(decoded.err.find("is the input file"), std::string::npos) << decoded.err;
    EXPECT_EQ(testing::ReadFile(dir + "/" + name), lmap);
  }
}

// An output that is only the extension names no file: decode said it "must
// end in .yaml or .yml", which it does.
TEST(CmdDecodeTest, OutputWithoutANameBeforeTheExtensionIsRefused) {
  const std::string dir = testing::MakeTempDir("decode_no_stem");
  const std::string lmap = testing::SourceDir() + "/tests/data/lmap/lse_arena_lossy.lmap";
  for (const std::string name : {".yaml", ".YML", "sub/.yaml"}) {
    const std::string out = dir + "/" + name;
    const CliResult r = RunCli({"decode", lmap, "-o", out});
    EXPECT_EQ(r.exit_code, 2) << name;
    EXPECT_NE(r.err.find("output '" + out + "' has no file name before "), std::string::npos)
        << r.err;
    EXPECT_EQ(r.err.find("must end in"), std::string::npos) << r.err;
  }
  EXPECT_TRUE(testing::ListDir(dir).empty());
}

}  // namespace
}  // namespace linemap
