// linemap info MAP [--json]: size, resolution, origin and cell counts.
#include <algorithm>
#include <cstdio>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "linemap/codec.h"
#include "tools/linemap/commands.h"
#include "tools/linemap/json.h"
#include "tools/linemap/lmap_cli_util.h"
#include "tools/linemap/map_input.h"

namespace linemap::cli {

const CommandSpec kInfoSpec = {
    "info",
    "MAP [--json]",
    "print a map's size, resolution, origin and free / occupied / unknown cell counts",
    "MAP is a ROS map YAML (its image: PGM or PNG), a bare PGM/PNG image, which\n"
    "gets the defaults 0.05 m/cell, origin 0,0,0 and thresholds 0.65 / 0.196,\n"
    "or an .lmap file: then its version, header, chunks (size, coder), the\n"
    "decoded cell counts and its vector layers are printed: walls (polylines\n"
    "and the straight segments they are made of), rooms and furniture objects\n"
    "(for a version 1.0 file: segments, room chains and blobs), and its metadata\n"
    "(creator, time, frame_id, robot_pose; tolerance, the T of a file saved\n"
    "with --tolerance T), one 'meta:' line per entry, with control characters\n"
    "and backslashes escaped as in C (\\n, \\x1b, \\\\): the format does not\n"
    "check the text (encode refuses them in --time). A file saved within a\n"
    "tolerance says so on its first line, with T in cells and metres.",
    WithMapLoadOptions({{"--json", "",
                         "print one JSON object with keys width, height, "
                         "resolution, origin, free, occupied, unknown, mode, negate, "
                         "occupied_thresh, free_thresh (an .lmap file "
                         "also: version, lossless, tolerance_cells (the T a file saved within "
                         "a tolerance names, else null), layers (false for a file saved "
                         "--raster-only, which holds no layer chunk), walls, wall_segments, "
                         "rooms, "
                         "furniture, chunks, and metadata: an object of the file's metadata "
                         "as text, such as creator, time, frame_id and robot_pose (\"x y "
                         "yaw\") from encode --metadata, --time and --pose, and tolerance "
                         "from --tolerance, {} when it has none, a "
                         "key stored more than once giving an array of its values; a 1.0 "
                         "file also segments, room_chains, blobs)"}}),
    1,
    1,
};

namespace {

// Whether the file holds a layer chunk: one saved --raster-only has none,
// which is not the same as layers found empty.
bool HasLayerChunk(const LmapContents& contents) {
  return std::any_of(contents.chunks.begin(), contents.chunks.end(), [](const LmapChunkInfo& c) {
    return c.type == "LAYR" || c.type == "WALL" || c.type == "ROOM" || c.type == "FURN" ||
           c.type == "SEGS" || c.type == "BLOB";
  });
}

// Counts of a file's vector layers; a 1.0 file's segments are two-point
// walls, its room chains rooms and its blobs furniture, as LoadLmapVectors
// reads them.
struct LayerCounts {
  std::size_t walls = 0;
  std::size_t wall_segments = 0;  // straight pieces: points - 1 per polyline
  std::size_t rooms = 0;
  std::size_t furniture = 0;
};

LayerCounts CountLayers(const LmapContents& c) {
  LayerCounts n;
  if (c.major >= 2) {
    n.walls = c.walls.size();
    for (const WallPolyline& w : c.walls)
      n.wall_segments += w.points.empty() ? 0 : w.points.size() - 1;
    n.rooms = c.rooms.size();
    n.furniture = c.furniture.size();
  } else {
    n.walls = n.wall_segments = c.segments.size();
    n.rooms = c.room_chains.size();
    n.furniture = c.blob_outlines.size();
  }
  return n;
}

// The metadata as one JSON object. The format keeps a key stored more than
// once with all its values, in order (spec/format.md, 4.3); such a key gets
// the array of them, so that every key is named once.
std::string MetadataJson(const std::vector<std::pair<std::string, std::string>>& metadata) {
  std::vector<std::string> keys;
  std::map<std::string, std::vector<std::string>> values;
  for (const auto& [key, value] : metadata) {
    if (values.count(key) == 0) keys.push_back(key);
    values[key].push_back(value);
  }
  JsonObject json;
  for (const std::string& key : keys) {
    const std::vector<std::string>& all = values[key];
    if (all.size() == 1) {
      json.Add(key, all.front());
      continue;
    }
    std::string array = "[";
    for (const std::string& value : all) array += (array.size() > 1 ? "," : "") + JsonString(value);
    json.AddRaw(key, array + "]");
  }
  return json.str();
}

// Metadata text as one line: the format does not validate it (linemap's
// encode refuses control characters in --time, other writers may store
// them), so control characters and backslashes are escaped as in C ("\n",
// "\x1b", "\\") rather than breaking info's one field per line.
std::string Printable(const std::string& text) {
  std::string out;
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (c == '\\') {
      out += "\\\\";
    } else if (c == '\n') {
      out += "\\n";
    } else if (c == '\t') {
      out += "\\t";
    } else if (c == '\r') {
      out += "\\r";
    } else if (byte < 0x20 || byte == 0x7f) {
      char hex[8];
      std::snprintf(hex, sizeof(hex), "\\x%02x", byte);
      out += hex;
    } else {
      out += c;
    }
  }
  return out;
}

// The resolution and origin, each the shortest decimal that reads back as
// the same double (as the JSON and a decoded map's YAML give them): six
// significant digits put a UTM-sized origin metres away.
void PrintFrame(const MapMetadata& meta) {
  std::printf("resolution: %s m/cell\n", JsonNumber(meta.resolution).c_str());
  std::printf("origin:     x %s m, y %s m, yaw %s rad\n", JsonNumber(meta.origin.x).c_str(),
              JsonNumber(meta.origin.y).c_str(), JsonNumber(meta.origin.yaw).c_str());
}

// `linemap info X.lmap`: the header fields, each chunk with its size and
// coder, and the counts of the vector layers.
int RunLmapInfo(const std::string& path, const ParsedArgs& args) {
  const Status applies = CheckMapOptionsApplyTo(path, args);
  if (!applies.ok()) return ReportError("info", applies);
  StatusOr<MapReadOptions> options = MapReadOptionsFrom(args);
  if (!options.ok()) return ReportError("info", options.status());
  StatusOr<LmapContents> contents = LoadLmapContents(path, options->lmap);
  if (!contents.ok()) return ReportError("info", contents.status());
  const Grid& grid = contents->grid;
  const CellCounts counts = grid.Count();
  const LayerCounts layers = CountLayers(*contents);
  const bool v1 = contents->major < 2;
  const bool has_layers = HasLayerChunk(*contents);
  const std::optional<int> tolerance =
      ToleranceCellsOf(contents->major, contents->lossless, contents->metadata);
  if (args.Has("--json")) {
    std::string chunks = "[";
    for (const LmapChunkInfo& c : contents->chunks) {
      JsonObject o;
      o.Add("type", c.type).Add("bytes", std::uint64_t{c.payload_bytes}).Add("coder", c.coder);
      chunks += (chunks.size() > 1 ? "," : "") + o.str();
    }
    chunks += "]";
    JsonObject json;
    json.Add("version", std::to_string(contents->major) + "." + std::to_string(contents->minor))
        .Add("width", grid.width())
        .Add("height", grid.height())
        .Add("resolution", grid.meta.resolution)
        .Add("origin",
             std::vector<double>{grid.meta.origin.x, grid.meta.origin.y, grid.meta.origin.yaw})
        .Add("lossless", contents->lossless)
        .AddRaw("tolerance_cells", tolerance ? std::to_string(*tolerance) : "null")
        .Add("layers", has_layers)
        .Add("walls", std::uint64_t{layers.walls})
        .Add("wall_segments", std::uint64_t{layers.wall_segments})
        .Add("rooms", std::uint64_t{layers.rooms})
        .Add("furniture", std::uint64_t{layers.furniture});
    if (v1) {
      json.Add("segments", std::uint64_t{contents->segments.size()})
          .Add("room_chains", std::uint64_t{contents->room_chains.size()})
          .Add("blobs", std::uint64_t{contents->blob_outlines.size()});
    }
    // The pixel fields, as for a map YAML: the text prints them, and a
    // decoded map's YAML carries them.
    json.Add("free", std::uint64_t{counts.free})
        .Add("occupied", std::uint64_t{counts.occupied})
        .Add("unknown", std::uint64_t{counts.unknown})
        .Add("mode", MapModeName(grid.meta.mode))
        .Add("negate", grid.meta.negate)
        .Add("occupied_thresh", grid.meta.occupied_thresh)
        .Add("free_thresh", grid.meta.free_thresh)
        .AddRaw("chunks", chunks)
        .AddRaw("metadata", MetadataJson(contents->metadata));
    std::printf("%s\n", json.str().c_str());
    return kExitOk;
  }
  // A 2.x file that is not exact was saved within a tolerance (its cells
  // in blocks); only the former 1.0 mode wrote lossy files without one.
  // Files written before the metadata named T say no more than that.
  std::string fidelity = contents->lossless    ? "lossless"
                         : contents->major > 1 ? "within a tolerance"
                                               : "lossy";
  if (tolerance) {
    char text[96];
    std::snprintf(text, sizeof(text), " of %d cell%s (%g m)", *tolerance,
                  *tolerance == 1 ? "" : "s", *tolerance * grid.meta.resolution);
    fidelity += text;
  }
  std::printf("file:       %s (.lmap version %d.%d, %s)\n", path.c_str(), contents->major,
              contents->minor, fidelity.c_str());
  std::printf("size:       %d x %d cells\n", grid.width(), grid.height());
  PrintFrame(grid.meta);
  std::printf("pixels:     mode %s, negate %d, occupied_thresh %g, free_thresh %g\n",
              MapModeName(grid.meta.mode), grid.meta.negate ? 1 : 0, grid.meta.occupied_thresh,
              grid.meta.free_thresh);
  if (v1) {
    std::printf("geometry:   %zu segments, %zu room chains, %zu blobs\n", contents->segments.size(),
                contents->room_chains.size(), contents->blob_outlines.size());
  } else if (!has_layers) {
    std::printf("layers:     none (cells only)\n");
  } else {
    std::printf("layers:     %zu walls (%zu segments), %zu rooms, %zu furniture\n", layers.walls,
                layers.wall_segments, layers.rooms, layers.furniture);
  }
  std::printf("decoded:    %zu free, %zu occupied, %zu unknown\n", counts.free, counts.occupied,
              counts.unknown);
  for (const auto& [key, value] : contents->metadata) {
    std::printf("meta:       %s = %s\n", Printable(key).c_str(), Printable(value).c_str());
  }
  for (const LmapChunkInfo& c : contents->chunks) {
    std::printf("chunk:      %s %8zu bytes  %s\n", c.type.c_str(), c.payload_bytes,
                c.coder.c_str());
  }
  return kExitOk;
}

}  // namespace

int RunInfo(const std::vector<std::string>& args) {
  int exit_code = kExitOk;
  std::optional<ParsedArgs> parsed = ParseArgs(kInfoSpec, args, &exit_code);
  if (!parsed) return exit_code;
  if (IsLmapPath(parsed->positional[0])) return RunLmapInfo(parsed->positional[0], *parsed);
  StatusOr<Grid> grid = LoadMapArgument(parsed->positional[0], *parsed);
  if (!grid.ok()) return ReportError("info", grid.status());
  const CellCounts counts = grid->Count();
  const MapMetadata& meta = grid->meta;
  if (parsed->Has("--json")) {
    JsonObject json;
    json.Add("width", grid->width())
        .Add("height", grid->height())
        .Add("resolution", meta.resolution)
        .Add("origin", std::vector<double>{meta.origin.x, meta.origin.y, meta.origin.yaw})
        .Add("free", std::uint64_t{counts.free})
        .Add("occupied", std::uint64_t{counts.occupied})
        .Add("unknown", std::uint64_t{counts.unknown})
        .Add("mode", MapModeName(meta.mode))
        .Add("negate", meta.negate)
        .Add("occupied_thresh", meta.occupied_thresh)
        .Add("free_thresh", meta.free_thresh);
    std::printf("%s\n", json.str().c_str());
    return kExitOk;
  }
  const double total = static_cast<double>(grid->size());
  auto share = [total](std::size_t n) { return total > 0 ? 100.0 * n / total : 0.0; };
  std::printf("map:        %s\n", parsed->positional[0].c_str());
  std::printf("size:       %d x %d cells (%.2f x %.2f m)\n", grid->width(), grid->height(),
              grid->width() * meta.resolution, grid->height() * meta.resolution);
  PrintFrame(meta);
  std::printf("pixels:     mode %s, negate %d, occupied_thresh %g, free_thresh %g\n",
              MapModeName(meta.mode), meta.negate ? 1 : 0, meta.occupied_thresh, meta.free_thresh);
  std::printf("free:       %zu (%.1f%%)\n", counts.free, share(counts.free));
  std::printf("occupied:   %zu (%.1f%%)\n", counts.occupied, share(counts.occupied));
  std::printf("unknown:    %zu (%.1f%%)\n", counts.unknown, share(counts.unknown));
  return kExitOk;
}

}  // namespace linemap::cli
