// linemap lines MAP [-o LINES.csv] [--method rmline|linemap] ...: extract wall
// line segments, write them as CSV in map-frame metres and print the paper's
// measures (RM-Line, Liu & Zhang 2022, section 3.1).
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include "format/file_io.h"
#include "linemap/lines.h"
#include "tools/linemap/commands.h"
#include "tools/linemap/json.h"
#include "tools/linemap/map_input.h"

namespace linemap::cli {

const CommandSpec kLinesSpec = {
    "lines",
    "MAP [-o LINES.csv] [--method linemap|rmline] [--dtheta D] [--ds S] [--epsilon E] "
    "[--max-added-cost C] [--pose X,Y] [--json]",
    "extract wall line segments from a map (RM-Line or linemap's extractor)",
    "Segments are fitted to the edge map: obstacle cells 4-adjacent to the free cells\n"
    "flooded from --pose (or from every free cell without it). LINES.csv has the header\n"
    "layer,x1,y1,x2,y2 and one row per segment (layer 'segment'), in map-frame metres\n"
    "through cell centres. Printed: the number of lines, DisPL_ave (mean distance from\n"
    "an edge cell centre to the nearest segment, RM-Line Eq. 5) in cm and cells, the\n"
    "largest such distance in cells, and the extraction time in ms. The linemap\n"
    "extractor leaves the edge cells of furniture blobs (stand-alone objects) to\n"
    "the furniture layer an .lmap file stores beside the walls (`segment` lists\n"
    "them); they have no segment here, so on maps with furniture DisPL_ave and\n"
    "'within 1' count them far from every line ('furniture:' says how many;\n"
    "`eval` of the .lmap counts the cells in furniture as covered).\n"
    "The options marked linemap or RM-Line apply to that method only; given with\n"
    "the other they are refused.",
    WithMapLoadOptions({
        {"-o", "LINES.csv",
         "write the segments as CSV (layer,x1,y1,x2,y2; metres); the name ends in .csv"},
        {"--method", "NAME", "linemap (default) or rmline (the paper's method)"},
        {"--dtheta", "D", "RM-Line ray angle step in degrees (default 1)"},
        {"--ds", "S", "RM-Line scoring point spacing in cells, (0, 1] (default 0.5)"},
        {"--epsilon", "E",
         "linemap: max distance of an edge cell to its segment, cells (default 1)"},
        {"--max-added-cost", "C",
         "linemap: a merge may add at most C cells to the summed cell-to-segment distance "
         "(default 3; lower = closer fit, more lines)"},
        {"--straight-walls", "",
         "linemap: one segment per straight wall instead of following the pixel steps of "
         "slanted walls (fewer lines, higher DisPL_ave on clean maps; see StraightWalls in "
         "linemap/lines.h)"},
        {"--pose", "X,Y", "robot position in map metres; flood only its free component"},
        {"--json", "",
         "print one JSON object with keys lines, displ_cm, displ_cells, "
         "displ_max_cells, ms"},
    }),
    1,
    1,
};

namespace {

StatusOr<LineExtractionOptions> OptionsFromArgs(const ParsedArgs& args, const Grid& grid) {
  LineExtractionOptions options;
  if (args.Has("--straight-walls")) options = StraightWalls(options);
  const std::string method = args.Get("--method").value_or("linemap");
  if (method == "rmline") {
    options.method = LineMethod::kRmLine;
  } else if (method == "linemap") {
    options.method = LineMethod::kLinemap;
  } else {
    return InvalidArgumentError("--method must be rmline or linemap, not '" + method + "'");
  }
  // An option of the other method would be ignored without a word.
  const bool rmline = method == "rmline";
  for (const char* option :
       rmline ? std::vector<const char*>{"--epsilon", "--max-added-cost", "--straight-walls"}
              : std::vector<const char*>{"--dtheta", "--ds"}) {
    if (args.Has(option)) {
      return InvalidArgumentError(std::string(option) + " is an option of the " +
                                  (rmline ? "linemap" : "rmline") + " extractor, not of " + method);
    }
  }
  LINEMAP_ASSIGN_OR_RETURN(options.rmline_dtheta_deg,
                           args.GetDouble("--dtheta", options.rmline_dtheta_deg));
  LINEMAP_ASSIGN_OR_RETURN(options.rmline_ds_cells,
                           args.GetDouble("--ds", options.rmline_ds_cells));
  LINEMAP_ASSIGN_OR_RETURN(options.epsilon_cells,
                           args.GetDouble("--epsilon", options.epsilon_cells));
  if (!(options.rmline_dtheta_deg > 0 && options.rmline_dtheta_deg <= 180)) {
    return InvalidArgumentError("--dtheta must be in (0, 180] degrees");
  }
  if (!(options.rmline_ds_cells > 0 && options.rmline_ds_cells <= 1)) {
    return InvalidArgumentError("--ds must be in (0, 1] cells");
  }
  LINEMAP_ASSIGN_OR_RETURN(options.max_added_cost_cells,
                           args.GetDouble("--max-added-cost", options.max_added_cost_cells));
  if (!(options.max_added_cost_cells >= 0)) {
    return InvalidArgumentError("--max-added-cost must be at least 0 cells");
  }
  if (!(options.epsilon_cells >= 0.5)) {
    return InvalidArgumentError("--epsilon must be at least 0.5 cells");
  }
  LINEMAP_ASSIGN_OR_RETURN(std::vector<double> pose, args.GetDoubleList("--pose", 2));
  if (!pose.empty()) {
    options.robot = RobotCellPoint(grid, pose[0], pose[1]);
  }
  return options;
}

std::string SegmentsCsv(const Grid& grid, const std::vector<LineSegment>& segments) {
  std::string csv = "layer,x1,y1,x2,y2\n";
  char line[160];
  for (const LineSegment& s : segments) {
    double x1 = 0, y1 = 0, x2 = 0, y2 = 0;
    grid.CellToWorld(s.x1, s.y1, &x1, &y1);
    grid.CellToWorld(s.x2, s.y2, &x2, &y2);
    std::snprintf(line, sizeof(line), "segment,%.6f,%.6f,%.6f,%.6f\n", x1, y1, x2, y2);
    csv += line;
  }
  return csv;
}

}  // namespace

int RunLines(const std::vector<std::string>& args) {
  int exit_code = kExitOk;
  std::optional<ParsedArgs> parsed = ParseArgs(kLinesSpec, args, &exit_code);
  if (!parsed) return exit_code;
  if (std::optional<std::string> out = parsed->Get("-o")) {
    Status named = CheckOutputExtension(*out, {".csv"}, "CSV");
    // Before the extraction, not after it.
    if (named.ok()) named = CheckOutputWritable(*out);
    if (!named.ok()) return ReportError("lines", named);
  }
  const std::string& map_path = parsed->positional[0];
  StatusOr<Grid> grid = LoadMapArgument(map_path, *parsed);
  if (!grid.ok()) return ReportError("lines", grid.status());
  StatusOr<LineExtractionOptions> options = OptionsFromArgs(*parsed, *grid);
  if (!options.ok()) return ReportError("lines", options.status());

  const auto start = std::chrono::steady_clock::now();
  StatusOr<LineExtraction> extraction = ExtractLines(*grid, *options);
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  if (!extraction.ok()) {
    return ReportError("lines", extraction.status().WithContext("'" + map_path + "'"));
  }
  const LineFidelity fidelity = MeasureLineFidelity(extraction->edges, extraction->segments);

  if (std::optional<std::string> out = parsed->Get("-o")) {
    Status written = WriteFileAtomic(*out, SegmentsCsv(*grid, extraction->segments));
    if (!written.ok()) return ReportError("lines", written);
  }
  const double cm_per_cell = grid->meta.resolution * 100.0;
  const std::uint64_t lines = extraction->segments.size();
  if (parsed->Has("--json")) {
    JsonObject json;
    json.Add("lines", lines)
        .Add("displ_cm", fidelity.displ_ave_cells * cm_per_cell)
        .Add("displ_cells", fidelity.displ_ave_cells)
        .Add("displ_max_cells", fidelity.displ_max_cells)
        .Add("ms", ms)
        .Add("edge_cells", std::uint64_t{fidelity.edge_cells})
        .Add("share_within_1", fidelity.share_within_1)
        .Add("cells_left_to_blobs", std::uint64_t{extraction->cells_left_to_blobs});
    std::printf("%s\n", json.str().c_str());
    return kExitOk;
  }
  std::printf("lines:      %llu\n", static_cast<unsigned long long>(lines));
  std::printf("DisPL_ave:  %.3f cm (%.4f cells)\n", fidelity.displ_ave_cells * cm_per_cell,
              fidelity.displ_ave_cells);
  std::printf("max:        %.4f cells\n", fidelity.displ_max_cells);
  std::printf("within 1:   %.2f%% of %zu edge cells\n", 100.0 * fidelity.share_within_1,
              fidelity.edge_cells);
  if (options->method == LineMethod::kLinemap) {
    std::printf("furniture:  %zu edge cells left to the furniture layer\n",
                extraction->cells_left_to_blobs);
  }
  std::printf("time:       %.1f ms\n", ms);
  return kExitOk;
}

}  // namespace linemap::cli
