// linemap bench [CORPUS_DIR ...]: size, fidelity and speed of linemap beside
// PNG, zstd, xz, JBIG1, WebP, JPEG XL and RM-Line on every map of a corpus.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iterator>
#include <map>
#include <set>

#include "format/file_io.h"
#include "linemap/map_io.h"
#include "tools/bench/anchors.h"
#include "tools/bench/corpus.h"
#include "tools/bench/goals.h"
#include "tools/bench/machine.h"
#include "tools/bench/progress.h"
#include "tools/bench/report.h"
#include "tools/bench/runner.h"
#include "tools/bench/svg.h"
#include "tools/linemap/commands.h"

namespace linemap::cli {

const CommandSpec kBenchSpec = {
    "bench",
    "[CORPUS_DIR ...] [--md OUT.md] [--csv OUT.csv] [--svg-dir DIR]",
    "benchmark size, fidelity and speed against PNG and other codecs",
    "A corpus is a folder searched recursively for map YAMLs and for PGM/PNG images\n"
    "that no YAML names (those get 0.05 m/cell). Default: the bundled maps\n"
    "(tests/data/maps), plus $LINEMAP_SHARED_MAPS or ../shared/maps when present.\n"
    "Maps whose cells and metadata equal an earlier map's are measured once.\n"
    "Prints per-map tables, the medians by method and a scaling table; a progress\n"
    "bar is drawn on stderr when it is a terminal. JBIG1 needs `pbmtojbg`\n"
    "(jbigkit-bin), WebP `cwebp` and `dwebp` (webp), JPEG XL `cjxl` and `djxl`\n"
    "(libjxl-tools) in PATH; they are run as subprocesses, never linked, and a\n"
    "missing one is named in the notes and its column left out. The anchors table\n"
    "checks the default .lmap 2.0 file (exact, walls + rooms + furniture) against\n"
    "each of them and PNG-9, zstd -19, xz -9e on maps of >= 100,000 cells. The\n"
    "goals tables end the output: each default file decoded and compared cell for\n"
    "cell, size and layer cost at the median, how well the walls and furniture\n"
    "hold the map's edge cells (and DisPL_ave against RM-Line's), and encode and\n"
    "decode CPU time against libpng (the two timed in turn, run for run), each\n"
    "with PASS / FAIL.",
    {
        {"--md", "OUT.md", "also write the tables as Markdown (the name ends in .md)"},
        {"--csv", "OUT.csv", "also write every figure of every map as CSV (the name ends in .csv)"},
        {"--svg-dir", "DIR",
         "write per-map overlay SVGs (the 2.0 file's walls, rooms, furniture) and summary.svg"},
        {"--repeats", "N", "timed runs per map up to 1 Mcell (default 5; 3 to 4 Mcells, 1 above)"},
        {"--scaling-max", "MCELLS",
         "largest map of the scaling table: 0 (skip), 1, 4, 16, 64 or 282 (20,768 x 13,612; "
         "the default: about 2.5 min and 3 GB more than 64)"},
        {"--no-memory", "", "skip the peak-memory measurements (they fork per operation)"},
        {"--no-jbig", "", "skip the JBIG1 comparator"},
        {"--no-webp", "", "skip the WebP lossless comparator"},
        {"--no-jxl", "", "skip the JPEG XL comparator (cjxl -e 9: about 1.3 s CPU per Mcell)"},
    },
    0,
    1000,
};

namespace {

struct BenchArgs {
  std::vector<std::string> dirs;
  std::optional<std::string> md, csv, svg_dir;
  int scaling_max = 282;
  bench::BenchOptions options;
};

StatusOr<BenchArgs> BenchArgsFrom(const ParsedArgs& parsed) {
  BenchArgs args;
  // A misnamed output, or one that cannot be written, is refused before the
  // corpus is read, not after the run (minutes).
  args.md = parsed.Get("--md");
  if (args.md) {
    LINEMAP_RETURN_IF_ERROR(CheckOutputExtension(*args.md, {".md"}, "Markdown"));
    LINEMAP_RETURN_IF_ERROR(CheckOutputWritable(*args.md));
  }
  args.csv = parsed.Get("--csv");
  if (args.csv) {
    LINEMAP_RETURN_IF_ERROR(CheckOutputExtension(*args.csv, {".csv"}, "CSV"));
    LINEMAP_RETURN_IF_ERROR(CheckOutputWritable(*args.csv));
  }
  args.svg_dir = parsed.Get("--svg-dir");
  if (args.svg_dir) {
    LINEMAP_RETURN_IF_ERROR(CheckOutputFolderWritable(*args.svg_dir, /*make_parents=*/true));
  }
  args.dirs = parsed.positional.empty() ? bench::DefaultCorpusDirs() : parsed.positional;
  if (args.dirs.empty()) return NotFoundError("no corpus: give a folder of maps");
  LINEMAP_ASSIGN_OR_RETURN(args.options.repeats, parsed.GetInt("--repeats", 5));
  if (args.options.repeats < 1 || args.options.repeats > 100) {
    return InvalidArgumentError("--repeats must be in 1..100");
  }
  // The scaling table has rows of 1, 4, 16, 64 and 282 Mcells; another
  // value would silently stop at the row below it.
  const StatusOr<int> scaling_max = parsed.GetInt("--scaling-max", 282);
  constexpr int kRows[] = {0, 1, 4, 16, 64, 282};
  if (!scaling_max.ok() ||
      std::find(std::begin(kRows), std::end(kRows), *scaling_max) == std::end(kRows)) {
    return InvalidArgumentError("--scaling-max must be 0 (skip), 1, 4, 16, 64 or 282, not '" +
                                parsed.Get("--scaling-max").value_or("") + "'");
  }
  args.scaling_max = *scaling_max;
  args.options.measure_memory = !parsed.Has("--no-memory");
  args.options.jbig = !parsed.Has("--no-jbig");
  args.options.webp = !parsed.Has("--no-webp");
  args.options.jxl = !parsed.Has("--no-jxl");
  return args;
}

// A fingerprint of cells and metadata, to measure duplicated maps once.
std::uint64_t GridFingerprint(const Grid& grid) {
  std::uint64_t h = 1469598103934665603ull;  // FNV-1a
  auto mix = [&h](std::uint64_t v) {
    for (int i = 0; i < 8; ++i) {
      h ^= (v >> (8 * i)) & 0xff;
      h *= 1099511628211ull;
    }
  };
  mix(static_cast<std::uint64_t>(grid.width()));
  mix(static_cast<std::uint64_t>(grid.height()));
  for (Cell c : grid.cells()) {
    h ^= static_cast<std::uint8_t>(c);
    h *= 1099511628211ull;
  }
  mix(static_cast<std::uint64_t>(grid.meta.resolution * 1e9));
  mix(static_cast<std::uint64_t>(grid.meta.origin.x * 1e6));
  mix(static_cast<std::uint64_t>(grid.meta.origin.y * 1e6));
  return h;
}

// Notes that hold for every map are printed once.
std::string NotesText(const std::vector<bench::MapResult>& results,
                      const std::vector<std::string>& skipped) {
  std::map<std::string, std::size_t> counts;
  for (const bench::MapResult& r : results) {
    for (const std::string& note : r.notes) ++counts[note];
  }
  std::string out;
  for (const auto& [note, count] : counts) {
    if (count == results.size()) out += "  (all maps) " + note + "\n";
  }
  for (const bench::MapResult& r : results) {
    for (const std::string& note : r.notes) {
      if (counts[note] != results.size()) out += "  " + r.name + ": " + note + "\n";
    }
  }
  for (const std::string& s : skipped) out += "  " + s + "\n";
  return out.empty() ? "" : "\nNotes:\n" + out;
}

Status WriteOutputs(const BenchArgs& args, const std::string& header,
                    const std::vector<bench::NamedTable>& tables, const std::string& notes,
                    const std::vector<bench::MapResult>& results) {
  if (args.md) {
    // Markdown joins single lines; a trailing double space keeps them apart.
    std::string md_header;
    for (char c : header) md_header += c == '\n' ? std::string("  \n") : std::string(1, c);
    std::string md =
        "## linemap bench results\n\n" + md_header + "\n" + bench::TablesMarkdown(tables);
    if (!notes.empty()) md += "\n```\n" + notes.substr(1) + "```\n";
    LINEMAP_RETURN_IF_ERROR(WriteFileAtomic(*args.md, md));
  }
  if (args.csv) LINEMAP_RETURN_IF_ERROR(WriteFileAtomic(*args.csv, bench::ResultsCsv(results)));
  if (args.svg_dir) {
    LINEMAP_RETURN_IF_ERROR(
        WriteFileAtomic(*args.svg_dir + "/summary.svg", bench::SummaryPlotSvg(results)));
  }
  return Status::Ok();
}

}  // namespace

int RunBench(const std::vector<std::string>& argv) {
  int exit_code = kExitOk;
  std::optional<ParsedArgs> parsed = ParseArgs(kBenchSpec, argv, &exit_code);
  if (!parsed) return exit_code;
  StatusOr<BenchArgs> args = BenchArgsFrom(*parsed);
  if (!args.ok()) return ReportError("bench", args.status());
  StatusOr<std::vector<bench::CorpusMap>> corpus = bench::DiscoverCorpus(args->dirs);
  if (!corpus.ok()) return ReportError("bench", corpus.status());
  if (corpus->empty()) return ReportError("bench", NotFoundError("no maps in the corpus"));
  if (args->svg_dir) {
    std::error_code ec;
    std::filesystem::create_directories(*args->svg_dir, ec);
    if (ec) return ReportError("bench", IoError(*args->svg_dir + ": " + ec.message()));
  }

  std::string header = "command: linemap bench";
  for (const std::string& arg : argv) header += " " + arg;
  header += "\nmachine: " + bench::MachineDescription() + "\ncorpus:";
  for (const std::string& dir : args->dirs) header += " " + dir;
  header += " (" + std::to_string(corpus->size()) + " maps found)\n";
  std::printf("linemap bench\n%s", header.c_str());
  std::fflush(stdout);

  std::vector<bench::MapResult> results;
  std::vector<std::string> skipped;
  std::set<std::uint64_t> seen;
  const int scaling_steps = bench::ScalingProgressSteps(args->scaling_max, args->options.repeats);
  bench::ProgressBar progress(corpus->size() + static_cast<std::size_t>(scaling_steps));
  std::size_t step = 0;
  for (const bench::CorpusMap& map : *corpus) {
    progress.Update(step++, map.name);
    StatusOr<Grid> grid = LoadRosMap(map.path);
    if (!grid.ok()) {
      skipped.push_back(map.name + ": skipped, " + grid.status().message());
      continue;
    }
    if (!seen.insert(GridFingerprint(*grid)).second) {
      skipped.push_back(map.name + ": skipped, same cells as a map measured before");
      continue;
    }
    results.push_back(bench::MeasureMap(map.name, map.path, *grid, args->options));
    if (args->svg_dir) {
      Status svg = bench::WriteMapOverlaySvg(*args->svg_dir, *grid, results.back());
      if (!svg.ok()) results.back().notes.push_back("SVG: " + svg.message());
    }
  }
  std::vector<bench::ScalingRow> scaling;
  if (scaling_steps > 0) {
    scaling = bench::RunScaling(
        args->scaling_max, args->options.repeats,
        [&](const std::string& label) { progress.Update(step++, "scaling " + label); });
  }
  progress.Finish();

  std::vector<bench::NamedTable> tables = bench::PerMapTables(results);
  tables.push_back(bench::MediansTable(results));
  for (bench::NamedTable& table : bench::AnchorTables(results)) tables.push_back(std::move(table));
  for (const bench::Anchor& subject : bench::ComparedSubjects()) {
    for (bench::NamedTable& table : bench::AnchorTables(results, subject, /*goal=*/false)) {
      tables.push_back(std::move(table));
    }
  }
  tables.push_back(bench::LineMediansTable(results));
  if (!scaling.empty()) {
    tables.push_back(bench::ScalingTable(scaling));
    tables.push_back(bench::ScalingGoalsTable(scaling));
  }
  for (bench::NamedTable& table : bench::GoalTables(results)) tables.push_back(std::move(table));
  const std::string notes = NotesText(results, skipped);
  std::printf("%s%s", bench::TablesText(tables).c_str(), notes.c_str());
  Status written = WriteOutputs(*args, header, tables, notes, results);
  if (!written.ok()) return ReportError("bench", written);
  return kExitOk;
}

}  // namespace linemap::cli
