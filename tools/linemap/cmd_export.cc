// linemap export IN.lmap -o OUT.csv|OUT.geojson|OUT.svg: the vector layers
// of an .lmap file (wall, room_border, furniture) in map-frame metres.
// CSV and GeoJSON read only the layers; SVG also decodes the map to draw
// the layers over it.
#include <cstdio>
#include <string>

#include "format/file_io.h"
#include "linemap/codec.h"
#include "linemap/lmap_vectors.h"
#include "tools/linemap/commands.h"
#include "tools/linemap/decode_window.h"
#include "tools/linemap/export_layers.h"
#include "tools/linemap/export_svg.h"
#include "tools/linemap/lmap_cli_util.h"

namespace linemap::cli {

namespace {

std::vector<OptionSpec> ExportOptions() {
  std::vector<OptionSpec> options = {
      {"-o", "OUT", "output file; its extension (.csv, .geojson, .json, .svg) picks the format"},
      {"--window", "X0,Y0,X1,Y1",
       "only the items whose box meets the cells whose centres lie in the box (map-frame metres, "
       "edges included)"},
      {"--window-cells", "C0,R0,C1,R1",
       "only the items whose box meets columns C0..C1-1 and rows R0..R1-1"}};
  for (OptionSpec& o : DecodeLimitOptionSpecs()) options.push_back(std::move(o));
  return options;
}

}  // namespace

const CommandSpec kExportSpec = {
    "export",
    "IN.lmap -o OUT.csv|OUT.geojson|OUT.svg [--window X0,Y0,X1,Y1 | --window-cells "
    "C0,R0,C1,R1]",
    "export the layers of an .lmap file as CSV, GeoJSON or SVG",
    "The layers are wall (polylines), room_border (one closed chain of border\n"
    "cells per room) and furniture (closed outlines); coordinates are map-frame\n"
    "metres of cell centres. A version 1.0 file's segments are walls of two\n"
    "points, its room chains and blobs room borders and furniture.\n"
    "CSV: rows layer,x1,y1,x2,y2, one per wall segment and per edge of every\n"
    "closed chain (a one-cell chain gives one zero-length row).\n"
    "GeoJSON: a FeatureCollection; walls are LineStrings, rooms and furniture\n"
    "Polygons (rings counter-clockwise, as RFC 7946 asks; rings of fewer than\n"
    "four positions padded with their last point); properties layer and id, plus kind for rooms "
    "and room_id (null\n"
    "when in no room) for furniture. A wall's id is its index among the file's\n"
    "walls; rooms and furniture have the ids the file stores.\n"
    "SVG: the decoded map (free light, occupied black, unknown grey, as\n"
    "map_saver writes it) with walls in red, room borders in blue and\n"
    "furniture in green over it, north (map +y) up, a scale bar and a legend.\n"
    "With --window or --window-cells (as linemap decode reads them) only the\n"
    "items whose box meets the window are written, whole (not cut at its\n"
    "edge), with the ids they have in the whole file (the exports of several\n"
    "windows merge), reading only the layer sections that reach it; an SVG\n"
    "draws the window's cells and the items clipped to them.",
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
  const bool csv = HasExtension(*out, ".csv");
  const bool geojson = HasExtension(*out, ".geojson") || HasExtension(*out, ".json");
  const bool svg = HasExtension(*out, ".svg");
  if (!csv && !geojson && !svg) {
    return ReportError(
        "export",
        InvalidArgumentError("'" + *out + "' must end in .csv, .geojson (or .json) or .svg"));
  }
  // Before the layers (and for SVG the map) are decoded.
  const Status writable = CheckOutputWritable(*out);
  if (!writable.ok()) return ReportError("export", writable);
  const Status limits_apply = CheckLayerLimitsApplyTo({parsed->positional[0]}, *parsed);
  if (!limits_apply.ok()) return ReportError("export", limits_apply);
  StatusOr<DecodeLimits> limits = DecodeLimitsFrom(*parsed);
  if (!limits.ok()) return ReportError("export", limits.status());
  const std::string& in = parsed->positional[0];
  StatusOr<std::optional<CellWindow>> window = WindowFromArgs(*parsed, in, *limits);
  if (!window.ok()) return ReportError("export", window.status());
  StatusOr<LmapVectors> vectors =
      *window ? LoadLmapVectorsInWindow(in, **window, *limits) : LoadLmapVectors(in, *limits);
  if (!vectors.ok()) return ReportError("export", vectors.status());
  const std::vector<ExportLayer> layers = LayersOf(*vectors);
  std::string text;
  if (svg) {
    StatusOr<Grid> grid = *window ? LoadLmapRegion(in, **window, *limits) : LoadLmap(in, *limits);
    if (!grid.ok()) return ReportError("export", grid.status());
    StatusOr<std::string> drawn = LayersToSvg(layers, *grid);
    if (!drawn.ok()) return ReportError("export", drawn.status());
    text = std::move(*drawn);
  } else {
    text = csv ? LayersToCsv(layers) : LayersToGeoJson(layers);
  }
  Status written = WriteFileAtomic(*out, text);
  if (!written.ok()) return ReportError("export", written);
  // An empty export is what a cells-only file holds, not a failure; say so.
  if (vectors->walls.empty() && vectors->rooms.empty() && vectors->furniture.empty()) {
    std::fprintf(stderr, "linemap export: '%s' has no walls, rooms or furniture%s\n", in.c_str(),
                 *window ? " in the window" : " (saved with --raster-only?)");
  }
  return kExitOk;
}

}  // namespace linemap::cli
