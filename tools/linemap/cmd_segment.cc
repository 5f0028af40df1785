// linemap segment MAP [--pose X,Y] -o OUT.json [--geojson]: room-border
// chains and furniture blobs (Kosteley et al., section 3.2 B and C), written
// in map-frame metres through cell centres.
#include <chrono>
#include <cstdio>
#include <string>

#include "format/file_io.h"
#include "linemap/segmentation.h"
#include "tools/linemap/commands.h"
#include "tools/linemap/json.h"
#include "tools/linemap/map_input.h"

namespace linemap::cli {

const CommandSpec kSegmentSpec = {
    "segment",
    "MAP [--pose X,Y] -o OUT.json [--geojson] [--paper-border]",
    "find room-border chains and furniture blobs",
    "Each room is the free space around the robot (--pose) or, without it, every\n"
    "free component of at least 400 cells; its border is a closed chain of cells\n"
    "(paper: morphology + Lee algorithm). Blobs are the obstacles the free space\n"
    "encloses. Coordinates are map-frame metres of cell centres.",
    WithMapLoadOptions({
        {"--pose", "X,Y", "robot position in map-frame metres (default: all large rooms)"},
        {"-o", "OUT.json", "output file (required)"},
        {"--geojson", "",
         "write GeoJSON (Polygon per room chain and blob outline, "
         "property layer: room_border | furniture)"},
        {"--paper-border", "",
         "heavy border exactly as the paper: the shortest path may "
         "also cut across narrow parts of the room (default: off)"},
    }),
    1,
    1,
};

namespace {

std::string PointJson(const Grid& grid, const CellIndex& cell) {
  double x = 0, y = 0;
  grid.CellToWorld(cell.col, cell.row, &x, &y);
  return "[" + JsonNumber(x) + "," + JsonNumber(y) + "]";
}

// Points of a chain; `close_ring` repeats the first point (GeoJSON rings).
std::string ChainJson(const Grid& grid, const std::vector<CellIndex>& chain, bool close_ring) {
  std::string out = "[";
  for (std::size_t i = 0; i < chain.size(); ++i) {
    if (i) out += ",";
    out += PointJson(grid, chain[i]);
  }
  if (close_ring && !chain.empty()) out += "," + PointJson(grid, chain.front());
  return out + "]";
}

std::string BoxJson(const Grid& grid, const BoundingBox& box) {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  grid.CellToWorld(box.min_col - 0.5, box.min_row - 0.5, &x0, &y0);
  grid.CellToWorld(box.max_col + 0.5, box.max_row + 0.5, &x1, &y1);
  return "[" + JsonNumber(x0) + "," + JsonNumber(y0) + "," + JsonNumber(x1) + "," + JsonNumber(y1) +
         "]";
}

// The box's outer cell edges as a closed counter-clockwise ring.
std::string BoxRingJson(const Grid& grid, const BoundingBox& box) {
  const double c0 = box.min_col - 0.5, c1 = box.max_col + 0.5;
  const double r0 = box.min_row - 0.5, r1 = box.max_row + 0.5;
  const double corners[5][2] = {{c0, r0}, {c1, r0}, {c1, r1}, {c0, r1}, {c0, r0}};
  std::string out = "[";
  for (int k = 0; k < 5; ++k) {
    double x = 0, y = 0;
    grid.CellToWorld(corners[k][0], corners[k][1], &x, &y);
    out += (k ? ",[" : "[") + JsonNumber(x) + "," + JsonNumber(y) + "]";
  }
  return out + "]";
}

std::string PlainJson(const Grid& grid, const Segmentation& seg) {
  std::string rooms = "[";
  for (std::size_t i = 0; i < seg.rooms.size(); ++i) {
    const RoomBorder& room = seg.rooms[i];
    JsonObject json;
    json.Add("free_cells", std::uint64_t{room.free_cells})
        .Add("enclosed_free_cells", std::uint64_t{room.enclosed_free_cells})
        .Add("closed_by_lee", room.closed_by_lee)
        .Add("chain_cells", std::uint64_t{room.chain.size()})
        .AddRaw("chain", ChainJson(grid, room.chain, false));
    rooms += (i ? "," : "") + json.str();
  }
  std::string blobs = "[";
  for (std::size_t i = 0; i < seg.blobs.size(); ++i) {
    const FurnitureBlob& blob = seg.blobs[i];
    JsonObject json;
    json.Add("cell_count", std::uint64_t{blob.cell_count})
        .AddRaw("first_cell", PointJson(grid, blob.first_cell))
        .AddRaw("bbox", BoxJson(grid, blob.box))
        .AddRaw("outline", ChainJson(grid, blob.outline, false));
    blobs += (i ? "," : "") + json.str();
  }
  const SegmentationTimings& t = seg.timings;
  JsonObject timings;
  timings.Add("layout", t.room_layout_ms)
      .Add("morphology", t.morphology_ms)
      .Add("furniture", t.furniture_ms)
      .Add("border_components", t.border_ms)
      .Add("lee", t.lee_ms)
      .Add("total", t.total_ms);
  JsonObject top;
  top.Add("resolution", grid.meta.resolution)
      .AddRaw("timings_ms", timings.str())
      .AddRaw("rooms", rooms + "]")
      .AddRaw("blobs", blobs + "]");
  return top.str() + "\n";
}

std::string Feature(const std::string& layer, const std::string& ring, std::size_t index) {
  JsonObject props;
  props.Add("layer", layer).Add("index", std::uint64_t{index});
  JsonObject geometry;
  geometry.Add("type", "Polygon").AddRaw("coordinates", "[" + ring + "]");
  JsonObject feature;
  feature.Add("type", "Feature")
      .AddRaw("properties", props.str())
      .AddRaw("geometry", geometry.str());
  return feature.str();
}

std::string GeoJson(const Grid& grid, const Segmentation& seg) {
  std::string features;
  for (std::size_t i = 0; i < seg.rooms.size(); ++i) {
    if (!features.empty()) features += ",";
    features += Feature("room_border", ChainJson(grid, seg.rooms[i].chain, true), i);
  }
  for (std::size_t i = 0; i < seg.blobs.size(); ++i) {
    if (!features.empty()) features += ",";
    const FurnitureBlob& blob = seg.blobs[i];
    // A GeoJSON ring needs 3 distinct points; tiny blobs get their box.
    const std::string ring = blob.outline.size() >= 3 ? ChainJson(grid, blob.outline, true)
                                                      : BoxRingJson(grid, blob.box);
    features += Feature("furniture", ring, i);
  }
  JsonObject top;
  top.Add("type", "FeatureCollection").AddRaw("features", "[" + features + "]");
  return top.str() + "\n";
}

}  // namespace

int RunSegment(const std::vector<std::string>& args) {
  int exit_code = kExitOk;
  std::optional<ParsedArgs> parsed = ParseArgs(kSegmentSpec, args, &exit_code);
  if (!parsed) return exit_code;
  const std::optional<std::string> out_path = parsed->Get("-o");
  if (!out_path || out_path->empty()) {
    return ReportError("segment", InvalidArgumentError("missing -o OUT.json"));
  }
  const std::string& map_path = parsed->positional[0];
  StatusOr<Grid> grid = LoadMapArgument(map_path, *parsed);
  if (!grid.ok()) return ReportError("segment", grid.status());
  SegmentationOptions options;
  if (parsed->Has("--pose")) {
    StatusOr<std::vector<double>> pose = parsed->GetDoubleList("--pose", 2);
    if (!pose.ok()) return ReportError("segment", pose.status());
    CellPoint robot;
    grid->WorldToCell((*pose)[0], (*pose)[1], &robot.col, &robot.row);
    options.robot = robot;
  }
  options.protect_room_interior = !parsed->Has("--paper-border");
  const auto start = std::chrono::steady_clock::now();
  StatusOr<Segmentation> seg = SegmentMap(*grid, options);
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  if (!seg.ok()) return ReportError("segment", seg.status().WithContext(map_path));
  const std::string text = parsed->Has("--geojson") ? GeoJson(*grid, *seg) : PlainJson(*grid, *seg);
  const Status written = WriteFileAtomic(*out_path, text);
  if (!written.ok()) return ReportError("segment", written.WithContext(*out_path));
  const SegmentationTimings& t = seg->timings;
  std::printf("rooms: %zu  blobs: %zu  time: %.2f ms (wall)\n", seg->rooms.size(),
              seg->blobs.size(), ms);
  for (std::size_t i = 0; i < seg->rooms.size(); ++i) {
    const RoomBorder& room = seg->rooms[i];
    std::printf("room %zu: chain %zu cells, encloses %zu of %zu free cells (%.1f%%)%s\n", i,
                room.chain.size(), room.enclosed_free_cells, room.free_cells,
                room.free_cells ? 100.0 * room.enclosed_free_cells / room.free_cells : 0.0,
                room.closed_by_lee ? "" : " [fallback contour]");
  }
  std::printf(
      "stages (CPU ms): layout %.2f  1 morphology %.2f  2 furniture %.2f  3 border components %.2f "
      " "
      "4 Lee %.2f\n",
      t.room_layout_ms, t.morphology_ms, t.furniture_ms, t.border_ms, t.lee_ms);
  return kExitOk;
}

}  // namespace linemap::cli
