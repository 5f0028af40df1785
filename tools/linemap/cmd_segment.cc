// linemap segment MAP -o OUT.json [--geojson] [--method rooms|paper]
// [--pose X,Y] [--paper-border]: rooms split at doorways (default) or the
// paper's room-border chains (Kosteley et al., section 3.2 B and C), and
// furniture blobs, written in map-frame metres through cell centres.
#include <algorithm>
#include <chrono>
#include <cstdint>
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
    "MAP -o OUT.json [--geojson] [--method rooms|paper] [--doors MIN,MAX] [--max-room-area M2] "
    "[--pose X,Y] [--paper-border]",
    "split the free space into rooms at doorways; find furniture blobs",
    "rooms (default): the free space is split into rooms and corridors at doorways\n"
    "(passages 0.5-1.2 m wide narrower than both sides); each room is the closed\n"
    "chain of its boundary cells, with an id, its area and its kind (room or\n"
    "corridor). Blobs are stand-alone obstacles inside rooms (furniture).\n"
    "A doorway is told by the clearance c (cells) at the passage's middle, so\n"
    "the range has up to a cell of slack below and two above: an opening of n\n"
    "cells along the grid (c = ceil(n/2)) is a door when 3c lies in\n"
    "[round(1.5 MIN/res), round(1.5 (MAX/res + 2))]; the default 0.5,1.2 takes\n"
    "openings of 0.45-1.30 m at 0.05 m/cell, 0.5-1.4 m at 0.1 m/cell. A door's\n"
    "width_m is the opening's width (n cells x resolution).\n"
    "paper: each room is the free space around the robot (--pose) or every free\n"
    "component of at least 400 cells, its border closed by morphology and the Lee\n"
    "algorithm. Coordinates are map-frame metres of cell centres.",
    WithMapLoadOptions({
        {"-o", "OUT.json",
         "output file (required; ends in .json, with --geojson in .geojson or .json)"},
        {"--geojson", "",
         "write GeoJSON (Polygon per room with id, area_m2, kind and per blob "
         "outline; Point per door; property layer: room | door | furniture, "
         "room_border with --method paper)"},
        {"--method", "rooms|paper", "segmentation method (default: rooms)"},
        {"--doors", "MIN,MAX",
         "rooms: width range of doorways in metres (default 0.5,1.2; passages in it "
         "split rooms when narrower than both sides; up to a cell of slack below, two above, as "
         "said above)"},
        {"--max-room-area", "M2",
         "rooms: spaces joined by an opening wider than a door stay apart when "
         "together larger than this (square metres; default 0 = no limit)"},
        {"--pose", "X,Y",
         "robot position in map-frame metres (implies --method paper); a position off free "
         "space moves to the nearest free cell at most 3 cells away in column and row (0.15 m at "
         "0.05 m/cell; nearest by that count), else it is refused"},
        {"--paper-border", "",
         "heavy border exactly as the paper: the shortest path may "
         "also cut across narrow parts of the room (implies --method paper)"},
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

// A closed GeoJSON ring through the chain, counter-clockwise as RFC 7946
// asks of exterior rings: a chain traced clockwise is written backwards from
// the same first cell.
std::string RingJson(const Grid& grid, const std::vector<CellIndex>& chain) {
  if (!RunsClockwise(chain)) return ChainJson(grid, chain, true);
  std::vector<CellIndex> reversed = chain;
  std::reverse(reversed.begin() + 1, reversed.end());
  return ChainJson(grid, reversed, true);
}

// A blob's bbox: [x0, y0, x1, y1], the axis-aligned box in map-frame
// metres around the squares of its outline's cells (which run around its
// cells, and around the unknown core or the gaps of a group: the blob's
// cell box) and of its cells (x0 <= x1, y0 <= y1). With a yaw in the origin
// the squares are turned, so the box is that of their turned corners, not
// two corners of the cell box taken into metres. A blob without either
// gets the box of its cell box's corners.
std::string BlobBoxJson(const Grid& grid, const FurnitureBlob& blob) {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  bool first = true;
  const auto add_square = [&](double col, double row) {
    for (const double dc : {-0.5, 0.5}) {
      for (const double dr : {-0.5, 0.5}) {
        double x = 0, y = 0;
        grid.CellToWorld(col + dc, row + dr, &x, &y);
        x0 = first ? x : std::min(x0, x);
        y0 = first ? y : std::min(y0, y);
        x1 = first ? x : std::max(x1, x);
        y1 = first ? y : std::max(y1, y);
        first = false;
      }
    }
  };
  for (const CellIndex& cell : blob.outline) add_square(cell.col, cell.row);
  for (const CellIndex& cell : blob.cells) add_square(cell.col, cell.row);
  if (first) {
    add_square(blob.box.min_col, blob.box.min_row);
    add_square(blob.box.max_col, blob.box.max_row);
    add_square(blob.box.min_col, blob.box.max_row);
    add_square(blob.box.max_col, blob.box.min_row);
  }
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

// The blobs as a JSON array; with `with_room` each names the room it stands
// in (the rooms method numbers rooms; the paper's does not).
std::string BlobsJson(const Grid& grid, const std::vector<FurnitureBlob>& blobs, bool with_room) {
  std::string out = "[";
  for (std::size_t i = 0; i < blobs.size(); ++i) {
    const FurnitureBlob& blob = blobs[i];
    JsonObject json;
    if (with_room) json.Add("room", blob.room);
    json.Add("against_wall", blob.against_wall)
        .Add("cell_count", std::uint64_t{blob.cell_count})
        .AddRaw("first_cell", PointJson(grid, blob.first_cell))
        .AddRaw("bbox", BlobBoxJson(grid, blob))
        .AddRaw("outline", ChainJson(grid, blob.outline, false));
    out += (i ? "," : "") + json.str();
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
  const std::string blobs = BlobsJson(grid, seg.blobs, false);
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
      .Add("method", "paper")
      .AddRaw("timings_ms", timings.str())
      .AddRaw("rooms", rooms + "]")
      .AddRaw("blobs", blobs);
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

std::string GeoFeature(const JsonObject& props, const std::string& type,
                       const std::string& coordinates) {
  JsonObject geometry;
  geometry.Add("type", type).AddRaw("coordinates", coordinates);
  JsonObject feature;
  feature.Add("type", "Feature")
      .AddRaw("properties", props.str())
      .AddRaw("geometry", geometry.str());
  return feature.str();
}

// A blob's ring: its outline, or its box when the outline has fewer than
// the 3 distinct points a GeoJSON ring needs.
std::string BlobRing(const Grid& grid, const FurnitureBlob& blob) {
  return blob.outline.size() >= 3 ? RingJson(grid, blob.outline) : BoxRingJson(grid, blob.box);
}

std::string DoorJson(const Grid& grid, const Doorway& door) {
  JsonObject json;
  json.AddRaw("rooms", "[" + std::to_string(door.room_a) + "," + std::to_string(door.room_b) + "]")
      .Add("width_m", door.width_m)
      .AddRaw("at", PointJson(grid, door.cell));
  return json.str();
}

std::string RoomsPlainJson(const Grid& grid, const Segmentation& seg) {
  std::string rooms = "[";
  for (std::size_t i = 0; i < seg.rooms.size(); ++i) {
    const RoomBorder& room = seg.rooms[i];
    JsonObject json;
    json.Add("id", room.id)
        .Add("kind", RoomKindName(room.kind))
        .Add("area_m2", room.area_m2)
        .Add("cells", std::uint64_t{room.cells})
        .Add("free_cells", std::uint64_t{room.free_cells})
        .Add("width_m", room.width_m)
        .Add("chain_cells", std::uint64_t{room.chain.size()})
        .AddRaw("chain", ChainJson(grid, room.chain, false));
    rooms += (i ? "," : "") + json.str();
  }
  std::string doors = "[";
  for (std::size_t i = 0; i < seg.doors.size(); ++i) {
    doors += (i ? "," : "") + DoorJson(grid, seg.doors[i]);
  }
  const std::string blobs = BlobsJson(grid, seg.blobs, true);
  const SegmentationTimings& t = seg.timings;
  JsonObject timings;
  timings.Add("clearance", t.clearance_ms)
      .Add("flooding", t.flooding_ms)
      .Add("chains", t.chains_ms)
      .Add("total", t.total_ms);
  JsonObject top;
  top.Add("resolution", grid.meta.resolution)
      .Add("method", "rooms")
      .AddRaw("timings_ms", timings.str())
      .AddRaw("rooms", rooms + "]")
      .AddRaw("doors", doors + "]")
      .AddRaw("blobs", blobs);
  return top.str() + "\n";
}

std::string RoomsGeoJson(const Grid& grid, const Segmentation& seg) {
  std::string features;
  auto add = [&](const std::string& feature) {
    features += (features.empty() ? "" : ",") + feature;
  };
  for (const RoomBorder& room : seg.rooms) {
    JsonObject props;
    props.Add("layer", "room")
        .Add("id", room.id)
        .Add("area_m2", room.area_m2)
        .Add("kind", RoomKindName(room.kind));
    // A ring needs 3 distinct points; a room that thin gets its box.
    const std::string ring =
        room.chain.size() >= 3 ? RingJson(grid, room.chain) : BoxRingJson(grid, room.box);
    add(GeoFeature(props, "Polygon", "[" + ring + "]"));
  }
  for (const Doorway& door : seg.doors) {
    JsonObject props;
    props.Add("layer", "door")
        .AddRaw("rooms",
                "[" + std::to_string(door.room_a) + "," + std::to_string(door.room_b) + "]")
        .Add("width_m", door.width_m);
    add(GeoFeature(props, "Point", PointJson(grid, door.cell)));
  }
  for (std::size_t i = 0; i < seg.blobs.size(); ++i) {
    const FurnitureBlob& blob = seg.blobs[i];
    JsonObject props;
    props.Add("layer", "furniture")
        .Add("index", std::uint64_t{i})
        .Add("room", blob.room)
        .Add("cells", std::uint64_t{blob.cell_count})
        .AddRaw("bbox", BlobBoxJson(grid, blob));
    add(GeoFeature(props, "Polygon", "[" + BlobRing(grid, blob) + "]"));
  }
  JsonObject top;
  top.Add("type", "FeatureCollection").AddRaw("features", "[" + features + "]");
  return top.str() + "\n";
}

// "1 corridor", "0 corridors", "2 rooms".
std::string Counted(std::size_t n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

void PrintRooms(const Segmentation& seg, double wall_ms) {
  std::size_t corridors = 0;
  for (const RoomBorder& room : seg.rooms) corridors += room.kind == RoomKind::kCorridor;
  std::printf("rooms: %zu (%s, %s)  doors: %zu  blobs: %zu  time: %.2f ms (wall)\n",
              seg.rooms.size(), Counted(seg.rooms.size() - corridors, "room", "rooms").c_str(),
              Counted(corridors, "corridor", "corridors").c_str(), seg.doors.size(),
              seg.blobs.size(), wall_ms);
  for (const RoomBorder& room : seg.rooms) {
    std::printf("room %d: %-8s %8.2f m^2  width %.2f m  chain %zu cells\n", room.id,
                RoomKindName(room.kind), room.area_m2, room.width_m, room.chain.size());
  }
  const SegmentationTimings& t = seg.timings;
  std::printf("stages (CPU ms): clearance %.2f  flooding %.2f  chains and furniture %.2f\n",
              t.clearance_ms, t.flooding_ms, t.chains_ms);
}

std::string GeoJson(const Grid& grid, const Segmentation& seg) {
  std::string features;
  for (std::size_t i = 0; i < seg.rooms.size(); ++i) {
    if (!features.empty()) features += ",";
    features += Feature("room_border", RingJson(grid, seg.rooms[i].chain), i);
  }
  for (std::size_t i = 0; i < seg.blobs.size(); ++i) {
    if (!features.empty()) features += ",";
    const FurnitureBlob& blob = seg.blobs[i];
    // A GeoJSON ring needs 3 distinct points; tiny blobs get their box.
    const std::string ring =
        blob.outline.size() >= 3 ? RingJson(grid, blob.outline) : BoxRingJson(grid, blob.box);
    features += Feature("furniture", ring, i);
  }
  JsonObject top;
  top.Add("type", "FeatureCollection").AddRaw("features", "[" + features + "]");
  return top.str() + "\n";
}

// GeoJSON is JSON, so its file may end in either; plain JSON under a
// .geojson name would be taken for GeoJSON.
Status CheckOutputName(const std::string& path, const ParsedArgs& args) {
  if (args.Has("--geojson")) return CheckOutputExtension(path, {".geojson", ".json"}, "GeoJSON");
  return CheckOutputExtension(path, {".json"}, "JSON (GeoJSON with --geojson)");
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
  Status named = CheckOutputName(*out_path, *parsed);
  // Before the segmentation, not after it.
  if (named.ok()) named = CheckOutputWritable(*out_path);
  if (!named.ok()) return ReportError("segment", named);
  const std::string& map_path = parsed->positional[0];
  StatusOr<Grid> grid = LoadMapArgument(map_path, *parsed);
  if (!grid.ok()) return ReportError("segment", grid.status());
  SegmentationOptions options;
  const std::optional<std::string> method = parsed->Get("--method");
  if (method && *method != "rooms" && *method != "paper") {
    return ReportError(
        "segment", InvalidArgumentError("--method must be rooms or paper, not '" + *method + "'"));
  }
  const bool paper =
      (method && *method == "paper") || parsed->Has("--pose") || parsed->Has("--paper-border");
  if (method && *method == "rooms" && (parsed->Has("--pose") || parsed->Has("--paper-border"))) {
    return ReportError("segment",
                       InvalidArgumentError("--pose and --paper-border need --method paper"));
  }
  // The reverse: the rooms method's options would be ignored by the paper's.
  for (const char* rooms_only : {"--doors", "--max-room-area"}) {
    if (paper && parsed->Has(rooms_only)) {
      return ReportError(
          "segment", InvalidArgumentError(std::string(rooms_only) +
                                          " is an option of --method rooms; --method paper (which "
                                          "--pose and --paper-border imply) has no doorways"));
    }
  }
  options.method = paper ? SegmentationMethod::kPaperBorder : SegmentationMethod::kRooms;
  if (parsed->Has("--doors")) {
    StatusOr<std::vector<double>> doors = parsed->GetDoubleList("--doors", 2);
    if (!doors.ok()) return ReportError("segment", doors.status());
    options.min_door_width_m = (*doors)[0];
    options.max_door_width_m = (*doors)[1];
  }
  StatusOr<double> max_area = parsed->GetDouble("--max-room-area", 0.0);
  if (!max_area.ok()) return ReportError("segment", max_area.status());
  options.max_room_area_m2 = *max_area;
  if (parsed->Has("--pose")) {
    StatusOr<std::vector<double>> pose = parsed->GetDoubleList("--pose", 2);
    if (!pose.ok()) return ReportError("segment", pose.status());
    options.robot = RobotCellPoint(*grid, (*pose)[0], (*pose)[1]);
  }
  options.protect_room_interior = !parsed->Has("--paper-border");
  const auto start = std::chrono::steady_clock::now();
  StatusOr<Segmentation> seg = SegmentMap(*grid, options);
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  if (!seg.ok()) return ReportError("segment", seg.status().WithContext("'" + map_path + "'"));
  const bool geojson = parsed->Has("--geojson");
  const std::string text =
      paper ? (geojson ? GeoJson(*grid, *seg) : PlainJson(*grid, *seg))
            : (geojson ? RoomsGeoJson(*grid, *seg) : RoomsPlainJson(*grid, *seg));
  const Status written = WriteFileAtomic(*out_path, text);
  if (!written.ok()) return ReportError("segment", written);  // it names the file
  if (!paper) {
    PrintRooms(*seg, ms);
    return kExitOk;
  }
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
