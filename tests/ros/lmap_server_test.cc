// lmap_server on a real rosmaster: what a subscriber, a service client and
// `rostopic` receive is the map, cell for cell.
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <signal.h>

#include <algorithm>
#include <boost/function.hpp>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <string>
#include <tuple>
#include <vector>

#include "linemap/codec.h"
#include "linemap/lmap_vectors.h"
#include "ros/ros_messages.h"
#include "tests/ros/ros_maps.h"
#include "tests/ros/ros_test_support.h"
#include "tests/testing/test_support.h"

namespace linemap::testing {
namespace {

using ros_bridge::GetMapSrv;
using ros_bridge::MapMetaDataMsg;
using ros_bridge::OccupancyGridMsg;

// What one subscriber received on NS/map and NS/map_metadata.
struct MapListener {
  explicit MapListener(const std::string& ns) {
    ros::NodeHandle nh;
    map_sub = nh.subscribe<OccupancyGridMsg>(
        ns + "/map", 1,
        boost::function<void(const OccupancyGridMsg::ConstPtr&)>(
            [this](const OccupancyGridMsg::ConstPtr& m) { map = m; }));
    meta_sub =
        nh.subscribe<MapMetaDataMsg>(ns + "/map_metadata", 1,
                                     boost::function<void(const MapMetaDataMsg::ConstPtr&)>(
                                         [this](const MapMetaDataMsg::ConstPtr& m) { meta = m; }));
  }
  bool Received() const { return map != nullptr && meta != nullptr; }

  ros::Subscriber map_sub;
  ros::Subscriber meta_sub;
  OccupancyGridMsg::ConstPtr map;
  MapMetaDataMsg::ConstPtr meta;
};

// Starts lmap_server in namespace `ns` with `extra` arguments.
std::unique_ptr<ChildProcess> StartServer(RosMaster& master, const std::string& ns,
                                          std::vector<std::string> extra) {
  std::vector<std::string> argv = {LmapServerPath(), "__ns:=" + ns, "__name:=lmap_server"};
  argv.insert(argv.end(), extra.begin(), extra.end());
  return std::make_unique<ChildProcess>(argv, master.Env(), master.scratch(),
                                        "server" + ns.substr(1));
}

// Starts lmap_server in `ns` with `extra` arguments and waits for the map
// it publishes into *map (a fatal failure when it exits first).
void ReceiveServedMap(RosMaster& master, const std::string& ns, std::vector<std::string> extra,
                      OccupancyGridMsg* map) {
  MapListener listener(ns);
  auto server = StartServer(master, ns, std::move(extra));
  ASSERT_TRUE(WaitFor([&] { return listener.Received() || server->Wait(0); }, 20));
  ASSERT_TRUE(listener.Received()) << "lmap_server exited: " << server->Stderr();
  *map = *listener.map;
}

// The reference crop, cell by cell: the cells of an unrotated map whose
// centres lie in the closed window [x0, x1] x [y0, y1], as `linemap decode
// --window` takes them.
Grid ReferenceCrop(const Grid& grid, double x0, double y0, double x1, double y1) {
  const double r = grid.meta.resolution;
  const double ox = grid.meta.origin.x, oy = grid.meta.origin.y;
  std::vector<int> cols, rows;
  for (int c = 0; c < grid.width(); ++c) {
    const double centre = ox + (c + 0.5) * r;
    if (centre >= x0 - 1e-9 && centre <= x1 + 1e-9) cols.push_back(c);
  }
  for (int w = 0; w < grid.height(); ++w) {
    const double centre = oy + (w + 0.5) * r;
    if (centre >= y0 - 1e-9 && centre <= y1 + 1e-9) rows.push_back(w);
  }
  Grid out(static_cast<int>(cols.size()), static_cast<int>(rows.size()));
  for (std::size_t j = 0; j < rows.size(); ++j) {
    for (std::size_t i = 0; i < cols.size(); ++i) {
      out.set(static_cast<int>(i), static_cast<int>(j), grid.at(cols[i], rows[j]));
    }
  }
  out.meta = grid.meta;
  out.meta.origin.x = ox + cols.front() * r;
  out.meta.origin.y = oy + rows.front() * r;
  return out;
}

// The cells of the bundled depot_lossless.lmap in the window, cut by the
// test's own rule (ReferenceCrop).
Grid DepotCrop(double x0, double y0, double x1, double y1) {
  StatusOr<Grid> whole = LoadLmap(SourceDir() + "/tests/data/lmap/depot_lossless.lmap");
  EXPECT_TRUE(whole.ok()) << whole.status().message();
  return whole.ok() ? ReferenceCrop(*whole, x0, y0, x1, y1) : Grid();
}

void ExpectMetadataIsMapInfo(const MapMetaDataMsg& meta, const OccupancyGridMsg& map) {
  EXPECT_EQ(meta.width, map.info.width);
  EXPECT_EQ(meta.height, map.info.height);
  EXPECT_EQ(meta.resolution, map.info.resolution);
  EXPECT_EQ(meta.origin.position.x, map.info.origin.position.x);
  EXPECT_EQ(meta.origin.position.y, map.info.origin.position.y);
  EXPECT_EQ(meta.origin.orientation.w, map.info.origin.orientation.w);
  EXPECT_EQ(meta.map_load_time, map.info.map_load_time);
}

TEST(LmapServerTest, PublishesBundledLmapAndServesItOnStaticMap) {
  RosMaster& master = SharedMaster();
  const std::string lmap = SourceDir() + "/tests/data/lmap/depot_lossless.lmap";
  StatusOr<Grid> expected = LoadLmap(lmap);
  ASSERT_TRUE(expected.ok()) << expected.status().message();
  MapListener listener("/s1");
  auto server = StartServer(master, "/s1", {lmap});
  ASSERT_TRUE(WaitFor([&] { return listener.Received() || server->Wait(0); }, 20))
      << server->Stderr();
  ASSERT_TRUE(listener.Received()) << "lmap_server exited: " << server->Stderr();
  ExpectMessageIsGrid(*listener.map, *expected, "map");
  ExpectMetadataIsMapInfo(*listener.meta, *listener.map);

  ros::NodeHandle nh;
  ros::ServiceClient client = nh.serviceClient<GetMapSrv>("/s1/static_map");
  ASSERT_TRUE(client.waitForExistence(ros::Duration(10)));
  GetMapSrv service;
  ASSERT_TRUE(client.call(service));
  ExpectMessageIsGrid(service.response.map, *expected, "map");
  EXPECT_EQ(server->Stop(SIGINT), 0) << server->Stderr();
}

// The log line says what a file saved within a tolerance promises; an
// exact file's says nothing of it.
TEST(LmapServerTest, LogNamesTheToleranceTheFileWasSavedWithin) {
  RosMaster& master = SharedMaster();
  const std::pair<std::string, bool> files[] = {
      {SourceDir() + "/tests/data/lmap/willow_v2_3_tolerance_1.lmap", true},
      {SourceDir() + "/tests/data/lmap/depot_v2.lmap", false},
  };
  int n = 0;
  for (const auto& [lmap, named] : files) {
    const std::string ns = "/tol" + std::to_string(n++);
    MapListener listener(ns);
    auto server = StartServer(master, ns, {lmap});
    ASSERT_TRUE(WaitFor([&] { return listener.Received() || server->Wait(0); }, 20))
        << server->Stderr();
    ASSERT_TRUE(listener.Received()) << "lmap_server exited: " << server->Stderr();
    EXPECT_EQ(server->Stop(SIGINT), 0) << server->Stderr();
    const std::string log = server->Stdout();
    EXPECT_NE(log.find("lmap_server: serving " + lmap), std::string::npos) << log;
    EXPECT_EQ(log.find(", saved within a tolerance") != std::string::npos, named) << log;
    if (named) {
      EXPECT_NE(log.find(", saved within a tolerance of 1 cell (0.1 m)"), std::string::npos) << log;
    }
  }
}

TEST(LmapServerTest, PublishesMapYamlInTheGivenFrame) {
  RosMaster& master = SharedMaster();
  // Non-zero origin: the origin travels into the message.
  const Grid expected = LoadBundledMap("strands/kth/map.yaml");
  OccupancyGridMsg map;
  ASSERT_NO_FATAL_FAILURE(ReceiveServedMap(
      master, "/s2", {"_map:=" + BundledMapsDir() + "/strands/kth/map.yaml", "_frame_id:=world"},
      &map));
  ExpectMessageIsGrid(map, expected, "world");
  EXPECT_EQ(map.info.origin.position.x, -7.0);
  EXPECT_EQ(map.info.origin.position.y, -17.5);
}

// An .lmap file that names its frame (lmap_saver --metadata) is served in
// it; ~frame_id still wins, and a file without one is served in map.
TEST(LmapServerTest, ServesAnLmapInTheFrameItNames) {
  RosMaster& master = SharedMaster();
  const Grid expected = LoadBundledMap("navtut/lse_arena.yaml");
  const std::string dir = MakeTempDir("server_frame");
  EncodeOptions options;
  options.frame_id = "floor_2";
  ASSERT_TRUE(SaveLmap(dir + "/named.lmap", expected, options).ok());
  ASSERT_TRUE(SaveLmap(dir + "/plain.lmap", expected, EncodeOptions{}).ok());
  for (const auto& [ns, args, frame] :
       std::vector<std::tuple<std::string, std::vector<std::string>, std::string>>{
           {"/s20", {dir + "/named.lmap"}, "floor_2"},
           {"/s21", {dir + "/named.lmap", "_frame_id:=world"}, "world"},
           {"/s22", {dir + "/plain.lmap"}, "map"}}) {
    SCOPED_TRACE(ns);
    OccupancyGridMsg map;
    ASSERT_NO_FATAL_FAILURE(ReceiveServedMap(master, ns, args, &map));
    ExpectMessageIsGrid(map, expected, frame);
  }
}

TEST(LmapServerTest, WindowPublishesOnlyTheRegionWithItsOrigin) {
  RosMaster& master = SharedMaster();
  const Grid whole = LoadBundledMap("strands/kth/map.yaml");
  // Edges on cell borders (-5.0) and inside cells (-2.32, 3.01, 8.93). The
  // centres -7 + (c + 0.5) 0.05 in [-5, 3.01] are those of columns 40..199.
  const Grid expected = ReferenceCrop(whole, -5.0, -2.32, 3.01, 8.93);
  ASSERT_EQ(expected.width(), 160);
  OccupancyGridMsg map;
  ASSERT_NO_FATAL_FAILURE(ReceiveServedMap(
      master, "/s3",
      {BundledMapsDir() + "/strands/kth/map.yaml", "_window:=[-5.0, -2.32, 3.01, 8.93]"}, &map));
  ExpectMessageIsGrid(map, expected, "map");
}

TEST(LmapServerTest, RostopicEchoShowsTheMapInfo) {
  RosMaster& master = SharedMaster();
  auto server = StartServer(master, "/s4", {SourceDir() + "/tests/data/lmap/depot_lossless.lmap"});
  ChildProcess echo({RostopicPath(), "echo", "-n1", "/s4/map/info"}, master.Env(), master.scratch(),
                    "rostopic");
  const std::optional<int> code = echo.Wait(30);
  ASSERT_TRUE(code.has_value()) << "rostopic echo did not finish";
  EXPECT_EQ(*code, 0) << echo.Stderr();
  const std::string out = echo.Stdout();
  EXPECT_NE(out.find("width: 604"), std::string::npos) << out;
  EXPECT_NE(out.find("height: 307"), std::string::npos) << out;
}

TEST(LmapServerTest, UnreadableMapExitsTwoNamingTheFile) {
  RosMaster& master = SharedMaster();
  const std::string missing = MakeTempDir("server") + "/missing.lmap";
  auto server = StartServer(master, "/s5", {missing});
  const std::optional<int> code = server->Wait(20);
  ASSERT_TRUE(code.has_value());
  EXPECT_EQ(*code, 2);
  EXPECT_NE(server->Stderr().find(missing), std::string::npos) << server->Stderr();
}

TEST(LmapServerTest, NoMasterExitsOneWithinTheWait) {
  // Nothing listens on this port; no master of this process is started.
  const std::string uri = "http://127.0.0.1:" + std::to_string(FreePort()) + "/";
  const std::string scratch = MakeTempDir("nomaster");
  const double start = Now();
  ChildProcess server({LmapServerPath(), "--wait-master", "1.5",
                       SourceDir() + "/tests/data/lmap/depot_lossless.lmap"},
                      {"ROS_MASTER_URI=" + uri, "ROS_HOME=" + scratch}, scratch, "server");
  const std::optional<int> code = server.Wait(10);
  const double seconds = Now() - start;
  ASSERT_TRUE(code.has_value()) << "still waiting after 10 s";
  EXPECT_EQ(*code, 1);
  EXPECT_GE(seconds, 1.5);
  EXPECT_LT(seconds, 5.0);
  EXPECT_NE(server.Stderr().find("no ROS master at " + uri), std::string::npos) << server.Stderr();
}

// lmap_server with no master at a port nothing listens on, waiting for one
// at most `wait` seconds.
std::unique_ptr<ChildProcess> StartServerWithoutMaster(std::vector<std::string> extra,
                                                       double wait) {
  const std::string uri = "http://127.0.0.1:" + std::to_string(FreePort()) + "/";
  const std::string scratch = MakeTempDir("nomaster");
  std::vector<std::string> argv = {LmapServerPath(), "--wait-master", std::to_string(wait)};
  argv.insert(argv.end(), extra.begin(), extra.end());
  return std::make_unique<ChildProcess>(
      argv, std::vector<std::string>{"ROS_MASTER_URI=" + uri, "ROS_HOME=" + scratch}, scratch,
      "server");
}

// The lines of `text` that are not empty.
std::vector<std::string> Lines(const std::string& text) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    if (end > start) lines.push_back(text.substr(start, end - start));
    start = end + 1;
  }
  return lines;
}

// A window reaching past the map is refused as `linemap decode --window`
// refuses one: exit 2 and one line naming the window and the map's extent,
// before the master is waited for (none runs here; the wait would outlast
// the test). From an .lmap file (read by region) and from a map YAML (read
// whole and cropped) alike.
TEST(LmapServerTest, WindowPastTheMapExitsTwoNamingTheWindowAndTheMapsExtent) {
  struct Case {
    std::string map;
    std::string window;
    std::string extent;
  };
  const Case cases[] = {
      // 604 x 307 cells at 0.05 m from the origin 0,0: the window's lower
      // left lies off the map.
      {SourceDir() + "/tests/data/lmap/depot_lossless.lmap", "-5,-5,1,1",
       "the map's 604 x 307 cells have centres from 0.025,0.025 to 30.175,15.325 m"},
      // 260 x 781 cells from -7,-17.5: only x = 6..6.5 lies off the map.
      {BundledMapsDir() + "/strands/kth/map.yaml", "-5,-5,6.5,1",
       "the map's 260 x 781 cells have centres from -6.975,-17.475 to 5.975,21.525 m"},
  };
  for (const Case& c : cases) {
    auto server = StartServerWithoutMaster({c.map, "_window:=[" + c.window + "]"}, 60);
    const std::optional<int> code = server->Wait(10);
    ASSERT_TRUE(code.has_value()) << c.map << ": still running after 10 s";
    EXPECT_EQ(*code, 2) << server->Stderr();
    const std::vector<std::string> lines = Lines(server->Stderr());
    ASSERT_EQ(lines.size(), 1u) << server->Stderr();
    EXPECT_NE(lines[0].find(c.map), std::string::npos) << lines[0];
    EXPECT_NE(lines[0].find("window " + c.window + " m"), std::string::npos) << lines[0];
    EXPECT_NE(lines[0].find("past the map"), std::string::npos) << lines[0];
    EXPECT_NE(lines[0].find(c.extent), std::string::npos) << lines[0];
  }
}

// The same for a ~window set on the parameter server (as a launch file's
// <param> sets it), which lmap_server reads once the master answers.
TEST(LmapServerTest, WindowParameterPastTheMapExitsTwo) {
  RosMaster& master = SharedMaster();
  ros::param::set("/s7/lmap_server/window", std::vector<double>{25.0, 10.0, 31.0, 12.0});
  const std::string lmap = SourceDir() + "/tests/data/lmap/depot_lossless.lmap";
  auto server = StartServer(master, "/s7", {lmap});
  const std::optional<int> code = server->Wait(20);
  ASSERT_TRUE(code.has_value()) << "lmap_server did not exit";
  EXPECT_EQ(*code, 2) << server->Stderr();
  EXPECT_NE(server->Stderr().find("window 25,10,31,12 m"), std::string::npos) << server->Stderr();
  EXPECT_NE(server->Stderr().find("centres from 0.025,0.025 to 30.175,15.325 m"), std::string::npos)
      << server->Stderr();
}

// A command-line map with the window of a launch file's <param> (set on the
// parameter server only) publishes the window's cells, with the map read
// after the window is known (its tiles alone for an .lmap file, an image
// whole and cropped), or for an image whose ~max_cells is on the command
// line (no parameter can change it) read whole before the master answers
// and cropped once it does.
TEST(LmapServerTest, WindowParameterWithACommandLineMapPublishesTheWindow) {
  RosMaster& master = SharedMaster();
  const Grid expected = DepotCrop(5.0, 2.0, 12.5, 9.0);
  const std::string lmap = SourceDir() + "/tests/data/lmap/depot_lossless.lmap";
  const std::string yaml = BundledMapsDir() + "/nav2/depot.yaml";
  const std::vector<std::vector<std::string>> cases = {
      {lmap}, {yaml}, {yaml, "_max_cells:=" + std::to_string(604 * 307)}};
  int k = 0;
  for (const std::vector<std::string>& args : cases) {
    SCOPED_TRACE(args.back());
    const std::string ns = "/s10_" + std::to_string(k++);
    ros::param::set(ns + "/lmap_server/window", std::vector<double>{5.0, 2.0, 12.5, 9.0});
    OccupancyGridMsg map;
    ASSERT_NO_FATAL_FAILURE(ReceiveServedMap(master, ns, args, &map));
    ExpectMessageIsGrid(map, expected, "map");
  }
}

// A window that ends on the map's border holds the cells up to it.
TEST(LmapServerTest, WindowToTheMapsBorderPublishesItsCells) {
  RosMaster& master = SharedMaster();
  const std::string lmap = SourceDir() + "/tests/data/lmap/depot_lossless.lmap";
  OccupancyGridMsg map;
  ASSERT_NO_FATAL_FAILURE(
      ReceiveServedMap(master, "/s8", {lmap, "_window:=[20.0, 0.0, 30.2, 15.35]"}, &map));
  ExpectMessageIsGrid(map, DepotCrop(20.0, 0.0, 30.2, 15.35), "map");
}

// A map that cannot be read is refused at once, named, without waiting for
// a master: given as the argument or as `_map:=`.
TEST(LmapServerTest, UnreadableMapExitsTwoBeforeWaitingForTheMaster) {
  const std::string missing = MakeTempDir("server") + "/nosuch.lmap";
  for (const std::string& arg : {missing, "_map:=" + missing}) {
    const double start = Now();
    auto server = StartServerWithoutMaster({arg}, 60);
    const std::optional<int> code = server->Wait(10);
    ASSERT_TRUE(code.has_value()) << arg << ": still running after 10 s";
    EXPECT_EQ(*code, 2) << server->Stderr();
    EXPECT_LT(Now() - start, 5.0);
    EXPECT_NE(server->Stderr().find(missing), std::string::npos) << server->Stderr();
    EXPECT_EQ(server->Stderr().find("no ROS master"), std::string::npos) << server->Stderr();
  }
}

// roscpp stores `_window:=...` on the parameter server inside ros::init,
// retrying for ever while no master answers: --wait-master bounds that too.
TEST(LmapServerTest, NoMasterWithAWindowArgumentExitsOneWithinTheWait) {
  const double start = Now();
  auto server = StartServerWithoutMaster(
      {SourceDir() + "/tests/data/lmap/depot_lossless.lmap", "_window:=[1,1,5,5]"}, 1.5);
  const std::optional<int> code = server->Wait(10);
  const double seconds = Now() - start;
  ASSERT_TRUE(code.has_value()) << "still waiting after 10 s";
  EXPECT_EQ(*code, 1) << server->Stderr();
  EXPECT_GE(seconds, 1.5);
  EXPECT_LT(seconds, 5.0);
  EXPECT_NE(server->Stderr().find("no ROS master"), std::string::npos) << server->Stderr();
}

// roscpp retries each `_name:=` argument for the whole timeout in turn: the
// wait is shared among them, so three arguments still end within it.
TEST(LmapServerTest, NoMasterWithSeveralParameterArgumentsWaitsOnceInAll) {
  const double start = Now();
  auto server = StartServerWithoutMaster(
      {SourceDir() + "/tests/data/lmap/depot_lossless.lmap", "_frame_id:=map", "_a:=1", "_b:=2"},
      2.0);
  const std::optional<int> code = server->Wait(15);
  const double seconds = Now() - start;
  ASSERT_TRUE(code.has_value()) << "still waiting after 15 s";
  EXPECT_EQ(*code, 1) << server->Stderr();
  EXPECT_GE(seconds, 2.0);
  EXPECT_LT(seconds, 4.5);  // 6 s when each argument waited the whole 2 s
}

// A limit that is no whole number from 1 to 2147483647 is refused at once,
// naming the parameter and the range, as is a map over ~max_cells given on
// the command line (its header read): exit 2 and one line, before the
// master is waited for (none runs here).
TEST(LmapServerTest, BadLimitArgumentExitsTwoBeforeWaitingForTheMaster) {
  const std::string lmap = SourceDir() + "/tests/data/lmap/depot_v2.lmap";
  const std::string range = " must be a whole number from 1 to 2147483647 ";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"_max_cells:=0", "lmap_server: ~max_cells" + range + "(cells), not '0'"},
      {"_max_segments:=-4",
       "lmap_server: ~max_segments" + range + "(wall segments per chunk), not '-4'"},
      {"_max_objects:=2.5",
       "lmap_server: ~max_objects" + range + "(rooms, and furniture objects, per file), not '2.5'"},
      {"_max_cells:=lots", "lmap_server: ~max_cells" + range + "(cells), not 'lots'"},
      // 604 x 307 = 185,428 cells.
      {"_max_cells:=185427", "(limit: ~max_cells 185427)"},
  };
  for (const auto& [arg, expected] : cases) {
    const double start = Now();
    auto server = StartServerWithoutMaster({lmap, arg}, 60);
    const std::optional<int> code = server->Wait(10);
    ASSERT_TRUE(code.has_value()) << arg << ": still running after 10 s";
    EXPECT_EQ(*code, 2) << server->Stderr();
    EXPECT_LT(Now() - start, 5.0);
    const std::vector<std::string> lines = Lines(server->Stderr());
    ASSERT_EQ(lines.size(), 1u) << server->Stderr();
    EXPECT_NE(lines[0].find(expected), std::string::npos) << lines[0];
  }
}

// A map over a limit, or a bad limit, from the command line or from the
// parameter server (a launch file's <param>, read once the master answers),
// exits 2 naming the limit: the layers' limits are only known once the
// layers are read, and a limit not on the command line only once the master
// answers, whether the map is an .lmap file, one with a window given or a
// map image.
TEST(LmapServerTest, MapOverALimitOrABadLimitParameterExitsTwo) {
  RosMaster& master = SharedMaster();
  const std::string lmap = SourceDir() + "/tests/data/lmap/depot_v2.lmap";
  const std::string yaml = BundledMapsDir() + "/nav2/depot.yaml";
  struct Case {
    std::vector<std::string> args;
    std::string parameter;  // set on the parameter server when not empty
    XmlRpc::XmlRpcValue value;
    std::string expected;
  };
  const Case cases[] = {
      // 437 wall segments, 8 rooms, 33 furniture objects.
      {{lmap, "_max_segments:=1"}, "", {}, "segment limit of 1 (limit: ~max_segments 1)\n"},
      {{lmap, "_window:=[5,2,12.5,9]"}, "max_objects", 7, "(limit: ~max_objects 7)\n"},
      {{yaml}, "max_cells", 1000, "(limit: ~max_cells 1000)\n"},
      {{lmap}, "max_cells", 2.5, "~max_cells must be a whole number from 1 to 2147483647 "},
      {{lmap}, "max_segments", "many", "(wall segments per chunk), not 'many'"},
  };
  int k = 0;
  for (const Case& c : cases) {
    const std::string ns = "/s11_" + std::to_string(k++);
    SCOPED_TRACE(ns + " " + c.expected);
    if (!c.parameter.empty()) {
      XmlRpc::XmlRpcValue value = c.value;
      ros::param::set(ns + "/lmap_server/" + c.parameter, value);
    }
    auto server = StartServer(master, ns, c.args);
    const std::optional<int> code = server->Wait(20);
    ASSERT_TRUE(code.has_value()) << "lmap_server did not exit";
    EXPECT_EQ(*code, 2) << server->Stderr();
    EXPECT_NE(server->Stderr().find(c.expected), std::string::npos) << server->Stderr();
    EXPECT_EQ(server->Stderr().find("no ROS master"), std::string::npos) << server->Stderr();
    // A map over a limit names only that one.
    for (const char* other : {"~max_cells ", "~max_segments ", "~max_objects "}) {
      if (c.expected.find("(limit: ") != std::string::npos &&
          c.expected.find(other) == std::string::npos) {
        EXPECT_EQ(server->Stderr().find(other), std::string::npos) << server->Stderr();
      }
    }
  }
}

// A file over a limit no parameter sets (here the 2 GiB of a file the
// decoder reads, a sparse file) names no parameter: raising ~max_cells,
// ~max_segments or ~max_objects would not serve it. Refused before the wait
// for the master (none runs), with the limits on the command line or not.
TEST(LmapServerTest, FileOverALimitNoParameterSetsNamesNone) {
  const std::string big = MakeTempDir("server_big") + "/big.lmap";
  WriteFile(big, "");
  std::filesystem::resize_file(big, (std::uintmax_t{1} << 31) + 1);
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{big, "_max_cells:=1000"},
        std::vector<std::string>{big, "_max_cells:=1000", "_max_segments:=10",
                                 "_max_objects:=10"}}) {
    SCOPED_TRACE(args.size());
    auto server = StartServerWithoutMaster(args, 60);
    const std::optional<int> code = server->Wait(10);
    ASSERT_TRUE(code.has_value()) << "still running after 10 s";
    EXPECT_EQ(*code, 2) << server->Stderr();
    const std::vector<std::string> lines = Lines(server->Stderr());
    ASSERT_EQ(lines.size(), 1u) << server->Stderr();
    EXPECT_NE(lines[0].find(big + "' is 2147483649 bytes, more than the limit of 2147483648"),
              std::string::npos)
        << lines[0];
    EXPECT_EQ(lines[0].find("~max_"), std::string::npos) << lines[0];
  }
}

// Limits at the file's own counts (read here from its layers) serve it,
// cell for cell.
TEST(LmapServerTest, LimitsAtTheFilesCountsServeTheMap) {
  RosMaster& master = SharedMaster();
  const std::string lmap = SourceDir() + "/tests/data/lmap/depot_v2.lmap";
  const StatusOr<Grid> expected = LoadLmap(lmap);
  ASSERT_TRUE(expected.ok()) << expected.status().message();
  const StatusOr<LmapVectors> vectors = LoadLmapVectors(lmap);
  ASSERT_TRUE(vectors.ok()) << vectors.status().message();
  std::size_t segments = 0;
  for (const WallPolyline& wall : vectors->walls) segments += wall.points.size() - 1;
  const std::size_t objects = std::max(vectors->rooms.size(), vectors->furniture.size());
  ASSERT_GT(segments, 1u);
  ASSERT_GT(objects, 1u);
  OccupancyGridMsg map;
  ASSERT_NO_FATAL_FAILURE(ReceiveServedMap(
      master, "/s12",
      {lmap, "_max_cells:=" + std::to_string(expected->cells().size()),
       "_max_segments:=" + std::to_string(segments), "_max_objects:=" + std::to_string(objects)},
      &map));
  ExpectMessageIsGrid(map, *expected, "map");
}

}  // namespace
}  // namespace linemap::testing
