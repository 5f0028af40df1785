// linemap eval ORIGINAL DECODED_OR_LMAP [--json]: the quality
// measures of a decoded map against the original.
#include <cstdio>

#include "linemap/codec.h"
#include "linemap/lines.h"
#include "tools/linemap/commands.h"
#include "tools/linemap/json.h"
#include "tools/linemap/lmap_cli_util.h"
#include "tools/linemap/map_input.h"

namespace linemap::cli {

const CommandSpec kEvalSpec = {
    "eval",
    "ORIGINAL DECODED_OR_LMAP [--json]",
    "compare a decoded map with the original, cell by cell",
    "DECODED_OR_LMAP is a map (YAML or image) or an .lmap file, which is decoded.\n"
    "Prints: cells equal, obstacle recall and precision within 1 cell, free-space\n"
    "IoU, free regions (50+ cells) merged by the decode (leaks), and unknown cells\n"
    "turned free; for an .lmap file with wall segments also DisPL_ave (mean\n"
    "distance from the original's edge cells to the nearest segment, RM-Line's\n"
    "measure) and the share of edge cells within one cell of a segment.\n"
    "The map-reading options (--negate, --mode, the thresholds, --resolution,\n"
    "--origin) apply to ORIGINAL only: a decoded map's YAML carries its own\n"
    "values. --max-cells limits both. Maps of different sizes are refused.",
    WithMapLoadOptions({{"--json", "", "print one JSON object"}}),
    2,
    2,
};

int RunEval(const std::vector<std::string>& args) {
  int exit_code = kExitOk;
  std::optional<ParsedArgs> parsed = ParseArgs(kEvalSpec, args, &exit_code);
  if (!parsed) return exit_code;
  const std::string& original_path = parsed->positional[0];
  const std::string& decoded_path = parsed->positional[1];
  StatusOr<MapLoadOptions> original_options = MapLoadOptionsFrom(*parsed);
  if (!original_options.ok()) return ReportError("eval", original_options.status());
  StatusOr<Grid> original = LoadMapWithOptions(original_path, *original_options);
  if (!original.ok()) return ReportError("eval", original.status());
  MapLoadOptions decoded_options;  // the file's own values; only the limit is shared
  decoded_options.max_cells = original_options->max_cells;
  StatusOr<Grid> decoded = LoadMapWithOptions(decoded_path, decoded_options);
  if (!decoded.ok()) return ReportError("eval", decoded.status());
  if (original->width() != decoded->width() || original->height() != decoded->height()) {
    return ReportError(
        "eval", InvalidArgumentError(
                    "'" + original_path + "' is " + std::to_string(original->width()) + " x " +
                    std::to_string(original->height()) + " cells but '" + decoded_path + "' is " +
                    std::to_string(decoded->width()) + " x " + std::to_string(decoded->height()) +
                    ": eval compares maps of the same size"));
  }
  const GridComparison m = CompareGrids(*original, *decoded);
  // Line fidelity when the second file is an .lmap with segments.
  std::optional<LineFidelity> fidelity;
  if (IsLmapFile(decoded_path)) {
    DecodeLimits limits;
    limits.max_cells = decoded_options.max_cells;
    StatusOr<LmapContents> contents = LoadLmapContents(decoded_path, limits);
    if (!contents.ok()) return ReportError("eval", contents.status());
    if (!contents->segments.empty() && m.same_geometry) {
      std::vector<LineSegment> lines;
      for (const LatticeSegment& s : contents->segments) {
        lines.push_back(LineSegment{static_cast<double>(s.a.col), static_cast<double>(s.a.row),
                                    static_cast<double>(s.b.col), static_cast<double>(s.b.row)});
      }
      fidelity = MeasureLineFidelity(ComputeEdgeMap(*original), lines);
    }
  }
  if (parsed->Has("--json")) {
    JsonObject json;
    json.Add("same_geometry", m.same_geometry)
        .Add("cells", std::uint64_t{m.cells})
        .Add("cells_equal", std::uint64_t{m.cells_equal})
        .Add("obstacle_recall_1", m.obstacle_recall_1)
        .Add("obstacle_precision_1", m.obstacle_precision_1)
        .Add("free_iou", m.free_iou)
        .Add("leaks", std::uint64_t{m.leaks})
        .Add("unknown_turned_free", std::uint64_t{m.unknown_turned_free})
        .Add("unknown_turned_free_share", m.unknown_turned_free_share);
    if (fidelity) {
      json.Add("displ_ave_cells", fidelity->displ_ave_cells)
          .Add("displ_ave_m", fidelity->displ_ave_cells * original->meta.resolution)
          .Add("edge_share_within_1", fidelity->share_within_1);
    }
    std::printf("%s\n", json.str().c_str());
    return kExitOk;
  }
  std::printf("same geometry:        %s\n", m.same_geometry ? "yes" : "NO");
  std::printf("cells equal:          %zu of %zu (%.4f)\n", m.cells_equal, m.cells,
              m.cells ? static_cast<double>(m.cells_equal) / m.cells : 1.0);
  std::printf("obstacle recall (1):  %.4f\n", m.obstacle_recall_1);
  std::printf("obstacle precision(1):%.4f\n", m.obstacle_precision_1);
  std::printf("free IoU:             %.4f\n", m.free_iou);
  std::printf("leaks:                %zu\n", m.leaks);
  std::printf("unknown turned free:  %zu (%.4f of free)\n", m.unknown_turned_free,
              m.unknown_turned_free_share);
  if (fidelity) {
    std::printf("DisPL_ave:            %.4f cells (%.4f m)\n", fidelity->displ_ave_cells,
                fidelity->displ_ave_cells * original->meta.resolution);
    std::printf("edge cells within 1:  %.4f\n", fidelity->share_within_1);
  }
  return kExitOk;
}

}  // namespace linemap::cli
