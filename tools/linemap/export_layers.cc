#include "tools/linemap/export_layers.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "tools/linemap/json.h"

namespace linemap::cli {

namespace {

std::vector<WorldPoint> ToWorld(const LmapVectors& vectors, const std::vector<CellIndex>& cells) {
  std::vector<WorldPoint> points;
  points.reserve(cells.size());
  for (const CellIndex& c : cells) {
    WorldPoint p;
    vectors.ToWorld(c, &p.x, &p.y);
    points.push_back(p);
  }
  return points;
}

std::string Position(const WorldPoint& p) {
  return "[" + CoordText(p.x) + "," + CoordText(p.y) + "]";
}

std::string Properties(const ExportLayer& layer, const LayerFeature& f) {
  JsonObject o;
  o.Add("layer", layer.name).Add("id", f.id);
  if (layer.name == "room_border") o.Add("kind", f.kind);
  if (layer.name == "furniture") {
    if (f.room_id) {
      o.Add("room_id", std::int64_t{*f.room_id});
    } else {
      o.AddRaw("room_id", "null");
    }
  }
  return o.str();
}

std::string Geometry(const ExportLayer& layer, const LayerFeature& f) {
  std::vector<WorldPoint> points = f.points;
  // RFC 7946 3.1.6: an exterior ring runs counter-clockwise. The chains run
  // either way (a room's border as it was traced), so a clockwise one is
  // written backwards from the same first point.
  if (layer.closed && f.clockwise) std::reverse(points.begin() + 1, points.end());
  std::string coords;
  for (const WorldPoint& p : points) coords += (coords.empty() ? "" : ",") + Position(p);
  if (!layer.closed) return "{\"type\":\"LineString\",\"coordinates\":[" + coords + "]}";
  // A linear ring repeats its first position and has at least four: chains
  // of one or two cells (small furniture) are padded with their last point.
  std::size_t positions = f.points.size() + 1;
  for (; positions < 4; ++positions) coords += "," + Position(points.back());
  coords += "," + Position(points.front());
  return "{\"type\":\"Polygon\",\"coordinates\":[[" + coords + "]]}";
}

}  // namespace

std::string CoordText(double metres) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.6f", metres);
  return text;
}

std::vector<ExportLayer> LayersOf(const LmapVectors& vectors) {
  ExportLayer walls{"wall", false, {}};
  for (std::size_t i = 0; i < vectors.walls.size(); ++i) {
    walls.features.push_back(
        {vectors.WallIndex(i), "", std::nullopt, ToWorld(vectors, vectors.walls[i].points)});
  }
  ExportLayer rooms{"room_border", true, {}};
  for (const RoomOutline& room : vectors.rooms) {
    rooms.features.push_back({room.id, RoomKindName(room.kind), std::nullopt,
                              ToWorld(vectors, room.chain), RunsClockwise(room.chain)});
  }
  ExportLayer furniture{"furniture", true, {}};
  for (const FurnitureObject& object : vectors.furniture) {
    std::optional<std::int32_t> room;
    if (object.room_id >= 0) room = object.room_id;
    furniture.features.push_back(
        {object.id, "", room, ToWorld(vectors, object.outline), RunsClockwise(object.outline)});
  }
  return {walls, rooms, furniture};
}

std::string LayersToCsv(const std::vector<ExportLayer>& layers) {
  std::string out = "layer,x1,y1,x2,y2\n";
  auto row = [&](const std::string& layer, const WorldPoint& p, const WorldPoint& q) {
    out += layer + "," + CoordText(p.x) + "," + CoordText(p.y) + "," + CoordText(q.x) + "," +
           CoordText(q.y) + "\n";
  };
  for (const ExportLayer& layer : layers) {
    for (const LayerFeature& f : layer.features) {
      const std::vector<WorldPoint>& p = f.points;
      if (p.empty()) continue;
      if (p.size() == 1) {
        row(layer.name, p[0], p[0]);
        continue;
      }
      for (std::size_t i = 0; i + 1 < p.size(); ++i) row(layer.name, p[i], p[i + 1]);
      if (layer.closed) row(layer.name, p.back(), p.front());
    }
  }
  return out;
}

std::string LayersToGeoJson(const std::vector<ExportLayer>& layers) {
  std::string out = "{\"type\":\"FeatureCollection\",\"features\":[";
  bool first = true;
  for (const ExportLayer& layer : layers) {
    for (const LayerFeature& f : layer.features) {
      if (f.points.empty()) continue;
      out += std::string(first ? "" : ",") +
             "\n{\"type\":\"Feature\",\"properties\":" + Properties(layer, f) +
             ",\"geometry\":" + Geometry(layer, f) + "}";
      first = false;
    }
  }
  return out + "\n]}\n";
}

}  // namespace linemap::cli
