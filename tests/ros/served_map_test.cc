// The ~window of lmap_server (ros/served_map.cc) without ROS: parsing, and
// the crop of a rotated map checked against the map's own cell geometry;
// its limits (~max_cells, ~max_segments, ~max_objects) against the counts
// the bundled files hold.
#include "ros/served_map.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "linemap/codec.h"
#include "linemap/lmap_vectors.h"
#include "linemap/map_io.h"
#include "tests/ros/ros_maps.h"
#include "tests/testing/test_support.h"

namespace linemap::ros_bridge {
namespace {

TEST(ServedMapTest, ParsesWindowTextAndRefusesBadOnes) {
  StatusOr<Window> window = ParseWindow("[-5.0, -2.32, 3.01, 8.93]");
  ASSERT_TRUE(window.ok()) << window.status().message();
  EXPECT_EQ(window->x0, -5.0);
  EXPECT_EQ(window->y0, -2.32);
  EXPECT_EQ(window->x1, 3.01);
  EXPECT_EQ(window->y1, 8.93);
  EXPECT_TRUE(ParseWindow("1,2,3,4").ok());
  EXPECT_FALSE(ParseWindow("1,2,3").ok());
  EXPECT_FALSE(ParseWindow("1,2,3,4,5").ok());
  EXPECT_FALSE(ParseWindow("3,2,1,4").ok());    // x0 > x1
  EXPECT_TRUE(ParseWindow("1,2,3,2").ok());     // y0 = y1: a row of centres, maybe
  EXPECT_FALSE(ParseWindow("1,2,3,1.9").ok());  // y0 > y1
  EXPECT_FALSE(ParseWindow("1,2,x,4").ok());
  EXPECT_FALSE(ParseWindow("1,2,nan,4").ok());
}

TEST(ServedMapTest, WindowOutsideTheMapIsRefused) {
  Grid grid = testing::NoiseMap(20, 10, 1);
  EXPECT_FALSE(CropToWindow(grid, {5.0, 5.0, 6.0, 6.0}).ok());  // map is 1 x 0.5 m
  // A window of no height on row 3's centres (0.175 m) holds that row, as
  // `linemap decode --window` takes it; one between two rows holds none.
  StatusOr<Grid> row = CropToWindow(grid, {0.0, 0.175, 1.0, 0.175});
  ASSERT_TRUE(row.ok()) << row.status().message();
  EXPECT_EQ(row->width(), 20);
  EXPECT_EQ(row->height(), 1);
  for (int c = 0; c < 20; ++c) EXPECT_EQ(row->at(c, 0), grid.at(c, 3));
  EXPECT_FALSE(CropToWindow(grid, {0.0, 0.2, 1.0, 0.2}).ok());
}

// A window holds the cells whose centres lie in it (as `linemap decode
// --window`); one that reaches a centre past the map's border is refused,
// not clipped, naming the window and the map's extent, while one whose edges
// lie on the border holds the whole map, and one a little past it too.
TEST(ServedMapTest, WindowPastTheMapsBorderIsRefused) {
  const Grid grid = testing::NoiseMap(20, 10, 1);  // 1 x 0.5 m from 0,0
  StatusOr<Grid> whole = CropToWindow(grid, {0.0, 0.0, 1.0, 0.5});
  ASSERT_TRUE(whole.ok()) << whole.status().message();
  EXPECT_EQ(whole->width(), 20);
  EXPECT_EQ(whole->height(), 10);
  EXPECT_EQ(whole->cells(), grid.cells());
  // Short of the outer cells' centres (0.025 m inside the border): still whole.
  StatusOr<Grid> nearly = CropToWindow(grid, {-0.02, -0.02, 1.02, 0.52});
  ASSERT_TRUE(nearly.ok()) << nearly.status().message();
  EXPECT_EQ(nearly->cells(), grid.cells());
  for (const Window& past :
       {Window{-0.03, 0.0, 0.5, 0.25}, Window{0.5, 0.25, 1.03, 0.4}, Window{0.1, -1e6, 0.2, 0.1},
        Window{0.1, 0.1, 0.2, 0.6}, Window{-1e300, -1e300, 1e300, 1e300}}) {
    const StatusOr<Grid> crop = CropToWindow(grid, past);
    ASSERT_FALSE(crop.ok()) << past.x0 << "," << past.y0 << "," << past.x1 << "," << past.y1;
    EXPECT_EQ(crop.status().code(), StatusCode::kInvalidArgument);
    EXPECT_NE(crop.status().message().find("past the map"), std::string::npos)
        << crop.status().message();
    EXPECT_NE(crop.status().message().find(
                  "the map's 20 x 10 cells have centres from 0.025,0.025 to 0.975,0.475 m"),
              std::string::npos)
        << crop.status().message();
  }
  const StatusOr<Grid> crop = CropToWindow(grid, {-5, -5, 1, 1});
  ASSERT_FALSE(crop.ok());
  EXPECT_NE(crop.status().message().find("window -5,-5,1,1 m"), std::string::npos)
      << crop.status().message();
}

// LoadServedMap refuses such a window the same way for an .lmap file, whose
// window is decoded alone, and for a map image, which is cropped; the
// message names the file.
TEST(ServedMapTest, LoadServedMapRefusesAWindowPastTheMap) {
  for (const std::string& path : {testing::SourceDir() + "/tests/data/lmap/depot_lossless.lmap",
                                  testing::BundledMapsDir() + "/nav2/depot.yaml"}) {
    const StatusOr<Grid> grid = LoadServedMap(path, Window{-5, -5, 1, 1});
    ASSERT_FALSE(grid.ok()) << path;
    EXPECT_EQ(grid.status().code(), StatusCode::kInvalidArgument);
    EXPECT_NE(grid.status().message().find(path), std::string::npos) << grid.status().message();
    EXPECT_NE(grid.status().message().find(
                  "the map's 604 x 307 cells have centres from 0.025,0.025 to 30.175,15.325 m"),
              std::string::npos)
        << grid.status().message();
    EXPECT_TRUE(LoadServedMap(path, Window{0, 0, 30.2, 15.35}).ok()) << path;
  }
}

TEST(ServedMapTest, CropOfARotatedMapKeepsEveryCellWhereItWas) {
  Grid grid = testing::NoiseMap(120, 90, 7);
  grid.meta.resolution = 0.05;
  grid.meta.origin = {-1.3, 2.1, 0.4};
  const Window window{0.0, 3.5, 1.5, 4.5};  // inside the rotated map
  StatusOr<Grid> crop = CropToWindow(grid, window);
  ASSERT_TRUE(crop.ok()) << crop.status().message();
  EXPECT_EQ(crop->meta.resolution, grid.meta.resolution);
  EXPECT_EQ(crop->meta.origin.yaw, grid.meta.origin.yaw);
  // Cell (0, 0) of the crop lies on a cell centre of the map: that cell is
  // the crop's offset, and every cell keeps its state and its place.
  double x = 0, y = 0, col = 0, row = 0;
  crop->CellToWorld(0, 0, &x, &y);
  grid.WorldToCell(x, y, &col, &row);
  EXPECT_NEAR(col, std::round(col), 1e-9);
  EXPECT_NEAR(row, std::round(row), 1e-9);
  const int col0 = static_cast<int>(std::round(col)), row0 = static_cast<int>(std::round(row));
  for (int r = 0; r < crop->height(); ++r) {
    for (int c = 0; c < crop->width(); ++c) {
      ASSERT_TRUE(grid.Contains(col0 + c, row0 + r));
      ASSERT_EQ(crop->at(c, r), grid.at(col0 + c, row0 + r)) << c << "," << r;
    }
  }
  // The crop is the cell rectangle around the window's corners, by their
  // centres: the corners' extreme columns lie within a cell outside the
  // first and last centres kept (0 and width - 1), and so do the rows.
  double min_col = INFINITY, max_col = -INFINITY, min_row = INFINITY, max_row = -INFINITY;
  for (const double wx : {window.x0, window.x1}) {
    for (const double wy : {window.y0, window.y1}) {
      crop->WorldToCell(wx, wy, &col, &row);
      min_col = std::min(min_col, col);
      max_col = std::max(max_col, col);
      min_row = std::min(min_row, row);
      max_row = std::max(max_row, row);
    }
  }
  EXPECT_GT(min_col, -1.0);
  EXPECT_LE(min_col, 0.0);
  EXPECT_GE(max_col, crop->width() - 1.0);
  EXPECT_LT(max_col, crop->width());
  EXPECT_GT(min_row, -1.0);
  EXPECT_LE(min_row, 0.0);
  EXPECT_GE(max_row, crop->height() - 1.0);
  EXPECT_LT(max_row, crop->height());
}

const LimitParameter& Limit(const std::string& name) {
  for (const LimitParameter& limit : LimitParameters()) {
    if (limit.name() == name) return limit;
  }
  ADD_FAILURE() << "no limit ~" << name;
  return LimitParameters()[0];
}

TEST(ServedMapTest, LimitParametersAreTheDecodeLimitsTheyName) {
  ASSERT_EQ(LimitParameters().size(), 3u);
  DecodeLimits limits;
  limits.*Limit("max_cells").field = 11;
  limits.*Limit("max_segments").field = 12;
  limits.*Limit("max_objects").field = 13;
  EXPECT_EQ(limits.max_cells, 11u);
  EXPECT_EQ(limits.max_segments, 12u);
  EXPECT_EQ(limits.max_objects, 13u);
}

TEST(ServedMapTest, LimitsAreWholeNumbersFromOneToXmlRpcsLargestInt) {
  const LimitParameter& limit = Limit("max_segments");
  for (const auto& [text, value] : std::vector<std::pair<std::string, std::uint64_t>>{
           {"1", 1}, {"437", 437}, {"2147483647", 2147483647}, {"1e6", 1000000}, {"8.0", 8}}) {
    const StatusOr<std::uint64_t> parsed = ParseLimit(limit, text);
    ASSERT_TRUE(parsed.ok()) << text << ": " << parsed.status().message();
    EXPECT_EQ(*parsed, value) << text;
  }
  for (const std::string text :
       {"0", "-3", "2.5", "abc", "", "12x", "2147483648", "1e300", "nan", "inf", "true"}) {
    const StatusOr<std::uint64_t> parsed = ParseLimit(limit, text);
    ASSERT_FALSE(parsed.ok()) << text;
    EXPECT_EQ(parsed.status().code(), StatusCode::kInvalidArgument);
    EXPECT_EQ(parsed.status().message(),
              "~max_segments must be a whole number from 1 to 2147483647 (wall segments per "
              "chunk), not '" +
                  text + "'");
  }
  EXPECT_EQ(*LimitFromNumber(Limit("max_cells"), 2147483647.0), 2147483647u);
  for (const auto& [value, shown] : std::vector<std::pair<double, std::string>>{
           {0.0, "0"}, {-1.0, "-1"}, {0.1, "0.1"}, {2.5, "2.5"}, {2147483648.0, "2147483648"}}) {
    const StatusOr<std::uint64_t> parsed = LimitFromNumber(Limit("max_cells"), value);
    ASSERT_FALSE(parsed.ok()) << shown;
    EXPECT_EQ(parsed.status().message(),
              "~max_cells must be a whole number from 1 to 2147483647 (cells), not " + shown);
  }
}

// What an .lmap file holds, as LoadLmapVectors reads it.
struct FileCounts {
  std::uint64_t cells = 0;
  std::uint64_t walls = 0;
  std::uint64_t segments = 0;
  std::uint64_t rooms = 0;
  std::uint64_t objects = 0;
};

FileCounts CountsOf(const std::string& path) {
  const StatusOr<LmapVectors> vectors = LoadLmapVectors(path);
  EXPECT_TRUE(vectors.ok()) << path << ": " << vectors.status().message();
  if (!vectors.ok()) return {};
  FileCounts counts;
  counts.cells = std::uint64_t(vectors->width) * std::uint64_t(vectors->height);
  counts.walls = vectors->walls.size();
  for (const WallPolyline& wall : vectors->walls) counts.segments += wall.points.size() - 1;
  counts.rooms = vectors->rooms.size();
  counts.objects = vectors->furniture.size();
  return counts;
}

// Expects LoadServedMap(path, window, limits) to fail as a map over a limit,
// naming the file and `limit` with its value.
void ExpectOverTheLimit(const std::string& path, const std::optional<Window>& window,
                        const DecodeLimits& limits, const std::string& limit) {
  const StatusOr<Grid> grid = LoadServedMap(path, window, limits);
  ASSERT_FALSE(grid.ok()) << limit;
  EXPECT_EQ(grid.status().code(), StatusCode::kResourceExhausted) << grid.status().message();
  EXPECT_NE(grid.status().message().find(path), std::string::npos) << grid.status().message();
  EXPECT_NE(grid.status().message().find(limit), std::string::npos) << grid.status().message();
}

// Each limit one below what the file holds refuses it, and the limits at
// its counts load it as the defaults do: for the layers in one section
// (depot_v2), in 64-cell sections and in chunks of their own (2.0), whole
// and through a window (which decodes only its tiles, yet the limits count
// the whole file).
TEST(ServedMapTest, LmapOverALimitIsRefusedNamingIt) {
  for (const std::string name : {"depot_v2", "depot_v2_2_sections_64", "depot_v2_0"}) {
    const std::string path = testing::SourceDir() + "/tests/data/lmap/" + name + ".lmap";
    const FileCounts counts = CountsOf(path);
    // 604 x 307 cells; 320 walls of 437 segments (2.0: 275 of 370), 8
    // rooms, 33 furniture objects.
    ASSERT_GT(counts.walls, 200u) << path;
    ASSERT_GT(counts.segments, counts.walls) << path;
    ASSERT_EQ(counts.rooms, 8u) << path;
    ASSERT_EQ(counts.objects, 33u) << path;
    for (const std::optional<Window>& window :
         {std::optional<Window>(), std::optional<Window>(Window{5.0, 2.0, 12.5, 9.0})}) {
      SCOPED_TRACE(path + (window ? " with a window" : ""));
      const StatusOr<Grid> expected = LoadServedMap(path, window);
      ASSERT_TRUE(expected.ok()) << expected.status().message();
      DecodeLimits at_counts;
      at_counts.max_cells = counts.cells;
      at_counts.max_segments = counts.segments;
      at_counts.max_objects = counts.objects;
      const StatusOr<Grid> grid = LoadServedMap(path, window, at_counts);
      ASSERT_TRUE(grid.ok()) << grid.status().message();
      EXPECT_EQ(grid->cells(), expected->cells());

      DecodeLimits limits = at_counts;
      limits.max_segments = counts.walls - 1;  // fewer than the walls
      ExpectOverTheLimit(path, window, limits,
                         "~max_segments " + std::to_string(limits.max_segments));
      // Fewer than the segments, as many as the walls. (The decoder counts
      // the segments of 64-cell sections per band of sections it reads,
      // not per chunk: depot_v2_2_sections_64 decodes.)
      limits.max_segments = counts.segments - 1;
      if (name != "depot_v2_2_sections_64") {
        ExpectOverTheLimit(path, window, limits,
                           "~max_segments " + std::to_string(limits.max_segments));
      }
      limits = at_counts;
      limits.max_objects = counts.objects - 1;  // the furniture objects
      ExpectOverTheLimit(path, window, limits, "~max_objects 32");
      limits.max_objects = counts.rooms - 1;  // the rooms too
      ExpectOverTheLimit(path, window, limits, "~max_objects 7");
      limits = at_counts;
      limits.max_cells = counts.cells - 1;
      ExpectOverTheLimit(path, window, limits, "~max_cells 185427");
    }
  }
}

// A map over a limit names the parameter that lifts the refusal, with its
// value, and no other; a map over one of the decoder's limits that no
// parameter sets (file, chunk and inflated bytes, chain cells) names none.
// Every .lmap fixture the server reads, of each version and layout, whole
// and through a window.
TEST(ServedMapTest, OnlyTheParameterThatLiftsTheRefusalIsNamed) {
  const std::string dir = testing::SourceDir() + "/tests/data/lmap/";
  constexpr std::uint64_t DecodeLimits::*kOtherLimits[] = {
      &DecodeLimits::max_file_bytes, &DecodeLimits::max_chunk_bytes,
      &DecodeLimits::max_inflated_bytes, &DecodeLimits::max_chain_length};
  std::size_t named = 0;
  std::size_t unnamed = 0;
  for (const std::string& name : testing::ListDir(dir)) {
    const std::string path = dir + name;
    if (!name.ends_with(".lmap") || !LoadServedMap(path, std::nullopt).ok()) continue;
    for (const std::optional<Window>& window :
         {std::optional<Window>(), std::optional<Window>(Window{1.0, 1.0, 2.0, 2.0})}) {
      SCOPED_TRACE(path + (window ? " with a window" : ""));
      for (const LimitParameter& parameter : LimitParameters()) {
        DecodeLimits limits;
        limits.*parameter.field = 1;
        const StatusOr<Grid> grid = LoadServedMap(path, window, limits);
        if (grid.ok()) continue;  // e.g. no layers to be over ~max_segments
        const std::string& message = grid.status().message();
        EXPECT_EQ(grid.status().code(), StatusCode::kResourceExhausted) << message;
        EXPECT_TRUE(message.ends_with(" (limit: ~" + std::string(parameter.name()) + " 1)"))
            << message;
        EXPECT_EQ(message.find("~max_"), message.rfind("~max_")) << message;
        ++named;
      }
      for (std::uint64_t DecodeLimits::*field : kOtherLimits) {
        DecodeLimits limits;
        limits.*field = 1;
        const StatusOr<Grid> grid = LoadServedMap(path, window, limits);
        if (grid.ok()) continue;
        const std::string& message = grid.status().message();
        EXPECT_EQ(grid.status().code(), StatusCode::kResourceExhausted) << message;
        EXPECT_EQ(message.find("~max_"), std::string::npos) << message;
        ++unnamed;
      }
    }
  }
  EXPECT_GT(named, 40u);
  EXPECT_GT(unnamed, 40u);
  // A parameter at the value of the limit the map is over is not named for
  // it: depot_v2's 8 rooms and 33 objects are within ~max_objects 100, their
  // chains over 100 cells.
  DecodeLimits limits;
  limits.max_chain_length = 100;
  limits.max_objects = 100;
  const StatusOr<Grid> chains = LoadServedMap(dir + "depot_v2.lmap", std::nullopt, limits);
  ASSERT_FALSE(chains.ok());
  EXPECT_TRUE(chains.status().message().ends_with("chain limit of 100"))
      << chains.status().message();
}

// ~max_cells applies to a map image (whole, with a window too), and is the
// only limit named.
TEST(ServedMapTest, MapImageOverMaxCellsIsRefused) {
  const std::string yaml = testing::BundledMapsDir() + "/nav2/depot.yaml";
  const StatusOr<Grid> whole = LoadRosMap(yaml);
  ASSERT_TRUE(whole.ok()) << whole.status().message();
  const std::uint64_t cells = whole->cells().size();
  ASSERT_EQ(cells, 604u * 307u);
  for (const std::optional<Window>& window :
       {std::optional<Window>(), std::optional<Window>(Window{5.0, 2.0, 12.5, 9.0})}) {
    DecodeLimits limits;
    limits.max_cells = cells;
    limits.max_segments = 1;  // an image has none
    limits.max_objects = 1;
    EXPECT_TRUE(LoadServedMap(yaml, window, limits).ok());
    limits.max_cells = cells - 1;
    const StatusOr<Grid> grid = LoadServedMap(yaml, window, limits);
    ASSERT_FALSE(grid.ok());
    EXPECT_EQ(grid.status().code(), StatusCode::kResourceExhausted);
    EXPECT_NE(grid.status().message().find("(limit: ~max_cells 185427)"), std::string::npos)
        << grid.status().message();
  }
}

// CheckServedMap refuses what LoadServedMap refuses from the header alone:
// a map over ~max_cells, a window past the map; the layers' limits are left
// to the decode.
TEST(ServedMapTest, CheckServedMapChecksTheHeaderAndTheWindow) {
  const std::string lmap = testing::SourceDir() + "/tests/data/lmap/depot_v2.lmap";
  const std::string yaml = testing::BundledMapsDir() + "/nav2/depot.yaml";
  for (const std::string& path : {lmap, yaml}) {
    SCOPED_TRACE(path);
    DecodeLimits limits;
    limits.max_cells = 604 * 307;
    limits.max_segments = 1;
    limits.max_objects = 1;
    const Status ok = CheckServedMap(path, Window{5.0, 2.0, 12.5, 9.0}, limits);
    EXPECT_TRUE(ok.ok()) << ok.message();
    limits.max_cells = 604 * 307 - 1;
    const Status over = CheckServedMap(path, std::nullopt, limits);
    EXPECT_EQ(over.code(), StatusCode::kResourceExhausted) << over.message();
    EXPECT_NE(over.message().find(path), std::string::npos) << over.message();
    EXPECT_NE(over.message().find("(limit: ~max_cells 185427)"), std::string::npos)
        << over.message();
    const Status past = CheckServedMap(path, Window{-5, -5, 1, 1}, DecodeLimits{});
    EXPECT_EQ(past.code(), StatusCode::kInvalidArgument);
    EXPECT_EQ(past.message(), LoadServedMap(path, Window{-5, -5, 1, 1}).status().message());
  }
  const std::string missing = testing::MakeTempDir("served") + "/missing.lmap";
  const Status status = CheckServedMap(missing, std::nullopt);
  EXPECT_EQ(status.code(), StatusCode::kNotFound) << status.message();
  EXPECT_NE(status.message().find(missing), std::string::npos) << status.message();
}

}  // namespace
}  // namespace linemap::ros_bridge
