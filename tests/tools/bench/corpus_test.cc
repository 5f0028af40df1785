#include "tools/bench/corpus.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "tests/testing/test_support.h"

namespace linemap::bench {
namespace {

using linemap::testing::MakeTempDir;
using linemap::testing::WriteFile;

std::vector<std::string> Names(const std::vector<CorpusMap>& maps) {
  std::vector<std::string> names;
  for (const CorpusMap& m : maps) names.push_back(m.name + (m.bare_image ? " (bare)" : ""));
  return names;
}

TEST(BenchCorpusTest, FindsYamlsAndOnlyTheImagesNoYamlNames) {
  const std::string dir = MakeTempDir("bench-corpus");
  std::filesystem::create_directories(dir + "/site/floor1");
  WriteFile(dir + "/a.yaml", "image: a.pgm\nresolution: 0.05\norigin: [0, 0, 0]\n");
  WriteFile(dir + "/a.pgm", "P5 1 1 255\n\xfe");
  WriteFile(dir + "/b.png", "not really a png");
  WriteFile(dir + "/site/floor1/map.yml", "image: \"../shared.PGM\"\n");
  WriteFile(dir + "/site/shared.PGM", "P5 1 1 255\n\x00");
  WriteFile(dir + "/site/missing.yaml", "image: nowhere.pgm\n");
  WriteFile(dir + "/site/notes.txt", "ignored");
  StatusOr<std::vector<CorpusMap>> maps = DiscoverCorpus({dir});
  ASSERT_TRUE(maps.ok()) << maps.status().message();
  EXPECT_EQ(Names(*maps),
            (std::vector<std::string>{"a", "b (bare)", "site/floor1/map", "site/missing"}));
}

TEST(BenchCorpusTest, KeepsTheOrderOfTheFolders) {
  const std::string first = MakeTempDir("bench-corpus-z");
  const std::string second = MakeTempDir("bench-corpus-a");
  WriteFile(first + "/z.pgm", "P5 1 1 255\n\xfe");
  WriteFile(second + "/a.pgm", "P5 1 1 255\n\xfe");
  StatusOr<std::vector<CorpusMap>> maps = DiscoverCorpus({first, second});
  ASSERT_TRUE(maps.ok());
  EXPECT_EQ(Names(*maps), (std::vector<std::string>{"z (bare)", "a (bare)"}));
}

TEST(BenchCorpusTest, AMissingFolderIsNotFound) {
  StatusOr<std::vector<CorpusMap>> maps = DiscoverCorpus({"/nonexistent/linemap/corpus"});
  ASSERT_FALSE(maps.ok());
  EXPECT_EQ(maps.status().code(), StatusCode::kNotFound);
}

TEST(BenchCorpusTest, YamlImagePathResolvesAgainstTheYamlFolder) {
  const std::string dir = MakeTempDir("bench-yaml");
  WriteFile(dir + "/m.yaml", "image: sub/../m.pgm\n");
  EXPECT_EQ(YamlImagePath(dir + "/m.yaml"),
            std::filesystem::path(dir + "/m.pgm").lexically_normal().string());
  WriteFile(dir + "/broken.yaml", "image: [unclosed\n");
  EXPECT_EQ(YamlImagePath(dir + "/broken.yaml"), "");
}

TEST(BenchCorpusTest, BundledCorpusHasTheFourBundledMaps) {
  StatusOr<std::vector<CorpusMap>> maps = DiscoverCorpus({linemap::testing::BundledMapsDir()});
  ASSERT_TRUE(maps.ok());
  EXPECT_EQ(Names(*maps),
            (std::vector<std::string>{"nav2/depot", "navtut/lse_arena", "strands/kth/map",
                                      "turtlebot_apps/willow-2010-02-18-0.10"}));
}

TEST(BenchCorpusTest, SharedCorpusListsTheBareImagesOfItsManifest) {
  const std::string shared = linemap::testing::SharedMapsDir();
  if (shared.empty()) GTEST_SKIP() << "../shared/maps is absent";
  StatusOr<std::vector<CorpusMap>> maps = DiscoverCorpus({shared});
  ASSERT_TRUE(maps.ok());
  std::vector<std::string> bare;
  for (const CorpusMap& m : *maps) {
    if (m.bare_image) bare.push_back(m.name);
  }
  // MANIFEST.tsv: the four images without a YAML, and empty_room.pgm, whose
  // YAML names a missing empty.pgm.
  EXPECT_EQ(bare, (std::vector<std::string>{"mrpt/map1", "nav2/empty_room", "nav2/map",
                                            "rosnav1/willow-full-0.05", "stage_ros/willow-full"}));
}

}  // namespace
}  // namespace linemap::bench
