// bench_lines: RM-Line against linemap's extractor on every map of a folder
// (default ../shared/maps, read through its MANIFEST.tsv), one table row per
// map: lines, DisPL_ave (cm and cells), the largest distance and the time of
// both, whether linemap is Pareto-better (<= 0.7x the lines and a DisPL_ave no
// larger) and whether its epsilon bound holds on every non-furniture edge cell.
//
// Usage: bench_lines [MAPS_DIR] [--straight-walls] [--epsilon E] [--max-added-cost C] [--merge-gap
// G]
//                    [--split-epsilon S] [--free-cost C] [--target-distance T]
//                    [--growth G] [--prune-cost C]
//                    [--min-component N] [--speck-max-cells N] [--speck-gap G]
//                    [--speck-max-added C] [--noise-factor F]
//                    [--noise-window W] [--noise-min-mean M] [--noise-min-cells N]
//                    [--runs N] [--rm-cache FILE]
// --rm-cache FILE: RM-Line's lines, DisPL and ms per map are read from FILE
// when it exists (written by an earlier run otherwise), to tune linemap fast.
// Times are the fastest of N runs (default 3) of ExtractLines() alone, in
// process CPU milliseconds (the extraction is single-threaded; CPU time is
// steadier than wall time on a shared machine).
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "codec/lines/segment_index.h"
#include "linemap/lines.h"
#include "linemap/map_io.h"

namespace linemap {
namespace {

struct MapEntry {
  std::string name;   // relative image path
  std::string image;  // absolute
  std::string yaml;   // absolute or empty
};

std::vector<MapEntry> ReadManifest(const std::string& dir) {
  std::vector<MapEntry> maps;
  std::ifstream in(dir + "/MANIFEST.tsv");
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    std::vector<std::string> fields;
    std::stringstream ss(line);
    std::string field;
    while (std::getline(ss, field, '\t')) fields.push_back(field);
    if (fields.size() < 9) continue;
    maps.push_back(
        {fields[0], dir + "/" + fields[0], fields[8].empty() ? "" : dir + "/" + fields[8]});
  }
  return maps;
}

StatusOr<Grid> LoadEntry(const MapEntry& entry) {
  if (!entry.yaml.empty()) {
    StatusOr<Grid> grid = LoadRosMap(entry.yaml);
    if (grid.ok()) return grid;
  }
  return LoadMapImage(entry.image, MapMetadata{});  // no (usable) YAML: map_server defaults
}

double CpuMs() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return t.tv_sec * 1e3 + t.tv_nsec * 1e-6;
}

struct Run {
  std::size_t lines = 0;
  LineFidelity fidelity;
  double ms = 0;
  double bound_max = 0;  // linemap: largest distance over non-furniture edge cells
  std::size_t blob_cells = 0;
};

StatusOr<Run> Measure(const Grid& grid, const LineExtractionOptions& options, int runs) {
  Run run;
  run.ms = 1e300;
  StatusOr<LineExtraction> result = InternalError("not run");
  for (int i = 0; i < runs; ++i) {
    const double start = CpuMs();
    result = ExtractLines(grid, options);
    const double ms = CpuMs() - start;
    if (!result.ok()) return result.status();
    run.ms = std::min(run.ms, ms);
  }
  run.lines = result->segments.size();
  run.fidelity = MeasureLineFidelity(result->edges, result->segments);
  run.blob_cells = result->cells_left_to_blobs;
  lines_internal::SegmentIndex index(&result->segments, grid.width(), grid.height());
  for (std::size_t i = 0; i < result->edges.is_edge.size(); ++i) {
    if (!result->edges.is_edge[i]) continue;
    if (!result->left_to_blobs.empty() && result->left_to_blobs[i]) continue;
    const double d = index.NearestDistance(static_cast<double>(i % grid.width()),
                                           static_cast<double>(i / grid.width()));
    run.bound_max = std::max(run.bound_max, d);
  }
  return run;
}

// One line per map in the cache: name, lines, DisPL_ave (cells), max, ms.
StatusOr<Run> ReadCachedRun(const std::string& cache, const std::string& name) {
  std::ifstream in(cache);
  std::string key;
  Run run;
  while (in >> key >> run.lines >> run.fidelity.displ_ave_cells >> run.fidelity.displ_max_cells >>
         run.ms) {
    if (key == name) return run;
  }
  return NotFoundError("not cached");
}

void AppendCachedRun(const std::string& cache, const std::string& name, const Run& run) {
  if (cache.empty()) return;
  std::ofstream out(cache, std::ios::app);
  out << name << ' ' << run.lines << ' ' << run.fidelity.displ_ave_cells << ' '
      << run.fidelity.displ_max_cells << ' ' << run.ms << '\n';
}

int Main(int argc, char** argv) {
  std::string dir = "../shared/maps";
  LineExtractionOptions lm;
  lm.method = LineMethod::kLinemap;
  int runs = 3;
  std::string rm_cache;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--straight-walls") {
      lm = StraightWalls(lm);
    } else if (arg == "--epsilon" && i + 1 < argc) {
      lm.epsilon_cells = std::atof(argv[++i]);
    } else if (arg == "--max-added-cost" && i + 1 < argc) {
      lm.max_added_cost_cells = std::atof(argv[++i]);
    } else if (arg == "--free-cost" && i + 1 < argc) {
      lm.free_merge_cost_cells = std::atof(argv[++i]);
    } else if (arg == "--target-distance" && i + 1 < argc) {
      lm.target_mean_distance_cells = std::atof(argv[++i]);
    } else if (arg == "--growth" && i + 1 < argc) {
      lm.distance_growth_factor = std::atof(argv[++i]);
    } else if (arg == "--prune-cost" && i + 1 < argc) {
      lm.prune_added_cost_cells = std::atof(argv[++i]);
    } else if (arg == "--split-epsilon" && i + 1 < argc) {
      lm.split_epsilon_cells = std::atof(argv[++i]);
    } else if (arg == "--merge-gap" && i + 1 < argc) {
      lm.merge_gap_cells = std::atof(argv[++i]);
    } else if (arg == "--min-component" && i + 1 < argc) {
      lm.min_component_cells = std::atoi(argv[++i]);
    } else if (arg == "--speck-max-cells" && i + 1 < argc) {
      lm.speck_max_cells = std::atoi(argv[++i]);
    } else if (arg == "--speck-gap" && i + 1 < argc) {
      lm.speck_min_gap_cells = std::atof(argv[++i]);
    } else if (arg == "--speck-max-added" && i + 1 < argc) {
      lm.speck_max_added_cells = std::atof(argv[++i]);
    } else if (arg == "--noise-factor" && i + 1 < argc) {
      lm.noise_merge_factor = std::atof(argv[++i]);
    } else if (arg == "--noise-window" && i + 1 < argc) {
      lm.noise_window_cells = std::atoi(argv[++i]);
    } else if (arg == "--noise-min-mean" && i + 1 < argc) {
      lm.noise_min_mean_cells = std::atof(argv[++i]);
    } else if (arg == "--noise-min-cells" && i + 1 < argc) {
      lm.noise_min_cells = std::atoi(argv[++i]);
    } else if (arg == "--rm-cache" && i + 1 < argc) {
      rm_cache = argv[++i];
    } else if (arg == "--runs" && i + 1 < argc) {
      runs = std::max(1, std::atoi(argv[++i]));
    } else {
      dir = arg;
    }
  }
  const std::vector<MapEntry> maps = ReadManifest(dir);
  if (maps.empty()) {
    std::fprintf(stderr, "bench_lines: no maps in %s/MANIFEST.tsv\n", dir.c_str());
    return 2;
  }
  std::printf(
      "| map | cells | RM lines | RM DisPL cm (cells) | RM max | RM ms | LM lines | ratio "
      "| LM DisPL cm (cells) | LM max | LM ms | blob cells | bound max | Pareto |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  int pareto = 0, counted = 0;
  for (const MapEntry& entry : maps) {
    StatusOr<Grid> grid = LoadEntry(entry);
    if (!grid.ok()) {
      std::printf("| %s | load failed: %s |\n", entry.name.c_str(),
                  grid.status().message().c_str());
      continue;
    }
    LineExtractionOptions rm;
    rm.method = LineMethod::kRmLine;
    StatusOr<Run> a = ReadCachedRun(rm_cache, entry.name);
    if (!a.ok()) {
      a = Measure(*grid, rm, runs);
      if (a.ok()) AppendCachedRun(rm_cache, entry.name, *a);
    }
    StatusOr<Run> b = Measure(*grid, lm, runs);
    if (!a.ok() || !b.ok()) {
      std::printf("| %s | extraction failed |\n", entry.name.c_str());
      continue;
    }
    const double cm = grid->meta.resolution * 100;
    const double ratio = a->lines ? static_cast<double>(b->lines) / a->lines : 0;
    const bool better = ratio <= 0.7 && b->fidelity.displ_ave_cells <= a->fidelity.displ_ave_cells;
    ++counted;
    pareto += better ? 1 : 0;
    std::printf(
        "| %s | %dx%d | %zu | %.2f (%.3f) | %.1f | %.1f | %zu | %.2f | %.2f (%.3f) | %.1f "
        "| %.1f | %zu | %.3f | %s |\n",
        entry.name.c_str(), grid->width(), grid->height(), a->lines,
        a->fidelity.displ_ave_cells * cm, a->fidelity.displ_ave_cells, a->fidelity.displ_max_cells,
        a->ms, b->lines, ratio, b->fidelity.displ_ave_cells * cm, b->fidelity.displ_ave_cells,
        b->fidelity.displ_max_cells, b->ms, b->blob_cells, b->bound_max, better ? "yes" : "no");
    std::fflush(stdout);
  }
  std::printf(
      "\nPareto-better (<= 0.7x lines and DisPL_ave <= RM-Line's) on %d of %d maps; "
      "epsilon %.2f cells, split epsilon %.2f, merge gap %.1f, max added cost %.1f, free cost "
      "%.2f, target distance %.3f, growth %.2f, prune cost %.2f, min component %d, noise factor "
      "%.2f, noise window %d, noise min mean %.2f, noise min cells %d, speck max cells %d, speck "
      "gap %.1f, speck max added %.0f\n",
      pareto, counted, lm.epsilon_cells, lm.split_epsilon_cells, lm.merge_gap_cells,
      lm.max_added_cost_cells, lm.free_merge_cost_cells, lm.target_mean_distance_cells,
      lm.distance_growth_factor, lm.prune_added_cost_cells, lm.min_component_cells,
      lm.noise_merge_factor, lm.noise_window_cells, lm.noise_min_mean_cells, lm.noise_min_cells,
      lm.speck_max_cells, lm.speck_min_gap_cells, lm.speck_max_added_cells);
  return 0;
}

}  // namespace
}  // namespace linemap

int main(int argc, char** argv) { return linemap::Main(argc, argv); }
