// linemap export IN.lmap -o OUT.csv|OUT.geojson|OUT.svg: the geometric
// layers of an .lmap file in map-frame metres.
//   CSV      layer,x1,y1,x2,y2: one row per segment and per edge of every
//            room chain and blob outline (layers segment, room_border,
//            furniture).
//   GeoJSON  a FeatureCollection: segments as LineStrings, room chains and
//            blob outlines as Polygons, each with a "layer" property.
//   SVG      the layers in distinct colours over the map extent (north up).
#include <cstdio>
#include <string>

#include "format/file_io.h"
#include "linemap/codec.h"
#include "tools/linemap/commands.h"
#include "tools/linemap/lmap_cli_util.h"

namespace linemap::cli {

namespace {

std::vector<OptionSpec> ExportOptions() {
  std::vector<OptionSpec> options = {
      {"-o", "OUT", "output file; its extension (.csv, .geojson, .json, .svg) picks the format"}};
  for (OptionSpec& o : DecodeLimitOptionSpecs()) options.push_back(std::move(o));
  return options;
}

struct Point {
  double x = 0, y = 0;
};

struct Layer {
  const char* name;
  const char* colour;
  // Polylines in metres; closed ones repeat no point (closing is implied).
  std::vector<std::vector<Point>> lines;
  bool closed = false;
};

std::vector<Layer> LayersOf(const LmapContents& contents) {
  const Grid& grid = contents.grid;
  auto world = [&](CellIndex c) {
    Point p;
    grid.CellToWorld(c.col, c.row, &p.x, &p.y);
    return p;
  };
  Layer segments{"segment", "#d62728", {}, false};
  for (const LatticeSegment& s : contents.segments)
    segments.lines.push_back({world(s.a), world(s.b)});
  Layer rooms{"room_border", "#1f77b4", {}, true};
  for (const auto& chain : contents.room_chains) {
    std::vector<Point> line;
    for (const CellIndex& c : chain) line.push_back(world(c));
    rooms.lines.push_back(std::move(line));
  }
  Layer blobs{"furniture", "#2ca02c", {}, true};
  for (const auto& chain : contents.blob_outlines) {
    std::vector<Point> line;
    for (const CellIndex& c : chain) line.push_back(world(c));
    blobs.lines.push_back(std::move(line));
  }
  return {segments, rooms, blobs};
}

std::string Num(double v) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.6f", v);
  return text;
}

std::string ToCsv(const std::vector<Layer>& layers) {
  std::string out = "layer,x1,y1,x2,y2\n";
  for (const Layer& layer : layers) {
    for (const std::vector<Point>& line : layer.lines) {
      const std::size_t edges = layer.closed ? line.size() : line.size() - 1;
      for (std::size_t i = 0; i < edges && line.size() > 1; ++i) {
        const Point& p = line[i];
        const Point& q = line[(i + 1) % line.size()];
        out += std::string(layer.name) + "," + Num(p.x) + "," + Num(p.y) + "," + Num(q.x) + "," +
               Num(q.y) + "\n";
      }
    }
  }
  return out;
}

std::string ToGeoJson(const std::vector<Layer>& layers) {
  std::string out = "{\"type\":\"FeatureCollection\",\"features\":[";
  bool first = true;
  for (const Layer& layer : layers) {
    for (const std::vector<Point>& line : layer.lines) {
      std::string coords;
      for (const Point& p : line)
        coords += (coords.empty() ? "" : ",") + ("[" + Num(p.x) + "," + Num(p.y) + "]");
      std::string geometry;
      if (layer.closed) {
        coords += ",[" + Num(line[0].x) + "," + Num(line[0].y) + "]";  // rings repeat the start
        geometry = "{\"type\":\"Polygon\",\"coordinates\":[[" + coords + "]]}";
      } else {
        geometry = "{\"type\":\"LineString\",\"coordinates\":[" + coords + "]}";
      }
      out += std::string(first ? "" : ",") +
             "\n{\"type\":\"Feature\",\"properties\":{\"layer\":\"" + layer.name +
             "\"},\"geometry\":" + geometry + "}";
      first = false;
    }
  }
  return out + "\n]}\n";
}

std::string ToSvg(const std::vector<Layer>& layers, const Grid& grid) {
  // Corners of the map extent in metres (the yaw may rotate it).
  double min_x = 0, min_y = 0, max_x = 0, max_y = 0;
  bool first = true;
  for (double col : {-0.5, grid.width() - 0.5}) {
    for (double row : {-0.5, grid.height() - 0.5}) {
      double x, y;
      grid.CellToWorld(col, row, &x, &y);
      if (first || x < min_x) min_x = x;
      if (first || y < min_y) min_y = y;
      if (first || x > max_x) max_x = x;
      if (first || y > max_y) max_y = y;
      first = false;
    }
  }
  const double stroke = grid.meta.resolution;
  // SVG's y grows downwards: flip with y' = max_y + min_y - y.
  auto px = [&](const Point& p) { return Num(p.x) + "," + Num(max_y + min_y - p.y); };
  std::string out = "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"" + Num(min_x) + " " +
                    Num(min_y) + " " + Num(max_x - min_x) + " " + Num(max_y - min_y) + "\">\n";
  out += "<rect x=\"" + Num(min_x) + "\" y=\"" + Num(min_y) + "\" width=\"" + Num(max_x - min_x) +
         "\" height=\"" + Num(max_y - min_y) + "\" fill=\"#f4f4f4\"/>\n";
  for (const Layer& layer : layers) {
    out += std::string("<g id=\"") + layer.name + "\" stroke=\"" + layer.colour +
           "\" fill=\"none\" stroke-width=\"" + Num(stroke) + "\">\n";
    for (const std::vector<Point>& line : layer.lines) {
      std::string points;
      for (const Point& p : line) points += (points.empty() ? "" : " ") + px(p);
      out += std::string("<") + (layer.closed ? "polygon" : "polyline") + " points=\"" + points +
             "\"/>\n";
    }
    out += "</g>\n";
  }
  return out + "</svg>\n";
}

bool EndsWith(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() &&
         s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace

const CommandSpec kExportSpec = {
    "export",
    "IN.lmap -o OUT.csv|OUT.geojson|OUT.svg",
    "export the layers of an .lmap file as CSV, GeoJSON or SVG",
    "Coordinates are map-frame metres (cell centres). CSV rows are\n"
    "layer,x1,y1,x2,y2, one per segment and per edge of every room chain and\n"
    "blob outline (layers segment, room_border, furniture). GeoJSON has\n"
    "LineString (segments) and Polygon (chains, outlines) features with a\n"
    "\"layer\" property. SVG draws the layers in distinct colours over the map.",
    ExportOptions(),
    1,
    1,
};

int RunExport(const std::vector<std::string>& args) {
  int exit_code = kExitOk;
  std::optional<ParsedArgs> parsed = ParseArgs(kExportSpec, args, &exit_code);
  if (!parsed) return exit_code;
  const std::optional<std::string> out = parsed->Get("-o");
  if (!out) return ReportError("export", InvalidArgumentError("missing -o OUT"));
  const bool csv = EndsWith(*out, ".csv");
  const bool geojson = EndsWith(*out, ".geojson") || EndsWith(*out, ".json");
  const bool svg = EndsWith(*out, ".svg");
  if (!csv && !geojson && !svg) {
    return ReportError("export",
                       InvalidArgumentError("'" + *out + "' must end in .csv, .geojson or .svg"));
  }
  if (IsDirectory(*out)) {
    return ReportError("export", InvalidArgumentError("'" + *out + "' is a directory"));
  }
  StatusOr<DecodeLimits> limits = DecodeLimitsFrom(*parsed);
  if (!limits.ok()) return ReportError("export", limits.status());
  StatusOr<LmapContents> contents = LoadLmapContents(parsed->positional[0], *limits);
  if (!contents.ok()) return ReportError("export", contents.status());
  const std::vector<Layer> layers = LayersOf(*contents);
  const std::string text = csv       ? ToCsv(layers)
                           : geojson ? ToGeoJson(layers)
                                     : ToSvg(layers, contents->grid);
  Status written = WriteFileAtomic(*out, text);
  if (!written.ok()) return ReportError("export", written);
  return kExitOk;
}

}  // namespace linemap::cli
