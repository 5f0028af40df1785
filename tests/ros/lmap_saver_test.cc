// lmap_saver on a real rosmaster: the file it writes decodes to the map that
// was published, --every keeps the last one, and a saver killed while it
// writes leaves the previous file whole.
#include <dirent.h>
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/time.h>
#include <unistd.h>

#include <algorithm>
#include <climits>
#include <cstdio>
#include <ctime>
#include <sstream>
#include <string>

#include "format/file_io.h"
#include "linemap/codec.h"
#include "linemap/lmap_vectors.h"
#include "ros/ros_messages.h"
#include "tests/ros/ros_maps.h"
#include "tests/ros/ros_test_support.h"
#include "tests/testing/test_support.h"

namespace linemap::testing {
namespace {

using ros_bridge::OccupancyGridMsg;

std::unique_ptr<ChildProcess> StartSaver(RosMaster& master, const std::string& topic,
                                         const std::string& name, std::vector<std::string> extra) {
  std::vector<std::string> argv = {LmapSaverPath(), "-t", topic, "-f", name};
  argv.insert(argv.end(), extra.begin(), extra.end());
  return std::make_unique<ChildProcess>(argv, master.Env(), master.scratch(),
                                        "saver" + std::to_string(Now()));
}

// True when `path` holds an .lmap that decodes to exactly `grid`'s cells
// and size.
bool FileHoldsCells(const std::string& path, const Grid& grid) {
  StatusOr<Grid> decoded = LoadLmap(path);
  return decoded.ok() && decoded->width() == grid.width() && decoded->height() == grid.height() &&
         decoded->cells() == grid.cells();
}

// The map messages of the tests: bundled maps with values between the
// thresholds mixed in, so that the saver's reading of them is checked too.
OccupancyGridMsg MessageWithLevels(const Grid& grid) {
  OccupancyGridMsg message = ReferenceMessage(grid, "map");
  const std::int8_t levels[] = {10, 25, 26, 64, 65, 90, -7};
  for (std::size_t i = 0; i < message.data.size(); i += 97) {
    message.data[i] = levels[(i / 97) % 7];
  }
  return message;
}

// The grid the saver must write for `message`, by the reference reading.
Grid ExpectedGrid(const OccupancyGridMsg& message) {
  Grid grid(static_cast<int>(message.info.width), static_cast<int>(message.info.height));
  for (std::size_t i = 0; i < message.data.size(); ++i) {
    grid.mutable_cells()[i] = ReferenceCell(message.data[i]);
  }
  return grid;
}

TEST(LmapSaverTest, WritesThePublishedMapAndExits) {
  RosMaster& master = SharedMaster();
  ros::NodeHandle nh;
  ros::Publisher publisher = nh.advertise<OccupancyGridMsg>("/v1/map", 1, /*latch=*/true);
  OccupancyGridMsg message = MessageWithLevels(LoadBundledMap("strands/kth/map.yaml"));
  message.info.origin.position.x = -7.0;
  message.info.origin.position.y = -17.5;
  message.info.origin.orientation.z = std::sin(0.25);  // yaw 0.5 rad
  message.info.origin.orientation.w = std::cos(0.25);
  publisher.publish(message);
  const std::string dir = MakeTempDir("saver");
  auto saver = StartSaver(master, "/v1/map", dir + "/saved", {});
  const std::optional<int> code = saver->Wait(20);
  ASSERT_TRUE(code.has_value()) << "lmap_saver did not exit";
  EXPECT_EQ(*code, 0) << saver->Stderr();
  StatusOr<Grid> decoded = LoadLmap(dir + "/saved.lmap");
  ASSERT_TRUE(decoded.ok()) << decoded.status().message();
  ExpectGridIsMessage(*decoded, message, 0.05);
  EXPECT_EQ(ListDir(dir), std::vector<std::string>{"saved.lmap"});
}

// --compact saves a version 2.3 file that still reads back as the map.
TEST(LmapSaverTest, CompactSavesAVersionTwoThreeFileOfTheMap) {
  RosMaster& master = SharedMaster();
  ros::NodeHandle nh;
  ros::Publisher publisher = nh.advertise<OccupancyGridMsg>("/v6/map", 1, /*latch=*/true);
  const OccupancyGridMsg message = MessageWithLevels(LoadBundledMap("nav2/depot.yaml"));
  publisher.publish(message);
  const std::string dir = MakeTempDir("saver_compact");
  auto saver = StartSaver(master, "/v6/map", dir + "/saved", {"--compact", "--raster-only"});
  const std::optional<int> code = saver->Wait(20);
  ASSERT_TRUE(code.has_value()) << "lmap_saver did not exit";
  EXPECT_EQ(*code, 0) << saver->Stderr();
  StatusOr<LmapContents> contents = LoadLmapContents(dir + "/saved.lmap");
  ASSERT_TRUE(contents.ok()) << contents.status().message();
  EXPECT_EQ(contents->minor, 3);
  EXPECT_TRUE(contents->walls.empty());
  EXPECT_TRUE(FileHoldsCells(dir + "/saved.lmap", ExpectedGrid(message)));
}

TEST(LmapSaverTest, EveryRewritesTheFileAndLeavesTheLastMap) {
  RosMaster& master = SharedMaster();
  ros::NodeHandle nh;
  ros::Publisher publisher = nh.advertise<OccupancyGridMsg>("/v2/map", 3, /*latch=*/true);
  const OccupancyGridMsg maps[] = {MessageWithLevels(LoadBundledMap("nav2/depot.yaml")),
                                   MessageWithLevels(LoadBundledMap("navtut/lse_arena.yaml")),
                                   MessageWithLevels(LoadBundledMap("strands/kth/map.yaml"))};
  const std::string dir = MakeTempDir("every");
  const std::string path = dir + "/robot.lmap";
  auto saver = StartSaver(master, "/v2/map", dir + "/robot", {"--every"});
  publisher.publish(maps[0]);
  ASSERT_TRUE(WaitFor([&] { return FileHoldsCells(path, ExpectedGrid(maps[0])); }, 20))
      << saver->Stderr();
  publisher.publish(maps[1]);
  ASSERT_TRUE(WaitFor([&] { return FileHoldsCells(path, ExpectedGrid(maps[1])); }, 20))
      << saver->Stderr();
  publisher.publish(maps[2]);
  ASSERT_TRUE(WaitFor([&] { return FileHoldsCells(path, ExpectedGrid(maps[2])); }, 20))
      << saver->Stderr();
  EXPECT_FALSE(saver->Wait(0.2).has_value()) << "--every exited after a map";
  EXPECT_EQ(saver->Stop(SIGINT), 0) << saver->Stderr();
  StatusOr<Grid> decoded = LoadLmap(path);
  ASSERT_TRUE(decoded.ok()) << decoded.status().message();
  ExpectGridIsMessage(*decoded, maps[2], 0.05);
  EXPECT_EQ(ListDir(dir), std::vector<std::string>{"robot.lmap"});
}

// The acceptance: a map served by lmap_server and saved by
// lmap_saver comes back exactly, cells, resolution and origin.
TEST(LmapSaverTest, ServedMapSavesBackExactly) {
  RosMaster& master = SharedMaster();
  const std::string lmap = SourceDir() + "/tests/data/lmap/lse_arena_lossless.lmap";
  StatusOr<Grid> original = LoadLmap(lmap);
  ASSERT_TRUE(original.ok()) << original.status().message();
  ChildProcess server({LmapServerPath(), lmap, "__ns:=/r1"}, master.Env(), master.scratch(),
                      "server-r1");
  const std::string dir = MakeTempDir("roundtrip");
  auto saver = StartSaver(master, "/r1/map", dir + "/saved", {});
  ASSERT_EQ(saver->Wait(20).value_or(-1), 0) << saver->Stderr() << server.Stderr();
  StatusOr<Grid> saved = LoadLmap(dir + "/saved.lmap");
  ASSERT_TRUE(saved.ok()) << saved.status().message();
  EXPECT_EQ(saved->width(), original->width());
  EXPECT_EQ(saved->height(), original->height());
  EXPECT_TRUE(saved->cells() == original->cells());
  EXPECT_EQ(saved->meta.resolution, original->meta.resolution);
  EXPECT_EQ(saved->meta.origin, original->meta.origin);
}

// True while process `pid` has a file open under `dir` (the temporary file
// of a save: the output is written to an unnamed file in its folder).
bool WritesUnder(pid_t pid, const std::string& dir) {
  const std::string fds = "/proc/" + std::to_string(pid) + "/fd";
  DIR* listing = ::opendir(fds.c_str());
  if (listing == nullptr) return false;
  bool found = false;
  while (const dirent* entry = ::readdir(listing)) {
    char target[PATH_MAX];
    const ssize_t n = ::readlink((fds + "/" + entry->d_name).c_str(), target, sizeof(target) - 1);
    if (n > 0 && std::string(target, n).starts_with(dir + "/")) {
      found = true;
      break;
    }
  }
  ::closedir(listing);
  return found;
}

ino_t Inode(const std::string& path) {
  struct stat info {};
  return ::stat(path.c_str(), &info) == 0 ? info.st_ino : 0;
}

TEST(LmapSaverTest, SaverKilledWhileWritingLeavesTheOldFileWhole) {
  RosMaster& master = SharedMaster();
  ros::NodeHandle nh;
  ros::Publisher publisher = nh.advertise<OccupancyGridMsg>("/v3/map", 1, /*latch=*/true);
  const OccupancyGridMsg old_map = MessageWithLevels(LoadBundledMap("nav2/depot.yaml"));
  const std::string dir = MakeTempDir("killed");
  const std::string path = dir + "/robot.lmap";
  // Each try: a saver writes the old map, then gets a large map (noise:
  // a file of ~40 KB, written and flushed over milliseconds) and is killed
  // as soon as it holds a file open in the output folder. A try whose kill
  // came after the rename is repeated.
  int killed_while_writing = 0;
  for (int attempt = 0; attempt < 5 && killed_while_writing == 0; ++attempt) {
    publisher.publish(old_map);
    auto saver = StartSaver(master, "/v3/map", path, {"--every"});
    ASSERT_TRUE(WaitFor([&] { return FileHoldsCells(path, ExpectedGrid(old_map)); }, 20))
        << saver->Stderr();
    const OccupancyGridMsg big = ReferenceMessage(NoiseMap(400, 400, attempt + 1), "map");
    const ino_t old_inode = Inode(path);
    publisher.publish(big);
    const double deadline = Now() + 30;
    // Until the saver holds the temporary file open, or has renamed it
    // over the old one already (this try came too late), or has died.
    while (!WritesUnder(saver->pid(), dir) && Inode(path) == old_inode && Now() < deadline &&
           !saver->Wait(0)) {
    }
    ::kill(saver->pid(), SIGKILL);
    ASSERT_EQ(saver->Wait(5).value_or(-1), 128 + SIGKILL) << saver->Stderr();
    // Whole either way: the old map, or the new one when the kill came late.
    const bool old_whole = FileHoldsCells(path, ExpectedGrid(old_map));
    const bool new_whole = FileHoldsCells(path, ExpectedGrid(big));
    ASSERT_TRUE(old_whole || new_whole) << "try " << attempt << ": " << path << " is broken";
    // A kill in the instant between naming the temporary and the rename
    // leaves it beside the file; nothing else may be there.
    for (const std::string& name : ListDir(dir)) {
      EXPECT_TRUE(name == "robot.lmap" || name.starts_with("robot.lmap.linemap-tmp-")) << name;
    }
    killed_while_writing += old_whole;
    std::printf("try %d: killed %s the rename\n", attempt, old_whole ? "before" : "after");
  }
  EXPECT_EQ(killed_while_writing, 1) << "no kill landed while the saver wrote";
  // The next save removes such a leftover once it is old enough to belong
  // to no live save (aged here rather than waited for).
  for (const std::string& name : ListDir(dir)) {
    if (name == "robot.lmap") continue;
    const std::time_t then = std::time(nullptr) - kStaleTemporarySeconds - 5;
    const struct timeval times[2] = {{then, 0}, {then, 0}};
    ASSERT_EQ(::utimes((dir + "/" + name).c_str(), times), 0) << name;
  }
  publisher.publish(old_map);
  auto saver = StartSaver(master, "/v3/map", path, {});
  ASSERT_EQ(saver->Wait(20).value_or(-1), 0) << saver->Stderr();
  EXPECT_TRUE(FileHoldsCells(path, ExpectedGrid(old_map)));
  EXPECT_EQ(ListDir(dir), std::vector<std::string>{"robot.lmap"});
}

TEST(LmapSaverTest, MalformedMapExitsTwoWithoutAFile) {
  RosMaster& master = SharedMaster();
  ros::NodeHandle nh;
  ros::Publisher publisher = nh.advertise<OccupancyGridMsg>("/v4/map", 1, /*latch=*/true);
  OccupancyGridMsg message = ReferenceMessage(LoadBundledMap("nav2/depot.yaml"), "map");
  message.data.resize(message.data.size() - 1);  // one value short of width x height
  publisher.publish(message);
  const std::string dir = MakeTempDir("malformed");
  auto saver = StartSaver(master, "/v4/map", dir + "/saved", {});
  EXPECT_EQ(saver->Wait(20).value_or(-1), 2);
  EXPECT_NE(saver->Stderr().find("/v4/map"), std::string::npos) << saver->Stderr();
  EXPECT_TRUE(ListDir(dir).empty());
}

// With --every one bad message does not end a robot's periodic save: it is
// reported, the last good file stays, the next map is saved, and the exit
// code on shutdown says the last save went well.
TEST(LmapSaverTest, EveryKeepsSavingAfterAMalformedMap) {
  RosMaster& master = SharedMaster();
  ros::NodeHandle nh;
  ros::Publisher publisher = nh.advertise<OccupancyGridMsg>("/v5/map", 1, /*latch=*/true);
  const OccupancyGridMsg good = MessageWithLevels(LoadBundledMap("navtut/lse_arena.yaml"));
  OccupancyGridMsg bad = ReferenceMessage(LoadBundledMap("nav2/depot.yaml"), "map");
  bad.data.resize(bad.data.size() - 1);  // one value short of width x height
  const std::string dir = MakeTempDir("every_bad");
  const std::string path = dir + "/robot.lmap";
  auto saver = StartSaver(master, "/v5/map", dir + "/robot", {"--every"});
  publisher.publish(good);
  ASSERT_TRUE(WaitFor([&] { return FileHoldsCells(path, ExpectedGrid(good)); }, 20))
      << saver->Stderr();
  publisher.publish(bad);
  ASSERT_TRUE(WaitFor([&] { return saver->Stderr().find("/v5/map") != std::string::npos; }, 20))
      << saver->Stderr();
  EXPECT_FALSE(saver->Wait(0.5).has_value()) << "--every exited on a bad map: " << saver->Stderr();
  EXPECT_TRUE(FileHoldsCells(path, ExpectedGrid(good)));
  const OccupancyGridMsg next = MessageWithLevels(LoadBundledMap("nav2/depot.yaml"));
  publisher.publish(next);
  ASSERT_TRUE(WaitFor([&] { return FileHoldsCells(path, ExpectedGrid(next)); }, 20))
      << saver->Stderr();
  EXPECT_EQ(saver->Stop(SIGINT), 0) << saver->Stderr();
  EXPECT_EQ(ListDir(dir), std::vector<std::string>{"robot.lmap"});
}

// --metadata stores the saver, the message's frame and its stamp as ISO
// 8601 UTC; without it the file holds no metadata (the same map gives the
// same bytes). 1,700,000,000.25 s is 2023-11-14T22:13:20.25Z (`date -u -d
// @1700000000`).
TEST(LmapSaverTest, MetadataStoresTheFrameAndTheStamp) {
  RosMaster& master = SharedMaster();
  ros::NodeHandle nh;
  ros::Publisher publisher = nh.advertise<OccupancyGridMsg>("/v9/map", 1, /*latch=*/true);
  OccupancyGridMsg message = MessageWithLevels(LoadBundledMap("navtut/lse_arena.yaml"));
  message.header.frame_id = "floor_2";
  message.header.stamp = ros::Time(1700000000, 250000000);
  publisher.publish(message);
  const std::string dir = MakeTempDir("saver_metadata");
  for (const bool metadata : {true, false}) {
    const std::string name = dir + (metadata ? "/with" : "/without");
    auto saver =
        StartSaver(master, "/v9/map", name,
                   metadata ? std::vector<std::string>{"--metadata"} : std::vector<std::string>{});
    const std::optional<int> code = saver->Wait(20);
    ASSERT_TRUE(code.has_value()) << "lmap_saver did not exit";
    ASSERT_EQ(*code, 0) << saver->Stderr();
    StatusOr<LmapHeader> header = LoadLmapHeader(name + ".lmap");
    ASSERT_TRUE(header.ok()) << header.status().message();
    if (!metadata) {
      EXPECT_TRUE(header->metadata.empty());
      continue;
    }
    ASSERT_EQ(header->metadata.size(), 3u);
    EXPECT_EQ(header->metadata[0].first, "creator");
    EXPECT_EQ(header->metadata[0].second.rfind("linemap lmap_saver ", 0), 0u)
        << header->metadata[0].second;
    EXPECT_EQ(header->metadata[1],
              (std::pair<std::string, std::string>{"time", "2023-11-14T22:13:20.25Z"}));
    EXPECT_EQ(header->metadata[2], (std::pair<std::string, std::string>{"frame_id", "floor_2"}));
    EXPECT_TRUE(FileHoldsCells(name + ".lmap", ExpectedGrid(message)));
  }
}

// An output that cannot be written is refused at startup, before the master
// is waited for (none runs here), naming it: not when a map arrives.
TEST(LmapSaverTest, UnwritableOutputExitsTwoAtStartup) {
  const std::string scratch = MakeTempDir("unwritable");
  // A missing folder, and a folder where the file should go (".lmap" is
  // added to a name without it, so the folder has it already).
  ASSERT_EQ(::mkdir((scratch + "/folder.lmap").c_str(), 0755), 0);
  for (const std::string& name : {scratch + "/nodir/map", scratch + "/folder.lmap"}) {
    ChildProcess saver({LmapSaverPath(), "-f", name, "--every", "--wait-master", "60"},
                       {"ROS_MASTER_URI=http://127.0.0.1:1/", "ROS_HOME=" + scratch}, scratch,
                       "saver");
    const std::optional<int> code = saver.Wait(10);
    ASSERT_TRUE(code.has_value()) << name << ": still running after 10 s";
    EXPECT_EQ(*code, 2) << name << ": " << saver.Stderr();
    EXPECT_NE(saver.Stderr().find(name), std::string::npos) << saver.Stderr();
    EXPECT_EQ(saver.Stderr().find("no ROS master"), std::string::npos) << saver.Stderr();
  }
}

TEST(LmapSaverTest, NoMasterExitsOneWithinTheWait) {
  const std::string uri = "http://127.0.0.1:" + std::to_string(FreePort()) + "/";
  const std::string scratch = MakeTempDir("nomaster");
  const double start = Now();
  ChildProcess saver({LmapSaverPath(), "-f", scratch + "/x", "--wait-master", "1.5"},
                     {"ROS_MASTER_URI=" + uri, "ROS_HOME=" + scratch}, scratch, "saver");
  const std::optional<int> code = saver.Wait(10);
  const double seconds = Now() - start;
  ASSERT_TRUE(code.has_value()) << "still waiting after 10 s";
  EXPECT_EQ(*code, 1);
  EXPECT_GE(seconds, 1.5);
  EXPECT_LT(seconds, 5.0);
  EXPECT_NE(saver.Stderr().find("no ROS master"), std::string::npos) << saver.Stderr();
  EXPECT_FALSE(FileExists(scratch + "/x.lmap"));
}

// Thresholds are checked at startup as the library reads a map with them,
// in whole percents: --free 64.6 --occ 65 is 65 % both, refused here rather
// than when the first map arrives.
TEST(LmapSaverTest, BadOptionExitsTwo) {
  const std::string scratch = MakeTempDir("badopt");
  for (const std::vector<std::string>& thresholds :
       {std::vector<std::string>{"--occ", "20", "--free", "30"},
        std::vector<std::string>{"--occ", "65", "--free", "64.6"}}) {
    std::vector<std::string> argv = {LmapSaverPath()};
    argv.insert(argv.end(), thresholds.begin(), thresholds.end());
    ChildProcess saver(argv, {"ROS_MASTER_URI=http://127.0.0.1:1/", "ROS_HOME=" + scratch}, scratch,
                       "saver");
    EXPECT_EQ(saver.Wait(10).value_or(-1), 2) << thresholds[3];
    EXPECT_NE(saver.Stderr().find("--free / --occ: thresholds must satisfy 0 <= free < occupied"),
              std::string::npos)
        << saver.Stderr();
  }
}

// --tolerance is checked at startup (not when a map arrives, which with
// --every may be hours later): a whole number 0..4, else exit 2 naming the
// range. 1e10 is out of an int's range, so it must be refused before any
// conversion to int.
TEST(LmapSaverTest, ToleranceOutsideZeroToFourExitsTwoAtStartup) {
  const std::string scratch = MakeTempDir("tolerance");
  for (const std::string value : {"5", "1e10", "-1", "1.5", "-1e10"}) {
    ChildProcess saver({LmapSaverPath(), "--tolerance", value, "--every", "--wait-master", "60"},
                       {"ROS_MASTER_URI=http://127.0.0.1:1/", "ROS_HOME=" + scratch}, scratch,
                       "saver");
    const std::optional<int> code = saver.Wait(10);
    ASSERT_TRUE(code.has_value()) << "--tolerance " << value << ": still running after 10 s";
    EXPECT_EQ(*code, 2) << value << ": " << saver.Stderr();
    EXPECT_NE(saver.Stderr().find("0..4"), std::string::npos) << value << ": " << saver.Stderr();
  }
  // 0 and 4 are taken: the saver goes on to wait for the master (none here).
  for (const std::string value : {"0", "4"}) {
    ChildProcess saver({LmapSaverPath(), "--tolerance", value, "--wait-master", "0"},
                       {"ROS_MASTER_URI=http://127.0.0.1:1/", "ROS_HOME=" + scratch}, scratch,
                       "saver");
    EXPECT_EQ(saver.Wait(10).value_or(-1), 1) << value << ": " << saver.Stderr();
    EXPECT_NE(saver.Stderr().find("no ROS master"), std::string::npos) << saver.Stderr();
  }
}

// The median of `values`.
double Median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : (values[n / 2 - 1] + values[n / 2]) / 2;
}

std::string OneDecimal(double value) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.1f", value);
  return text;
}

// The usage text quotes the decode time of --compact files as the
// benchmark measured it (tools/bench/results/results.csv, one row per map):
// the medians of the maps' decode times, and the median and largest ratio
// per map.
TEST(LmapSaverTest, UsageQuotesTheMeasuredCompactDecodeTimes) {
  std::istringstream csv(ReadFile(SourceDir() + "/tools/bench/results/results.csv"));
  auto split = [](const std::string& line) {
    std::vector<std::string> fields;
    std::istringstream stream(line);
    std::string field;
    while (std::getline(stream, field, ',')) fields.push_back(field);
    return fields;
  };
  std::string line;
  ASSERT_TRUE(std::getline(csv, line));
  const std::vector<std::string> header = split(line);
  const auto column = [&](const std::string& name) {
    return std::find(header.begin(), header.end(), name) - header.begin();
  };
  const std::size_t compact_ms = column("lmap2_compact_decode_ms");
  const std::size_t exact_ms = column("lmap2_decode_ms");
  ASSERT_LT(compact_ms, header.size());
  ASSERT_LT(exact_ms, header.size());
  std::vector<double> compact, exact, ratios;
  while (std::getline(csv, line)) {
    const std::vector<std::string> fields = split(line);
    ASSERT_GT(fields.size(), std::max(compact_ms, exact_ms)) << line;
    compact.push_back(std::stod(fields[compact_ms]));
    exact.push_back(std::stod(fields[exact_ms]));
    ratios.push_back(compact.back() / exact.back());
  }
  ASSERT_GE(ratios.size(), 20u);
  const std::string scratch = MakeTempDir("usage");
  ChildProcess saver({LmapSaverPath(), "--help"}, {"ROS_HOME=" + scratch}, scratch, "saver");
  ASSERT_EQ(saver.Wait(10).value_or(-1), 0) << saver.Stderr();
  // The text wraps its lines: compare it with single spaces.
  std::string usage;
  for (const char c : saver.Stdout()) {
    if (c == ' ' || c == '\n') {
      if (!usage.empty() && usage.back() != ' ') usage += ' ';
    } else {
      usage += c;
    }
  }
  const std::string figures = OneDecimal(Median(compact) / Median(exact)) + "x the decode time (" +
                              OneDecimal(Median(compact)) + " against " +
                              OneDecimal(Median(exact)) + " ms at the median; a median " +
                              OneDecimal(Median(ratios)) + "x per map, up to " +
                              OneDecimal(*std::max_element(ratios.begin(), ratios.end())) + "x)";
  EXPECT_NE(usage.find(figures), std::string::npos) << "expected: " << figures << "\n" << usage;
}

}  // namespace
}  // namespace linemap::testing
