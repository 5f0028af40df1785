// The vector layers of an .lmap file as map-frame features, and their CSV
// and GeoJSON text (used by `linemap export`).
#ifndef LINEMAP_TOOLS_LINEMAP_EXPORT_LAYERS_H_
#define LINEMAP_TOOLS_LINEMAP_EXPORT_LAYERS_H_

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "linemap/lmap_vectors.h"

namespace linemap::cli {

struct WorldPoint {
  double x = 0;  // map-frame metres
  double y = 0;
};

// One wall polyline, room border or furniture outline.
struct LayerFeature {
  // A room's or object's id; a wall's index among the walls of the whole
  // file (LmapVectors::WallIndex), also when a window read only some.
  std::uint64_t id = 0;
  std::string kind;                     // rooms only: "room", "corridor", ...
  std::optional<std::int32_t> room_id;  // furniture only; nullopt when in no room
  std::vector<WorldPoint> points;       // closed features do not repeat the first point
  bool clockwise = false;               // closed features: the ring runs clockwise
};

struct ExportLayer {
  std::string name;     // "wall", "room_border", "furniture"
  bool closed = false;  // rooms and furniture are closed chains
  std::vector<LayerFeature> features;
};

// The three layers, in the order wall, room_border, furniture.
std::vector<ExportLayer> LayersOf(const LmapVectors& vectors);

// layer,x1,y1,x2,y2: one row per wall segment and per edge of every closed
// chain (a one-point chain gives one zero-length row).
std::string LayersToCsv(const std::vector<ExportLayer>& layers);

// A FeatureCollection: walls as LineStrings, rooms and furniture as Polygons.
std::string LayersToGeoJson(const std::vector<ExportLayer>& layers);

// Fixed-point text of a coordinate in metres (micrometre precision).
std::string CoordText(double metres);

}  // namespace linemap::cli

#endif  // LINEMAP_TOOLS_LINEMAP_EXPORT_LAYERS_H_
