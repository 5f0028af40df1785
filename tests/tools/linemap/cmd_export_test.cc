// `linemap export` through the built CLI: every feature of the three layers
// reaches CSV, GeoJSON and SVG at the map-frame position computed here from
// the file's cells and the YAML origin, and the SVG embeds the decoded map.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "linemap/codec.h"
#include "linemap/lmap_vectors.h"
#include "linemap/map_io.h"
#include "tests/testing/test_support.h"

namespace linemap {
namespace {

using testing::CliResult;
using testing::RunCli;

struct Xy {
  double x, y;
};

// Map-frame metres of a lattice point, straight from map_server's origin
// definition: the origin is the lower-left corner of cell (0, 0), turned by
// the yaw.
Xy Expected(const MapMetadata& meta, CellIndex c) {
  const double u = (c.col + 0.5) * meta.resolution, v = (c.row + 0.5) * meta.resolution;
  const double cs = std::cos(meta.origin.yaw), sn = std::sin(meta.origin.yaw);
  return {meta.origin.x + cs * u - sn * v, meta.origin.y + sn * u + cs * v};
}

// Depot with a turned, shifted origin, so that a wrong transform shows.
std::string EncodedDepot(const std::string& dir) {
  const std::string out = dir + "/depot.lmap";
  const CliResult r = RunCli({"encode", testing::BundledMapsDir() + "/nav2/depot.yaml", "--origin",
                              "1.5,-2,0.5", "-o", out});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return out;
}

// The rows CSV must hold, in order: wall segments, then every edge of each
// closed chain (one zero-length row for a one-point chain).
std::vector<std::pair<std::string, std::pair<Xy, Xy>>> ExpectedRows(const LmapVectors& v) {
  std::vector<std::pair<std::string, std::pair<Xy, Xy>>> rows;
  for (const WallPolyline& w : v.walls) {
    for (std::size_t i = 0; i + 1 < w.points.size(); ++i)
      rows.push_back({"wall", {Expected(v.meta, w.points[i]), Expected(v.meta, w.points[i + 1])}});
  }
  auto closed = [&](const std::string& layer, const std::vector<CellIndex>& chain) {
    for (std::size_t i = 0; i < chain.size(); ++i) {
      rows.push_back(
          {layer, {Expected(v.meta, chain[i]), Expected(v.meta, chain[(i + 1) % chain.size()])}});
    }
  };
  for (const RoomOutline& r : v.rooms) closed("room_border", r.chain);
  for (const FurnitureObject& f : v.furniture) closed("furniture", f.outline);
  return rows;
}

// The CSV text holds its header, then exactly `rows`, in order.
void ExpectCsvRows(const std::string& text,
                   const std::vector<std::pair<std::string, std::pair<Xy, Xy>>>& rows) {
  std::istringstream csv(text);
  std::string line;
  std::getline(csv, line);
  EXPECT_EQ(line, "layer,x1,y1,x2,y2");
  std::size_t n = 0;
  for (; std::getline(csv, line); ++n) {
    ASSERT_LT(n, rows.size()) << line;
    std::string layer = line.substr(0, line.find(','));
    double x1, y1, x2, y2;
    ASSERT_EQ(std::sscanf(line.c_str() + layer.size(), ",%lf,%lf,%lf,%lf", &x1, &y1, &x2, &y2), 4)
        << line;
    const auto& [want_layer, ends] = rows[n];
    EXPECT_EQ(layer, want_layer) << n;
    EXPECT_NEAR(x1, ends.first.x, 1e-6) << line;
    EXPECT_NEAR(y1, ends.first.y, 1e-6) << line;
    EXPECT_NEAR(x2, ends.second.x, 1e-6) << line;
    EXPECT_NEAR(y2, ends.second.y, 1e-6) << line;
  }
  EXPECT_EQ(n, rows.size());
}

TEST(CmdExportTest, CsvHasEveryWallSegmentAndChainEdgeInMetres) {
  const std::string dir = testing::MakeTempDir("export_csv");
  const std::string lmap = EncodedDepot(dir);
  StatusOr<LmapVectors> v = LoadLmapVectors(lmap);
  ASSERT_TRUE(v.ok()) << v.status().message();
  ASSERT_GT(v->walls.size(), 10u);
  ASSERT_GT(v->rooms.size(), 0u);
  ASSERT_GT(v->furniture.size(), 10u);
  const CliResult r = RunCli({"export", lmap, "-o", dir + "/d.csv"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ExpectCsvRows(testing::ReadFile(dir + "/d.csv"), ExpectedRows(*v));
}

void ExpectPosition(const YAML::Node& pos, Xy want) {
  ASSERT_TRUE(pos.IsSequence());
  EXPECT_NEAR(pos[0].as<double>(), want.x, 1e-6);
  EXPECT_NEAR(pos[1].as<double>(), want.y, 1e-6);
}

// Twice the signed area of a chain of cells: positive counter-clockwise.
std::int64_t TwiceCellArea(const std::vector<CellIndex>& chain) {
  std::int64_t sum = 0;
  for (std::size_t i = 0; i < chain.size(); ++i) {
    const CellIndex& p = chain[i];
    const CellIndex& q = chain[(i + 1) % chain.size()];
    sum += std::int64_t{p.col} * q.row - std::int64_t{q.col} * p.row;
  }
  return sum;
}

// A closed chain as a GeoJSON ring: the points from the first cell,
// counter-clockwise (RFC 7946; a clockwise chain is written backwards, one
// enclosing nothing either way), padded with the last to at least three,
// then the first again.
void ExpectRing(const YAML::Node& ring, const MapMetadata& meta,
                const std::vector<CellIndex>& chain) {
  std::vector<CellIndex> forwards = chain;
  std::vector<CellIndex> backwards = chain;
  std::reverse(backwards.begin() + 1, backwards.end());
  const std::int64_t area = TwiceCellArea(chain);
  std::vector<std::vector<CellIndex>> candidates;
  if (area >= 0) candidates.push_back(forwards);
  if (area <= 0) candidates.push_back(backwards);
  for (std::vector<CellIndex>& want : candidates) {
    const CellIndex last = want.back();
    while (want.size() < 3) want.push_back(last);
    want.push_back(want.front());
  }
  ASSERT_EQ(ring.size(), candidates.front().size());
  const auto near = [&](const std::vector<CellIndex>& want) {
    for (std::size_t i = 0; i < want.size(); ++i) {
      const Xy e = Expected(meta, want[i]);
      if (std::abs(ring[i][0].as<double>() - e.x) > 2e-6 ||
          std::abs(ring[i][1].as<double>() - e.y) > 2e-6) {
        return false;
      }
    }
    return true;
  };
  const std::vector<CellIndex>& want =
      near(candidates.front()) || candidates.size() == 1 ? candidates.front() : candidates.back();
  for (std::size_t i = 0; i < want.size(); ++i) ExpectPosition(ring[i], Expected(meta, want[i]));
}

TEST(CmdExportTest, GeoJsonFeaturesCarryLayerIdKindAndRoom) {
  const std::string dir = testing::MakeTempDir("export_geojson");
  const std::string lmap = EncodedDepot(dir);
  StatusOr<LmapVectors> v = LoadLmapVectors(lmap);
  ASSERT_TRUE(v.ok()) << v.status().message();
  const CliResult r = RunCli({"export", lmap, "-o", dir + "/d.geojson"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // JSON is YAML's flow style: yaml-cpp parses it independently of the CLI.
  const YAML::Node doc = YAML::LoadFile(dir + "/d.geojson");
  EXPECT_EQ(doc["type"].as<std::string>(), "FeatureCollection");
  const YAML::Node features = doc["features"];
  ASSERT_EQ(features.size(), v->walls.size() + v->rooms.size() + v->furniture.size());
  std::size_t i = 0;
  for (std::size_t w = 0; w < v->walls.size(); ++w, ++i) {
    const YAML::Node f = features[i];
    EXPECT_EQ(f["properties"]["layer"].as<std::string>(), "wall");
    EXPECT_EQ(f["properties"]["id"].as<std::size_t>(), w);
    EXPECT_EQ(f["geometry"]["type"].as<std::string>(), "LineString");
    const YAML::Node coords = f["geometry"]["coordinates"];
    ASSERT_EQ(coords.size(), v->walls[w].points.size());
    for (std::size_t k = 0; k < coords.size(); ++k)
      ExpectPosition(coords[k], Expected(v->meta, v->walls[w].points[k]));
  }
  for (const RoomOutline& room : v->rooms) {
    const YAML::Node f = features[i++];
    EXPECT_EQ(f["properties"]["layer"].as<std::string>(), "room_border");
    EXPECT_EQ(f["properties"]["id"].as<std::uint32_t>(), room.id);
    EXPECT_EQ(f["properties"]["kind"].as<std::string>(), RoomKindName(room.kind));
    EXPECT_EQ(f["geometry"]["type"].as<std::string>(), "Polygon");
    ExpectRing(f["geometry"]["coordinates"][0], v->meta, room.chain);
  }
  for (const FurnitureObject& object : v->furniture) {
    const YAML::Node f = features[i++];
    EXPECT_EQ(f["properties"]["layer"].as<std::string>(), "furniture");
    EXPECT_EQ(f["properties"]["id"].as<std::uint32_t>(), object.id);
    const YAML::Node room = f["properties"]["room_id"];
    if (object.room_id < 0) {
      EXPECT_TRUE(room.IsNull() || room.as<std::string>() == "null");
    } else {
      EXPECT_EQ(room.as<std::int32_t>(), object.room_id);
    }
    EXPECT_EQ(f["geometry"]["type"].as<std::string>(), "Polygon");
    ExpectRing(f["geometry"]["coordinates"][0], v->meta, object.outline);
  }
}

std::string Base64Decode(const std::string& text) {
  std::string out;
  int bits = 0, value = 0;
  for (char ch : text) {
    int d;
    if (ch >= 'A' && ch <= 'Z')
      d = ch - 'A';
    else if (ch >= 'a' && ch <= 'z')
      d = ch - 'a' + 26;
    else if (ch >= '0' && ch <= '9')
      d = ch - '0' + 52;
    else if (ch == '+')
      d = 62;
    else if (ch == '/')
      d = 63;
    else
      break;  // '=' padding
    value = (value << 6) | d;
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out += static_cast<char>((value >> bits) & 0xff);
    }
  }
  return out;
}

std::size_t Count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// The text of <g id="NAME"> ... </g>.
std::string Group(const std::string& svg, const std::string& name) {
  const std::size_t start = svg.find("<g id=\"" + name + "\"");
  if (start == std::string::npos) return "";
  return svg.substr(start, svg.find("</g>", start) - start);
}

// The map image an SVG embeds, read back as a bare map image (written to
// dir/embedded.png on the way).
StatusOr<Grid> EmbeddedMap(const std::string& svg, const std::string& dir) {
  const std::string key = "href=\"data:image/png;base64,";
  const std::size_t at = svg.find(key);
  if (at == std::string::npos) return NotFoundError("no embedded PNG");
  const std::size_t end = svg.find('"', at + key.size());
  testing::WriteFile(dir + "/embedded.png",
                     Base64Decode(svg.substr(at + key.size(), end - at - key.size())));
  return LoadMapImage(dir + "/embedded.png", MapMetadata{});
}

TEST(CmdExportTest, SvgDrawsTheLayersOverTheDecodedMap) {
  const std::string dir = testing::MakeTempDir("export_svg");
  const std::string lmap = EncodedDepot(dir);
  StatusOr<LmapVectors> v = LoadLmapVectors(lmap);
  ASSERT_TRUE(v.ok()) << v.status().message();
  const CliResult r = RunCli({"export", lmap, "-o", dir + "/d.svg"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string svg = testing::ReadFile(dir + "/d.svg");
  EXPECT_EQ(Count(Group(svg, "wall"), "<polyline "), v->walls.size());
  EXPECT_EQ(Count(Group(svg, "room_border"), "<polygon "), v->rooms.size());
  EXPECT_EQ(Count(Group(svg, "furniture"), "<polygon "), v->furniture.size());
  // The embedded image, read back as a bare map image, is the decoded map
  // (north up: image row 0 is the top grid row).
  StatusOr<Grid> decoded = LoadLmap(lmap);
  ASSERT_TRUE(decoded.ok());
  StatusOr<Grid> image = EmbeddedMap(svg, dir);
  ASSERT_TRUE(image.ok()) << image.status().message();
  EXPECT_EQ(image->cells(), decoded->cells());
  // The yaw of 0.5 rad turns the image (clockwise on screen, y down).
  EXPECT_NE(svg.find("transform=\"rotate(-28.65 "), std::string::npos);
  // A scale bar of a round length, labelled.
  std::smatch m;
  const std::string scale = Group(svg, "scale_bar");
  ASSERT_TRUE(std::regex_search(scale, m, std::regex(">([0-9.]+) m</text>"))) << scale;
  const double metres = std::stod(m[1]);
  const double mantissa = metres / std::pow(10.0, std::floor(std::log10(metres) + 1e-9));
  EXPECT_TRUE(std::abs(mantissa - 1) < 1e-9 || std::abs(mantissa - 2) < 1e-9 ||
              std::abs(mantissa - 5) < 1e-9)
      << metres;
  const std::string legend = Group(svg, "legend");
  for (const std::string& label : {"walls (" + std::to_string(v->walls.size()) + ")",
                                   "room borders (" + std::to_string(v->rooms.size()) + ")",
                                   "furniture (" + std::to_string(v->furniture.size()) + ")"}) {
    EXPECT_NE(legend.find(label), std::string::npos) << label;
  }
}

// With a window, the CSV holds the rows of the items whose box meets it
// (whole), the SVG the window's cells with those items clipped to the map;
// a window past the map is refused with nothing written.
TEST(CmdExportTest, WindowKeepsTheItemsWhoseBoxMeetsIt) {
  const std::string dir = testing::MakeTempDir("export_window");
  const std::string lmap = EncodedDepot(dir);
  StatusOr<LmapVectors> all = LoadLmapVectors(lmap);
  ASSERT_TRUE(all.ok()) << all.status().message();
  const CellWindow w{100, 50, 300, 200};
  LmapVectors want = *all;
  const auto meets = [&](const std::vector<CellIndex>& points) {
    const BoundingBox b = BoxOfCells(points);
    return b.max_col >= w.col0 && b.min_col < w.col1 && b.max_row >= w.row0 && b.min_row < w.row1;
  };
  std::erase_if(want.walls, [&](const WallPolyline& x) { return !meets(x.points); });
  std::erase_if(want.rooms, [&](const RoomOutline& x) { return !meets(x.polygon); });
  std::erase_if(want.furniture, [&](const FurnitureObject& x) { return !meets(x.polygon); });
  ASSERT_LT(want.walls.size(), all->walls.size());
  ASSERT_GT(want.walls.size(), 0u);
  const CliResult r =
      RunCli({"export", lmap, "-o", dir + "/w.csv", "--window-cells", "100,50,300,200"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ExpectCsvRows(testing::ReadFile(dir + "/w.csv"), ExpectedRows(want));
  const CliResult drawn =
      RunCli({"export", lmap, "-o", dir + "/w.svg", "--window-cells", "100,50,300,200"});
  ASSERT_EQ(drawn.exit_code, 0) << drawn.err;
  const std::string svg = testing::ReadFile(dir + "/w.svg");
  EXPECT_EQ(Count(Group(svg, "wall"), "<polyline "), want.walls.size());
  // Its image is the window's cells of the whole decode, cropped here.
  StatusOr<Grid> whole = LoadLmap(lmap);
  ASSERT_TRUE(whole.ok());
  StatusOr<Grid> image = EmbeddedMap(svg, dir);
  ASSERT_TRUE(image.ok()) << image.status().message();
  ASSERT_EQ(image->width(), w.col1 - w.col0);
  ASSERT_EQ(image->height(), w.row1 - w.row0);
  for (int r = w.row0; r < w.row1; ++r) {
    for (int c = w.col0; c < w.col1; ++c) {
      ASSERT_EQ(image->at(c - w.col0, r - w.row0), whole->at(c, r)) << c << "," << r;
    }
  }
  EXPECT_NE(svg.find("<g clip-path=\"url(#map_area)\">"), std::string::npos);
  const CliResult past =
      RunCli({"export", lmap, "-o", dir + "/p.csv", "--window-cells", "100,50,700,200"});
  EXPECT_EQ(past.exit_code, 2);
  EXPECT_NE(past.err.find("not inside the map's 604 x 307 cells"), std::string::npos) << past.err;
  EXPECT_FALSE(testing::FileExists(dir + "/p.csv"));
}

// A window's features carry the ids they have in the whole file, so that
// the exports of several windows merge: a wall's id is its index among the
// file's walls (the whole read's order), not its place in the window. The
// expected walls are those of the whole read whose box meets the window,
// with their whole-read indices; on the default file (one layer section)
// and on one of sections of 16 cells (the window reads few of them).
TEST(CmdExportTest, WindowFeaturesKeepTheirIdsInTheWholeFile) {
  const std::string dir = testing::MakeTempDir("export_window_ids");
  const std::string sectioned = dir + "/depot16.lmap";
  const CliResult encoded = RunCli({"encode", testing::BundledMapsDir() + "/nav2/depot.yaml",
                                    "--section-size", "16", "-o", sectioned});
  ASSERT_EQ(encoded.exit_code, 0) << encoded.err;
  for (const std::string& lmap : {EncodedDepot(dir), sectioned}) {
    SCOPED_TRACE(lmap);
    StatusOr<LmapVectors> all = LoadLmapVectors(lmap);
    ASSERT_TRUE(all.ok()) << all.status().message();
    const CellWindow w{200, 100, 320, 180};
    const auto meets = [&](const std::vector<CellIndex>& points) {
      const BoundingBox b = BoxOfCells(points);
      return b.max_col >= w.col0 && b.min_col < w.col1 && b.max_row >= w.row0 && b.min_row < w.row1;
    };
    std::vector<std::size_t> walls;
    for (std::size_t i = 0; i < all->walls.size(); ++i) {
      if (meets(all->walls[i].points)) walls.push_back(i);
    }
    std::vector<std::uint32_t> rooms, objects;
    for (const RoomOutline& room : all->rooms) {
      if (meets(room.polygon)) rooms.push_back(room.id);
    }
    for (const FurnitureObject& object : all->furniture) {
      if (meets(object.polygon)) objects.push_back(object.id);
    }
    ASSERT_GT(walls.size(), 1u);
    ASSERT_GT(walls.front(), 0u) << "a window whose first wall is the file's first shows nothing";
    const CliResult r =
        RunCli({"export", lmap, "-o", dir + "/w.geojson", "--window-cells", "200,100,320,180"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const YAML::Node features = YAML::LoadFile(dir + "/w.geojson")["features"];
    ASSERT_EQ(features.size(), walls.size() + rooms.size() + objects.size());
    std::size_t i = 0;
    for (const std::size_t wall : walls) {
      const YAML::Node f = features[i++];
      EXPECT_EQ(f["properties"]["layer"].as<std::string>(), "wall");
      EXPECT_EQ(f["properties"]["id"].as<std::size_t>(), wall);
      const YAML::Node coords = f["geometry"]["coordinates"];
      ASSERT_EQ(coords.size(), all->walls[wall].points.size());
      for (std::size_t k = 0; k < coords.size(); ++k) {
        ExpectPosition(coords[k], Expected(all->meta, all->walls[wall].points[k]));
      }
    }
    for (const std::uint32_t id : rooms) {
      EXPECT_EQ(features[i]["properties"]["layer"].as<std::string>(), "room_border");
      EXPECT_EQ(features[i++]["properties"]["id"].as<std::uint32_t>(), id);
    }
    for (const std::uint32_t id : objects) {
      EXPECT_EQ(features[i]["properties"]["layer"].as<std::string>(), "furniture");
      EXPECT_EQ(features[i++]["properties"]["id"].as<std::uint32_t>(), id);
    }
  }
}

// A --raster-only file has no layers: CSV is the header, the SVG still shows
// the map. A 1.0 file's segments are two-point walls.
TEST(CmdExportTest, RasterOnlyAndVersion1Files) {
  const std::string dir = testing::MakeTempDir("export_kinds");
  const std::string arena = testing::BundledMapsDir() + "/navtut/lse_arena.yaml";
  ASSERT_EQ(RunCli({"encode", arena, "--raster-only", "-o", dir + "/r.lmap"}).exit_code, 0);
  const CliResult empty = RunCli({"export", dir + "/r.lmap", "-o", dir + "/r.csv"});
  ASSERT_EQ(empty.exit_code, 0);
  EXPECT_EQ(testing::ReadFile(dir + "/r.csv"), "layer,x1,y1,x2,y2\n");
  // The empty file is explained, and only then.
  EXPECT_NE(empty.err.find("has no walls, rooms or furniture (saved with --raster-only?)"),
            std::string::npos)
      << empty.err;
  ASSERT_EQ(RunCli({"encode", arena, "-o", dir + "/d.lmap"}).exit_code, 0);
  EXPECT_EQ(RunCli({"export", dir + "/d.lmap", "-o", dir + "/d.csv"}).err, "");
  ASSERT_EQ(RunCli({"export", dir + "/r.lmap", "-o", dir + "/r.svg"}).exit_code, 0);
  EXPECT_NE(testing::ReadFile(dir + "/r.svg").find("data:image/png;base64,"), std::string::npos);

  const std::string v1 = testing::SourceDir() + "/tests/data/lmap/lse_arena_lossy.lmap";
  StatusOr<LmapContents> contents = LoadLmapContents(v1);
  ASSERT_TRUE(contents.ok());
  ASSERT_EQ(contents->major, 1);
  ASSERT_GT(contents->segments.size(), 0u);
  ASSERT_EQ(RunCli({"export", v1, "-o", dir + "/v1.csv"}).exit_code, 0);
  std::istringstream csv(testing::ReadFile(dir + "/v1.csv"));
  std::string line;
  std::getline(csv, line);
  for (const LatticeSegment& s : contents->segments) {
    ASSERT_TRUE(std::getline(csv, line));
    double x1, y1, x2, y2;
    ASSERT_EQ(std::sscanf(line.c_str(), "wall,%lf,%lf,%lf,%lf", &x1, &y1, &x2, &y2), 4) << line;
    const Xy a = Expected(contents->grid.meta, s.a), b = Expected(contents->grid.meta, s.b);
    EXPECT_NEAR(x1, a.x, 1e-6);
    EXPECT_NEAR(y1, a.y, 1e-6);
    EXPECT_NEAR(x2, b.x, 1e-6);
    EXPECT_NEAR(y2, b.y, 1e-6);
  }
}

// Twice the signed area of a GeoJSON ring (its last position repeats the
// first), taken about the first position: positive counter-clockwise.
double TwiceRingArea(const YAML::Node& ring) {
  const double x0 = ring[0][0].as<double>(), y0 = ring[0][1].as<double>();
  double sum = 0;
  for (std::size_t i = 1; i + 1 < ring.size(); ++i) {
    const double px = ring[i][0].as<double>() - x0, py = ring[i][1].as<double>() - y0;
    const double qx = ring[i + 1][0].as<double>() - x0, qy = ring[i + 1][1].as<double>() - y0;
    sum += px * qy - qx * py;
  }
  return sum;
}

// RFC 7946 3.1.6: exterior rings run counter-clockwise. Every Polygon ring
// that export and segment --geojson write has a signed area of at least 0
// (0 for a chain enclosing nothing, up to the 1e-6 m rounding of the
// positions). Many of depot's room and furniture chains run clockwise, so
// written as they were traced they broke it.
TEST(CmdExportTest, GeoJsonRingsRunCounterClockwise) {
  const std::string dir = testing::MakeTempDir("export_ring_orientation");
  const std::string depot = testing::BundledMapsDir() + "/nav2/depot.yaml";
  ASSERT_EQ(RunCli({"encode", depot, "-o", dir + "/plain.lmap"}).exit_code, 0);
  const std::vector<std::vector<std::string>> writers = {
      {"export", EncodedDepot(dir), "-o", dir + "/turned.geojson"},
      {"export", dir + "/plain.lmap", "-o", dir + "/plain.geojson"},
      {"segment", depot, "--geojson", "-o", dir + "/rooms.geojson"},
      {"segment", depot, "--geojson", "--method", "paper", "-o", dir + "/paper.geojson"},
  };
  for (const std::vector<std::string>& argv : writers) {
    const CliResult r = RunCli(argv);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const YAML::Node features = YAML::LoadFile(argv.back())["features"];
    std::size_t rings = 0, positive = 0;
    for (const YAML::Node& f : features) {
      if (f["geometry"]["type"].as<std::string>() != "Polygon") continue;
      for (const YAML::Node& ring : f["geometry"]["coordinates"]) {
        const double area = TwiceRingArea(ring);
        EXPECT_GE(area, -1e-9) << argv.back() << " ring " << rings;
        positive += area > 0;
        ++rings;
      }
    }
    SCOPED_TRACE(argv.back());
    EXPECT_GT(rings, 30u);
    EXPECT_GT(positive, 30u);
  }
}

// A map without yaw is drawn turned by 0 degrees, not "-0.00".
TEST(CmdExportTest, SvgOfAMapWithoutYawHasNoNegativeZero) {
  const std::string dir = testing::MakeTempDir("export_svg_zero");
  const std::string depot = testing::BundledMapsDir() + "/nav2/depot.yaml";
  ASSERT_EQ(RunCli({"encode", depot, "-o", dir + "/d.lmap"}).exit_code, 0);
  const CliResult r = RunCli({"export", dir + "/d.lmap", "-o", dir + "/d.svg"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string svg = testing::ReadFile(dir + "/d.svg");
  EXPECT_NE(svg.find("transform=\"rotate(0.00 "), std::string::npos);
  EXPECT_EQ(svg.find("-0.00"), std::string::npos);
}

}  // namespace
}  // namespace linemap
