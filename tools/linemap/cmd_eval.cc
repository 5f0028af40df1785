// linemap eval ORIGINAL DECODED_OR_LMAP [--tolerance T] [--json] [--check]:
// the quality measures of a decoded map against the original, and the
// guarantees of a save within T cells: the T of --tolerance, or the one an
// .lmap file names; with --check, an exit status that says whether the
// second map keeps its promise.
#include <cstdio>
#include <optional>
#include <string>

#include "codec/tolerance/simplify.h"
#include "linemap/codec.h"
#include "linemap/lmap_vectors.h"
#include "tools/linemap/commands.h"
#include "tools/linemap/json.h"
#include "tools/linemap/lmap_cli_util.h"
#include "tools/linemap/map_input.h"

namespace linemap::cli {

const CommandSpec kEvalSpec = {
    "eval",
    "ORIGINAL DECODED_OR_LMAP [--tolerance T] [--json] [--check]",
    "compare a decoded map with the original, cell by cell",
    "DECODED_OR_LMAP is a map (YAML or image) or an .lmap file, which is decoded.\n"
    "Prints: cells equal, obstacle recall and precision within 1 cell, free-space\n"
    "IoU, free regions (50+ cells) merged by the decode (leaks), and unknown cells\n"
    "turned free.\n"
    "For an .lmap file also the fidelity of its vector layers, the RM-Line\n"
    "paper's way: over the original's edge cells (occupied cells with a free\n"
    "4-neighbour), DisPL_ave, the mean Euclidean distance from the cell centre\n"
    "to the nearest wall segment (cells and cm; n/a when the file has no\n"
    "walls), the largest such distance, the share within 1 cell of a wall, and\n"
    "the share within 1 cell of a wall or inside a furniture outline (the\n"
    "outline's cells and the cells whose centres it encloses).\n"
    "The map-reading options (--negate, --mode, the thresholds, --resolution,\n"
    "--origin) apply to ORIGINAL only: a decoded map's YAML carries its own\n"
    "values. --max-cells limits both, --max-segments and --max-objects either\n"
    "that is an .lmap file (refused when neither is). Maps of different sizes\n"
    "are refused.\n"
    "With --tolerance T (whole cells, 0 to 4) also the guarantees of a save\n"
    "within T cells (Chebyshev): the Hausdorff distance between the two maps'\n"
    "occupied cells in each direction, the share of the original's wall-surface\n"
    "cells (occupied, with a free 4-neighbour) with a decoded obstacle within T,\n"
    "free cells moved or lost further than T, unknown turned free further than T\n"
    "from the original free space, free regions joined (leaks) or split, and\n"
    "plans (4-connected, over free cells, from 16 sampled starts to every cell\n"
    "free in both) that exist on one map only or differ in length by more than\n"
    "3 %, and plans of up to 16 steps from every cell beside a change that are\n"
    "not on the other map in as many steps; and whether all hold.\n"
    "Without --tolerance, an .lmap file saved within a tolerance is checked\n"
    "at the T it names (its metadata), on maps of up to 2^26 cells (the\n"
    "checks need some 25 bytes a cell; --tolerance T checks any map) and for\n"
    "T up to 4; otherwise a line says why not.\n"
    "If ORIGINAL is an .lmap file saved within a tolerance, a warning on\n"
    "stderr says the two files may be the other way round.\n"
    "Exit status 0, whatever the figures; with --check, 0 only when the\n"
    "second map keeps its promise (the same size, resolution and origin, and\n"
    "then the guarantees hold at the T checked, or, with no T checked, every\n"
    "cell is equal: an exact save) and 1 when not, with a last line (JSON:\n"
    "check_passed, check) saying why. Bad input exits 2 either way.",
    WithMapLoadOptions(
        {{"--json", "", "print one JSON object"},
         {"--check", "",
          "exit status 1 when the second map breaks its promise (guarantees or exactness)"},
         {"--tolerance", "T", "also check the guarantees of a save within T cells (0..4)"}}),
    2,
    2,
};

namespace {

// A Hausdorff distance as text; -1 stands for "the other map has no
// obstacle at all".
std::string CellsText(int cells) {
  return std::to_string(cells) + (cells == 1 ? " cell" : " cells");
}
std::string DistanceText(int cells) {
  return cells < 0 ? std::string("infinite (no obstacle on the other map)") : CellsText(cells);
}

void PrintToleranceReport(const ToleranceReport& t) {
  std::printf("tolerance:            %s (Chebyshev)\n", CellsText(t.tolerance_cells).c_str());
  std::printf("  Hausdorff orig->dec: %s\n", DistanceText(t.hausdorff_original_to_decoded).c_str());
  std::printf("  Hausdorff dec->orig: %s\n", DistanceText(t.hausdorff_decoded_to_original).c_str());
  std::printf("  wall surface kept:  %.4f (%zu of %zu within T)\n", t.WallSurfaceShare(),
              t.wall_surface_kept, t.wall_surface_cells);
  std::printf("  free moved > T:     %zu\n", t.free_moved_beyond);
  std::printf("  free lost > T:      %zu\n", t.free_lost_beyond);
  std::printf("  unknown->free > T:  %zu\n", t.unknown_turned_free_beyond);
  std::printf("  leaks / splits:     %zu / %zu\n", t.leaks, t.splits);
  std::printf("  plans disagreeing:  %zu of %zu pairs\n", t.plan_disagreements, t.plan_pairs);
  std::printf("  local plans:        %zu of %zu disagree (up to %d steps, beside a change)\n",
              t.local_plan_disagreements, t.local_plans, kLocalPlanSteps);
  std::printf("  guarantees:         %s\n", t.Holds() ? "hold" : "BROKEN");
}

// What --check decides: whether the second map keeps its promise, and why.
// A map checked within a tolerance promises its guarantees; any other, an
// exact copy (a file named within a T that eval did not check included:
// what it guarantees is then unknown). Both keep the map's frame: a map
// moved or rescaled puts every wall elsewhere in the world.
struct CheckVerdict {
  bool passed = false;
  std::string why;
};

// What differs between the two maps' frames (same size: eval refuses
// others), e.g. "resolution 0.05 against 0.1 m/cell"; empty when nothing.
std::string FrameDifference(const MapMetadata& a, const MapMetadata& b) {
  // Shortest exact decimals: six digits would print 0.05 against 0.05.
  const auto pose = [](const Pose2D& p) {
    return JsonNumber(p.x) + "," + JsonNumber(p.y) + "," + JsonNumber(p.yaw);
  };
  std::string out;
  if (a.resolution != b.resolution) {
    out = "resolution " + JsonNumber(a.resolution) + " against " + JsonNumber(b.resolution) +
          " m/cell";
  }
  if (!(a.origin == b.origin)) {
    out += (out.empty() ? "" : "; ") + std::string("origin ") + pose(a.origin) + " against " +
           pose(b.origin);
  }
  return out;
}

CheckVerdict VerdictOf(const GridComparison& m, const std::string& frame_difference,
                       const std::optional<ToleranceReport>& tol) {
  if (!m.same_geometry) {
    return {false, "the two maps' frames differ: " + frame_difference};
  }
  if (tol) {
    return {tol->Holds(), std::string("the guarantees within ") + CellsText(tol->tolerance_cells) +
                              (tol->Holds() ? " hold" : " are broken")};
  }
  const std::size_t differ = m.cells - m.cells_equal;
  if (differ > 0) {
    return {false, std::to_string(differ) + (differ == 1 ? " cell differs" : " cells differ") +
                       " and no tolerance was checked (an exact copy was expected; --tolerance T "
                       "checks the guarantees within T)"};
  }
  return {true, "every cell is equal"};
}

}  // namespace

int RunEval(const std::vector<std::string>& args) {
  int exit_code = kExitOk;
  std::optional<ParsedArgs> parsed = ParseArgs(kEvalSpec, args, &exit_code);
  if (!parsed) return exit_code;
  const std::string& original_path = parsed->positional[0];
  const std::string& decoded_path = parsed->positional[1];
  const Status applies = CheckMapOptionsApplyTo(original_path, *parsed);
  if (!applies.ok()) return ReportError("eval", applies);
  // The layer limits apply to either map that is an .lmap file.
  const Status limits_apply = CheckLayerLimitsApplyTo({original_path, decoded_path}, *parsed);
  if (!limits_apply.ok()) return ReportError("eval", limits_apply);
  StatusOr<MapReadOptions> original_options = MapReadOptionsFrom(*parsed);
  if (!original_options.ok()) return ReportError("eval", original_options.status());
  StatusOr<Grid> original = LoadMapWithOptions(original_path, *original_options);
  if (!original.ok()) return ReportError("eval", original.status());
  MapReadOptions decoded_options;  // the file's own values; only the limits are shared
  decoded_options.image.max_cells = original_options->image.max_cells;
  decoded_options.lmap = original_options->lmap;
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
  // An ORIGINAL saved within a tolerance is not the map the robot made:
  // most likely the two files were given the other way round.
  if (IsLmapPath(original_path)) {
    StatusOr<std::optional<int>> t = LoadLmapToleranceCells(original_path, decoded_options.lmap);
    if (t.ok() && *t) {
      std::fprintf(stderr,
                   "linemap eval: warning: ORIGINAL '%s' was saved within a tolerance of %d "
                   "cell%s: it is not the original map (are the two files the other way "
                   "round?)\n",
                   original_path.c_str(), **t, **t == 1 ? "" : "s");
    }
  }
  std::optional<ToleranceReport> tol;
  bool tolerance_from_file = false;
  std::optional<int> named;  // the T the decoded .lmap file names
  if (IsLmapPath(decoded_path)) {
    StatusOr<std::optional<int>> t = LoadLmapToleranceCells(decoded_path, decoded_options.lmap);
    if (!t.ok()) return ReportError("eval", t.status());
    named = *t;
  }
  if (parsed->Get("--tolerance")) {
    StatusOr<int> t = parsed->GetInt("--tolerance", 0);
    if (!t.ok() || *t < 0 || *t > kMaxToleranceCells) {
      return ReportError(
          "eval", InvalidArgumentError("--tolerance must be a whole number of cells from 0 to " +
                                       std::to_string(kMaxToleranceCells) + ", not '" +
                                       *parsed->Get("--tolerance") + "'"));
    }
    tol = CheckTolerance(*original, *decoded, *t);
  } else if (named && *named <= kMaxToleranceCells &&
             original->size() <= EncodeOptions{}.max_tolerance_cells) {
    // A file saved within a tolerance promises its guarantees at the T it
    // names: check those, where the checks take that T and fit the default
    // memory bound of a save within a tolerance.
    tol = CheckTolerance(*original, *decoded, *named);
    tolerance_from_file = true;
  }
  const GridComparison m = CompareGrids(*original, *decoded);
  // The layers' fidelity when the second file is an .lmap.
  std::optional<LayerFidelity> fidelity;
  if (IsLmapPath(decoded_path)) {
    StatusOr<LmapVectors> vectors = LoadLmapVectors(decoded_path, decoded_options.lmap);
    if (!vectors.ok()) return ReportError("eval", vectors.status());
    StatusOr<LayerFidelity> measured = MeasureLayerFidelity(*original, *vectors);
    if (!measured.ok()) return ReportError("eval", measured.status());
    fidelity = *measured;
  }
  const bool check = parsed->Has("--check");
  const std::string frame_difference = FrameDifference(original->meta, decoded->meta);
  const CheckVerdict verdict = VerdictOf(m, frame_difference, tol);
  const double cm_per_cell = original->meta.resolution * 100;
  auto share = [](std::size_t n, std::size_t of) {
    return of > 0 ? static_cast<double>(n) / static_cast<double>(of) : 1.0;
  };
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
      json.Add("edge_cells", std::uint64_t{fidelity->edge_cells});
      if (fidelity->displ_ave_cells) {
        json.Add("displ_ave_cells", *fidelity->displ_ave_cells)
            .Add("displ_ave_cm", *fidelity->displ_ave_cells * cm_per_cell)
            .Add("displ_max_cells", *fidelity->displ_max_cells);
      } else {
        json.AddRaw("displ_ave_cells", "null")
            .AddRaw("displ_ave_cm", "null")
            .AddRaw("displ_max_cells", "null");
      }
      if (fidelity->displ_ave_cells) {
        json.Add("edge_share_within_1", share(fidelity->within_1_of_wall, fidelity->edge_cells));
      } else {
        json.AddRaw("edge_share_within_1", "null");  // no walls to be within 1 cell of
      }
      json.Add("edge_share_in_furniture", share(fidelity->in_furniture, fidelity->edge_cells))
          .Add("edge_share_within_1_or_furniture", share(fidelity->covered, fidelity->edge_cells));
    }
    if (tol) {
      VisitToleranceFigures(*tol, [&json](const char* key, auto value) { json.Add(key, value); });
      json.Add("tolerance_from_file", tolerance_from_file);
    }
    if (named) json.Add("tolerance_named_cells", *named);
    if (check) json.Add("check_passed", verdict.passed).Add("check", verdict.why);
    std::printf("%s\n", json.str().c_str());
    return check && !verdict.passed ? kExitFailure : kExitOk;
  }
  std::printf("same geometry:        %s\n",
              m.same_geometry ? "yes" : ("NO (" + frame_difference + ")").c_str());
  std::printf("cells equal:          %zu of %zu (%.4f)\n", m.cells_equal, m.cells,
              m.cells ? static_cast<double>(m.cells_equal) / m.cells : 1.0);
  std::printf("obstacle recall:      %.4f (within 1 cell)\n", m.obstacle_recall_1);
  std::printf("obstacle precision:   %.4f (within 1 cell)\n", m.obstacle_precision_1);
  std::printf("free IoU:             %.4f\n", m.free_iou);
  std::printf("leaks:                %zu\n", m.leaks);
  std::printf("unknown turned free:  %zu (%.4f of free)\n", m.unknown_turned_free,
              m.unknown_turned_free_share);
  if (fidelity) {
    std::printf("edge cells:           %zu (occupied, with a free 4-neighbour)\n",
                fidelity->edge_cells);
    if (fidelity->displ_ave_cells) {
      std::printf("DisPL_ave:            %.4f cells (%.2f cm), largest %.2f cells\n",
                  *fidelity->displ_ave_cells, *fidelity->displ_ave_cells * cm_per_cell,
                  *fidelity->displ_max_cells);
    } else {
      std::printf("DisPL_ave:            n/a (the file has no walls)\n");
    }
    if (fidelity->displ_ave_cells) {
      std::printf("within 1 of a wall:   %.4f\n",
                  share(fidelity->within_1_of_wall, fidelity->edge_cells));
    } else {
      std::printf("within 1 of a wall:   n/a (the file has no walls)\n");
    }
    std::printf("  or in furniture:    %.4f\n", share(fidelity->covered, fidelity->edge_cells));
  }
  if (tol) {
    if (tolerance_from_file) {
      std::printf("tolerance named by the file's metadata\n");
    } else if (named && *named != tol->tolerance_cells) {
      std::printf("tolerance:            the file names %s; checked at %s (--tolerance)\n",
                  CellsText(*named).c_str(), CellsText(tol->tolerance_cells).c_str());
    }
    PrintToleranceReport(*tol);
  } else if (named) {
    std::printf(
        "tolerance:            the file names %s; not checked (%s; --tolerance T "
        "checks T = 0..4 on any map)\n",
        CellsText(*named).c_str(),
        *named > kMaxToleranceCells ? "eval checks T = 0..4" : "a map over 2^26 cells");
  }
  if (check) {
    std::printf("check:                %s (%s)\n", verdict.passed ? "PASS" : "FAIL",
                verdict.why.c_str());
    return verdict.passed ? kExitOk : kExitFailure;
  }
  return kExitOk;
}

}  // namespace linemap::cli
