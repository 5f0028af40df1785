// `linemap encode RECORDING.bag` (the CLI with ros/bag_reader.cc loaded) on
// bags written here with rosbag's C++ API. The files are encoded exactly
// (--lossless), so that they decode to the messages cell for cell.
#include <gtest/gtest.h>
#include <rosbag/bag.h>
#include <unistd.h>

#include <algorithm>
#include <climits>
#include <filesystem>
#include <string>
#include <vector>

#include "linemap/codec.h"
#include "ros/ros_messages.h"
#include "tests/ros/ros_maps.h"
#include "tests/testing/test_support.h"

namespace linemap::testing {
namespace {

using ros_bridge::MapMetaDataMsg;
using ros_bridge::OccupancyGridMsg;

// Three maps on /map (stamps 1700000000.5 + k s; the last one stamped zero,
// so it is named by its recording time), and map metadata on
// /map_metadata. Values between the thresholds are mixed in.
class BagTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = MakeTempDir("bag");
    bag_path_ = dir_ + "/recording.bag";
    const char* maps[] = {"nav2/depot.yaml", "navtut/lse_arena.yaml", "strands/kth/map.yaml"};
    rosbag::Bag bag;
    bag.open(bag_path_, rosbag::bagmode::Write);
    for (int k = 0; k < 3; ++k) {
      OccupancyGridMsg message = ReferenceMessage(LoadBundledMap(maps[k]), "map");
      for (std::size_t i = k; i < message.data.size(); i += 53) {
        message.data[i] = static_cast<std::int8_t>((i * 7) % 110);
      }
      message.info.origin.position.x = 1.5 * k;
      message.header.stamp = k < 2 ? ros::Time(1700000000 + k, 500000000) : ros::Time(0, 0);
      bag.write("/map", ros::Time(1800000000 + k, 7), message);
      MapMetaDataMsg meta = message.info;
      bag.write("/map_metadata", ros::Time(1800000000 + k, 8), meta);
      messages_.push_back(message);
    }
    bag.close();
  }

  void ExpectFileIsMessage(const std::string& path, int k) {
    SCOPED_TRACE(path);
    StatusOr<Grid> decoded = LoadLmap(path);
    ASSERT_TRUE(decoded.ok()) << decoded.status().message();
    ExpectGridIsMessage(*decoded, messages_[k], 0.05);
  }

  std::string dir_;
  std::string bag_path_;
  std::vector<OccupancyGridMsg> messages_;
};

TEST_F(BagTest, TopicGivesTheLastMap) {
  const CliResult result =
      RunCli({"encode", bag_path_, "--lossless", "--topic", "/map", "-o", dir_ + "/a.lmap"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  ExpectFileIsMessage(dir_ + "/a.lmap", 2);
  // A .bag input without --topic reads /map too.
  const CliResult plain = RunCli({"encode", bag_path_, "--lossless", "-o", dir_ + "/b.lmap"});
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  ExpectFileIsMessage(dir_ + "/b.lmap", 2);
}

TEST_F(BagTest, IndexGivesThatMap) {
  for (int k = 0; k < 3; ++k) {
    const std::string out = dir_ + "/i" + std::to_string(k) + ".lmap";
    const CliResult result = RunCli({"encode", bag_path_, "--lossless", "--topic", "map", "--index",
                                     std::to_string(k), "-o", out});
    ASSERT_EQ(result.exit_code, 0) << result.err;
    ExpectFileIsMessage(out, k);
  }
  const CliResult beyond = RunCli({"encode", bag_path_, "--index", "3", "-o", dir_ + "/x.lmap"});
  EXPECT_EQ(beyond.exit_code, 2);
  EXPECT_NE(beyond.err.find("holds 3 maps"), std::string::npos) << beyond.err;
  EXPECT_FALSE(FileExists(dir_ + "/x.lmap"));
}

TEST_F(BagTest, AllWritesEveryMapNamedByItsStamp) {
  const std::string out = dir_ + "/all";
  const CliResult result =
      RunCli({"encode", bag_path_, "--lossless", "--topic", "/map", "--all", "-o", out + "/"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const std::vector<std::string> expected = {
      "1700000000_500000000.lmap", "1700000001_500000000.lmap", "1800000002_000000007.lmap"};
  ASSERT_EQ(ListDir(out), expected);
  for (int k = 0; k < 3; ++k) ExpectFileIsMessage(out + "/" + expected[k], k);
}

// --all makes its folder with the first map written: a bag that cannot be
// read, or has no map on the topic, leaves no folder behind.
TEST_F(BagTest, AllLeavesNoFolderWhenNothingIsWritten) {
  WriteFile(dir_ + "/garbage.bag", "not a bag\n");
  const CliResult garbage =
      RunCli({"encode", dir_ + "/garbage.bag", "--all", "-o", dir_ + "/from_garbage"});
  EXPECT_EQ(garbage.exit_code, 2) << garbage.err;
  const CliResult no_topic =
      RunCli({"encode", bag_path_, "--topic", "/scan", "--all", "-o", dir_ + "/from_scan/"});
  EXPECT_EQ(no_topic.exit_code, 2) << no_topic.err;
  const std::vector<std::string> left = ListDir(dir_);
  EXPECT_EQ(std::count(left.begin(), left.end(), "from_garbage"), 0);
  EXPECT_EQ(std::count(left.begin(), left.end(), "from_scan"), 0);
}

// A folder --all made is taken back when its first file cannot be written.
// The write is made to fail by a folder name that fits the system's path
// limit (PATH_MAX) while the file names in it do not. A folder that was
// there before is kept.
TEST_F(BagTest, AllTakesBackItsFolderWhenTheFirstWriteFails) {
  constexpr std::size_t kPathMax = PATH_MAX;
  constexpr std::size_t kFileName = sizeof("/1700000000_500000000.lmap") - 1;
  std::string parent = dir_;
  while (parent.size() + 1 + 200 + 1 + 20 < kPathMax - kFileName) {
    parent += "/" + std::string(200, 'p');
  }
  ASSERT_TRUE(std::filesystem::create_directories(parent));
  std::string out = parent + "/";
  out += std::string(kPathMax - kFileName - out.size(), 'o');  // out + file name: >= PATH_MAX
  ASSERT_LT(out.size() + 1, kPathMax);                         // out itself fits
  const CliResult result =
      RunCli({"encode", bag_path_, "--lossless", "--topic", "/map", "--all", "-o", out});
  EXPECT_NE(result.exit_code, 0);
  EXPECT_NE(result.err.find("1700000000_500000000.lmap"), std::string::npos) << result.err;
  EXPECT_TRUE(ListDir(parent).empty());
  // The same failure into a folder made beforehand leaves that folder.
  ASSERT_TRUE(std::filesystem::create_directory(out));
  const CliResult again =
      RunCli({"encode", bag_path_, "--lossless", "--topic", "/map", "--all", "-o", out});
  EXPECT_NE(again.exit_code, 0);
  EXPECT_EQ(ListDir(parent).size(), 1u);
  std::filesystem::remove_all(dir_ + "/" + std::string(200, 'p'));  // 4 KB-long paths
}

TEST_F(BagTest, MissingTopicExitsTwoNamingWhatTheBagHolds) {
  const CliResult result =
      RunCli({"encode", bag_path_, "--topic", "/scan", "-o", dir_ + "/x.lmap"});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find(bag_path_), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("'/scan'"), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("/map (nav_msgs/OccupancyGrid, 3 messages)"), std::string::npos)
      << result.err;
  EXPECT_NE(result.err.find("/map_metadata (nav_msgs/MapMetaData, 3 messages)"), std::string::npos)
      << result.err;
  EXPECT_FALSE(FileExists(dir_ + "/x.lmap"));
}

// --json prints one object per map written (a line each), which a script
// parses; the file name's case does not hide a bag.
TEST_F(BagTest, JsonPrintsAnObjectPerMapWritten) {
  const CliResult one =
      RunCli({"encode", bag_path_, "--lossless", "--json", "--index", "1", "-o", dir_ + "/j.lmap"});
  ASSERT_EQ(one.exit_code, 0) << one.err;
  const std::string expected = "{\"topic\":\"/map\",\"index\":1,\"count\":3,\"width\":" +
                               std::to_string(messages_[1].info.width) +
                               ",\"height\":" + std::to_string(messages_[1].info.height) +
                               ",\"output\":\"" + dir_ + "/j.lmap\",\"bytes\":";
  EXPECT_EQ(one.out.rfind(expected, 0), 0u) << one.out;
  EXPECT_EQ(std::count(one.out.begin(), one.out.end(), '\n'), 1) << one.out;
  const CliResult all =
      RunCli({"encode", bag_path_, "--lossless", "--json", "--all", "-o", dir_ + "/all/"});
  ASSERT_EQ(all.exit_code, 0) << all.err;
  EXPECT_EQ(std::count(all.out.begin(), all.out.end(), '\n'), 3) << all.out;
  EXPECT_EQ(std::count(all.out.begin(), all.out.end(), '{'), 3) << all.out;
  ASSERT_EQ(::link(bag_path_.c_str(), (dir_ + "/UPPER.BAG").c_str()), 0);
  const CliResult upper = RunCli({"encode", dir_ + "/UPPER.BAG", "-o", dir_ + "/u.lmap"});
  EXPECT_EQ(upper.exit_code, 0) << upper.err;
  ExpectFileIsMessage(dir_ + "/u.lmap", 2);
}

// The bag options on a map YAML, an image or an .lmap say so, rather than
// the bag reader failing to read a YAML as a bag.
TEST_F(BagTest, BagOptionsOnAMapAreRefusedNamingThem) {
  const std::string map = testing::BundledMapsDir() + "/navtut/lse_arena.yaml";
  for (const std::vector<std::string>& option :
       {std::vector<std::string>{"--topic", "/map"}, {"--index", "0"}, {"--all"}}) {
    std::vector<std::string> argv = {"encode", map, "-o", dir_ + "/x.lmap"};
    argv.insert(argv.end(), option.begin(), option.end());
    const CliResult result = RunCli(argv);
    EXPECT_EQ(result.exit_code, 2) << option[0];
    EXPECT_NE(result.err.find("--topic, --index and --all read a ROS 1 bag; '" + map +
                              "' is a map or an .lmap file"),
              std::string::npos)
        << result.err;
  }
}

// --metadata stores the frame a message names (the fixture's is "map"; one
// in "world" keeps it) and its stamp as ISO 8601 UTC (1,700,000,001.5 s is
// 2023-11-14T22:13:21.5Z: `date -u -d @1700000001`), unless --time gives
// one.
TEST_F(BagTest, MetadataNamesTheMessagesFrameAndTime) {
  const std::string path = dir_ + "/world.bag";
  rosbag::Bag bag;
  bag.open(path, rosbag::bagmode::Write);
  OccupancyGridMsg message = messages_[1];
  message.header.frame_id = "world";
  bag.write("/map", ros::Time(1800000000, 7), message);
  bag.close();
  ASSERT_EQ(RunCli({"encode", path, "--metadata", "-o", dir_ + "/w.lmap"}).exit_code, 0);
  StatusOr<LmapContents> contents = LoadLmapContents(dir_ + "/w.lmap");
  ASSERT_TRUE(contents.ok());
  EXPECT_NE(std::find(contents->metadata.begin(), contents->metadata.end(),
                      std::pair<std::string, std::string>{"frame_id", "world"}),
            contents->metadata.end());
  EXPECT_NE(std::find(contents->metadata.begin(), contents->metadata.end(),
                      std::pair<std::string, std::string>{"time", "2023-11-14T22:13:21.5Z"}),
            contents->metadata.end());
  ASSERT_EQ(RunCli({"encode", path, "--metadata", "--time", "2024-05-01", "-o", dir_ + "/t.lmap"})
                .exit_code,
            0);
  StatusOr<LmapContents> timed = LoadLmapContents(dir_ + "/t.lmap");
  ASSERT_TRUE(timed.ok());
  EXPECT_NE(std::find(timed->metadata.begin(), timed->metadata.end(),
                      std::pair<std::string, std::string>{"time", "2024-05-01"}),
            timed->metadata.end());
}

// A map of no cells in a bag is refused when it is read, not saved as a
// file that no map server could serve.
TEST_F(BagTest, MapOfNoCellsIsRefused) {
  const std::string path = dir_ + "/empty_map.bag";
  rosbag::Bag bag;
  bag.open(path, rosbag::bagmode::Write);
  OccupancyGridMsg message = messages_[1];
  message.info.width = 0;
  message.info.height = 0;
  message.data.clear();
  bag.write("/map", ros::Time(1800000000, 7), message);
  bag.close();
  const CliResult result = RunCli({"encode", path, "-o", dir_ + "/e.lmap"});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find("a map of 0 x 0 cells: nothing to save"), std::string::npos)
      << result.err;
  EXPECT_FALSE(FileExists(dir_ + "/e.lmap"));
}

TEST_F(BagTest, TopicOfAnotherTypeExitsTwo) {
  const CliResult result =
      RunCli({"encode", bag_path_, "--topic", "/map_metadata", "-o", dir_ + "/x.lmap"});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find(bag_path_), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("'/map_metadata' holds nav_msgs/MapMetaData, not "
                            "nav_msgs/OccupancyGrid"),
            std::string::npos)
      << result.err;
  EXPECT_FALSE(FileExists(dir_ + "/x.lmap"));
}

// A bag's maps have no vector layers to limit: --max-segments and
// --max-objects are refused (exit 2, naming the bag), one map or all, and
// nothing is written.
TEST_F(BagTest, LayerLimitsAreRefused) {
  for (const char* option : {"--max-segments", "--max-objects"}) {
    for (const std::vector<std::string>& selection :
         {std::vector<std::string>{"-o", dir_ + "/x.lmap"},
          std::vector<std::string>{"--all", "-o", dir_ + "/all"}}) {
      std::vector<std::string> argv = {"encode", bag_path_, option, "1000"};
      argv.insert(argv.end(), selection.begin(), selection.end());
      const CliResult result = RunCli(argv);
      SCOPED_TRACE(std::string(option) + " " + selection[0] + ": " + result.err);
      EXPECT_EQ(result.exit_code, 2);
      EXPECT_NE(result.err.find(std::string(option) + " limits the vector layers of .lmap files"),
                std::string::npos);
      EXPECT_NE(result.err.find(bag_path_), std::string::npos);
    }
  }
  EXPECT_FALSE(FileExists(dir_ + "/x.lmap"));
  EXPECT_FALSE(FileExists(dir_ + "/all"));
}

// An OccupancyGrid message has its own resolution and origin and no pixels
// to negate or scale: the options that read images are refused (exit 2,
// naming the bag and the option), not silently ignored, and nothing is
// written.
TEST_F(BagTest, ImageOptionsAreRefused) {
  const std::vector<std::vector<std::string>> options = {
      {"--resolution", "0.1"}, {"--origin", "1,2"}, {"--negate"}, {"--mode", "scale"}};
  for (const std::vector<std::string>& option : options) {
    std::vector<std::string> argv = {"encode", bag_path_, "-o", dir_ + "/x.lmap"};
    argv.insert(argv.end(), option.begin(), option.end());
    const CliResult result = RunCli(argv);
    SCOPED_TRACE(option[0] + ": " + result.err);
    EXPECT_EQ(result.exit_code, 2);
    EXPECT_NE(result.err.find(option[0] + " reads map images and YAMLs"), std::string::npos);
    EXPECT_NE(result.err.find(bag_path_), std::string::npos);
  }
  EXPECT_FALSE(FileExists(dir_ + "/x.lmap"));
}

// The thresholds read the messages' occupancies: a value is free at or
// below the free percent (map_saver's 25 by default), so --free-thresh 0.0
// leaves free only the cells of occupancy 0. Counted here on the message.
TEST_F(BagTest, ThresholdsApplyToTheMessages) {
  std::size_t zero = 0;
  std::size_t up_to_25 = 0;
  for (const std::int8_t value : messages_[0].data) {
    zero += value == 0;
    up_to_25 += value >= 0 && value <= 25;
  }
  ASSERT_LT(zero, up_to_25);  // the mixed-in values include 1..25
  for (const bool thresh : {false, true}) {
    std::vector<std::string> argv = {"encode", bag_path_, "--lossless",    "--index",
                                     "0",      "-o",      dir_ + "/x.lmap"};
    if (thresh) argv.insert(argv.end(), {"--free-thresh", "0.0"});
    const CliResult result = RunCli(argv);
    ASSERT_EQ(result.exit_code, 0) << result.err;
    StatusOr<Grid> decoded = LoadLmap(dir_ + "/x.lmap");
    ASSERT_TRUE(decoded.ok()) << decoded.status().message();
    EXPECT_EQ(decoded->Count().free, thresh ? zero : up_to_25);
  }
}

TEST_F(BagTest, NotABagExitsTwo) {
  const std::string fake = dir_ + "/fake.bag";
  WriteFile(fake, "not a bag at all");
  const CliResult result = RunCli({"encode", fake, "-o", dir_ + "/x.lmap"});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find(fake), std::string::npos) << result.err;
}

}  // namespace
}  // namespace linemap::testing
