// bench_tolerance: bytes of the tolerance mode's files against the exact
// file and the PNG-9 of coarser maps, on ../shared/maps.
//
//   bench_tolerance [--maps DIR] [--only SUBSTR] [--cells-only] [--dump DIR] [--coarse-lmap]
//                   [--free-space] [--svg OUT.svg]
//
// For T = 0..4 each map is saved as `linemap encode --tolerance T` saves it
// (EncodeLmap with tolerance_cells = T, with and without the vector layers),
// decoded, and every guarantee checked on the decode by CheckTolerance
// ('!' after a size: one fails). Anchors: the exact file (T = 0) and the
// smallest trinary PNG (zlib 9) of the map made 2x and 4x coarser (a block
// is occupied if any cell is, else unknown if any is, else free). Medians
// are printed for the tuning maps and for the others separately.
// Plans from starts the checks never sample are counted too (cells-only
// files). --cells-only skips the files with vector layers (much faster).
// --coarse-lmap also prints the exact file of the coarser maps and of them
// drawn back at full size. --free-space prints what the free space alone
// costs, exact (FreeSpaceBytes), beside the anchors. --dump writes PNGs of
// the decodes. --svg draws the curve of bytes against T beside the anchors.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "codec/tolerance/simplify.h"
#include "linemap/codec.h"
#include "linemap/map_io.h"
#include "linemap/tolerance.h"
#include "tools/bench/netpbm.h"
#include "tools/bench/png_codec.h"
#include "tools/bench/tuning_split.h"

namespace linemap {
namespace {

constexpr int kMaxT = 4;

Grid Coarser(const Grid& g, int factor) {
  Grid out((g.width() + factor - 1) / factor, (g.height() + factor - 1) / factor, Cell::kFree);
  for (int r = 0; r < g.height(); ++r) {
    for (int c = 0; c < g.width(); ++c) {
      const Cell v = g.at(c, r);
      const Cell cur = out.at(c / factor, r / factor);
      if (v == Cell::kOccupied || (v == Cell::kUnknown && cur == Cell::kFree)) {
        out.set(c / factor, r / factor, v);
      }
    }
  }
  return out;
}

// `coarse` drawn back at the size of `like`, each cell its block's value.
Grid Upsampled(const Grid& coarse, int factor, const Grid& like) {
  Grid out(like.width(), like.height());
  for (int r = 0; r < like.height(); ++r) {
    for (int c = 0; c < like.width(); ++c) out.set(c, r, coarse.at(c / factor, r / factor));
  }
  return out;
}

long SmallestPngBytes(const Grid& g) {
  long best = -1;
  for (bench::PngLayout layout :
       {bench::PngLayout::kGrey8, bench::PngLayout::kPalette8, bench::PngLayout::kPalette2}) {
    StatusOr<std::string> png = bench::EncodeTrinaryPng(g, layout, 9);
    if (png.ok() && (best < 0 || static_cast<long>(png->size()) < best)) best = png->size();
  }
  return best;
}

// The PNG-9 anchor of a coarser map, as the main bench takes PNG-9: the
// smallest of libpng's layouts and `pnmtopng -compression 9` (left out, with
// a note on stderr, when netpbm is missing).
long CoarserPngBytes(const Grid& coarse) {
  long best = SmallestPngBytes(coarse);
  const StatusOr<std::uint64_t> netpbm = bench::PnmtopngBytes(coarse);
  if (!netpbm.ok()) {
    std::fprintf(stderr, "bench_tolerance: %s\n", netpbm.status().message().c_str());
  } else if (best < 0 || static_cast<long>(*netpbm) < best) {
    best = static_cast<long>(*netpbm);
  }
  return best;
}

std::string FlatName(std::string path) {
  std::replace(path.begin(), path.end(), '/', '_');
  return path;
}

void DumpPng(const Grid& g, const std::string& path) {
  StatusOr<std::string> png = bench::EncodeTrinaryPng(g, bench::PngLayout::kPalette8, 9);
  if (!png.ok()) return;
  if (FILE* f = std::fopen(path.c_str(), "wb")) {
    std::fwrite(png->data(), 1, png->size(), f);
    std::fclose(f);
  }
}

long LmapBytes(const Grid& g, bool layers) {
  EncodeOptions options;
  options.vector_layers = layers;
  StatusOr<std::vector<std::uint8_t>> bytes = EncodeLmap(g, options);
  return bytes.ok() ? static_cast<long>(bytes->size()) : -1;
}

// The map as free or not free, exact, coded as small as the codec codes
// a map (--compact --raster-only): what the edge of the free space costs
// when none of it moves. The plan guarantee holds every plan of up to 16
// steps beside a change to its length, which lets little of that edge move
// (a bump taken off a wall shortens the plans along it by 2 steps), so this
// is the scale of what a file within a tolerance must spend on it.
long FreeSpaceBytes(const Grid& g) {
  Grid mask = g;
  for (Cell& c : mask.mutable_cells()) {
    if (c != Cell::kFree) c = Cell::kOccupied;
  }
  EncodeOptions options;
  options.vector_layers = false;
  options.compact = true;
  StatusOr<std::vector<std::uint8_t>> bytes = EncodeLmap(mask, options);
  return bytes.ok() ? static_cast<long>(bytes->size()) : -1;
}

// The file saved within `t` cells and what it decodes to.
struct Saved {
  long bytes = -1;
  Grid decoded;
};

Saved SaveWithin(const Grid& g, int t, bool layers) {
  EncodeOptions options;
  options.vector_layers = layers;
  options.tolerance_cells = t;
  Saved out;
  StatusOr<std::vector<std::uint8_t>> bytes = EncodeLmap(g, options);
  if (!bytes.ok()) return out;
  StatusOr<Grid> decoded = DecodeLmap(*bytes);
  if (!decoded.ok()) return out;
  out.bytes = static_cast<long>(bytes->size());
  out.decoded = std::move(*decoded);
  return out;
}

// Plans between cells the encoder's checks never sampled: starts strided
// over the cells free in both maps (CheckTolerance draws its own by a fixed
// random sequence), every ~1000th such cell a goal. The guarantee is
// checked on the encoder's starts; these say how far it carries to others.
struct OtherPlans {
  long pairs = 0;
  long gone_or_new = 0;     // a plan on one map and none on the other
  long beyond_percent = 0;  // lengths more than 3 % apart (the guarantee)
  int worst_steps = 0;      // the largest length difference among those
};

std::vector<int> PlanSteps(const Grid& g, std::size_t from) {
  std::vector<int> steps(g.size(), -1);
  std::vector<std::size_t> queue{from};
  steps[from] = 0;
  const std::size_t w = static_cast<std::size_t>(g.width());
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const std::size_t i = queue[head];
    const int c = static_cast<int>(i % w), r = static_cast<int>(i / w);
    const int dc[4] = {1, -1, 0, 0}, dr[4] = {0, 0, 1, -1};
    for (int k = 0; k < 4; ++k) {
      if (!g.Contains(c + dc[k], r + dr[k])) continue;
      const std::size_t n = g.Index(c + dc[k], r + dr[k]);
      if (steps[n] >= 0 || g.cells()[n] != Cell::kFree) continue;
      steps[n] = steps[i] + 1;
      queue.push_back(n);
    }
  }
  return steps;
}

void AddOtherPlans(const Grid& original, const Grid& decoded, OtherPlans* out) {
  constexpr std::size_t kStarts = 24, kGoals = 1000;
  std::vector<std::size_t> both;
  for (std::size_t i = 0; i < original.size(); ++i) {
    if (original.cells()[i] == Cell::kFree && decoded.cells()[i] == Cell::kFree) both.push_back(i);
  }
  if (both.empty()) return;
  const std::size_t start_stride = std::max<std::size_t>(1, both.size() / kStarts);
  const std::size_t goal_stride = std::max<std::size_t>(1, both.size() / kGoals);
  for (std::size_t a = start_stride / 3; a < both.size(); a += start_stride) {
    const std::vector<int> lo = PlanSteps(original, both[a]);
    const std::vector<int> ls = PlanSteps(decoded, both[a]);
    for (std::size_t b = 0; b < both.size(); b += goal_stride) {
      const int x = lo[both[b]], y = ls[both[b]];
      ++out->pairs;
      if ((x < 0) != (y < 0)) {
        ++out->gone_or_new;
      } else if (x >= 0 && std::abs(x - y) > kPlanLengthTolerance * x) {
        ++out->beyond_percent;
        out->worst_steps = std::max(out->worst_steps, std::abs(x - y));
      }
    }
  }
}

struct Row {
  std::string name;
  bool tuning = false;
  long png2 = 0, png4 = 0;
  long free_space = -1;         // FreeSpaceBytes, with --free-space
  long cells[kMaxT + 1] = {};   // vector_layers = false
  long layers[kMaxT + 1] = {};  // default options
  bool holds[kMaxT + 1] = {};
  OtherPlans other[kMaxT + 1];  // of the cells-only files
};

double Median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// Which maps a summary covers.
enum class Group { kTuning, kHeldOut, kAll };

bool InGroup(const Row& row, Group group) {
  return group == Group::kAll || row.tuning == (group == Group::kTuning);
}

void PrintSummary(const std::vector<Row>& rows, Group group, bool with_layers) {
  std::printf("\n%s maps:\n", group == Group::kTuning    ? "tuning"
                              : group == Group::kHeldOut ? "held-out"
                                                         : "all");
  std::printf(
      "  T  kind     med/exact  max/exact  med/png2x  max/png2x  med/png4x  max/png4x  held\n");
  for (int t = 1; t <= kMaxT; ++t) {
    for (int kind = 0; kind < (with_layers ? 2 : 1); ++kind) {
      std::vector<double> e, p2, p4;
      int held = 0, n = 0;
      for (const Row& r : rows) {
        if (!InGroup(r, group)) continue;
        const long* b = kind ? r.layers : r.cells;
        e.push_back(static_cast<double>(b[t]) / b[0]);
        p2.push_back(static_cast<double>(b[t]) / r.png2);
        p4.push_back(static_cast<double>(b[t]) / r.png4);
        held += r.holds[t];
        ++n;
      }
      auto mx = [](const std::vector<double>& v) { return *std::max_element(v.begin(), v.end()); };
      if (n == 0) continue;
      std::printf("  %d  %-7s  %9.3f  %9.3f  %9.3f  %9.3f  %9.3f  %9.3f  %d/%d\n", t,
                  kind ? "layers" : "cells", Median(e), mx(e), Median(p2), mx(p2), Median(p4),
                  mx(p4), held, n);
    }
  }
}

// The tolerance goals over every map, with PASS / FAIL, for the files a
// save within T writes (the vector layers stay in the file) and, for
// comparison, the cells-only files: at T = 1 every file under the PNG-9 of
// the 2x coarser map and the median at most 0.5x of it, the median at most
// 0.6x of the exact file and none larger than it; at T = 3 every file under
// the PNG-9 of the 4x coarser map and the median at most 0.5x of it; every
// guarantee on every map at every T.
void PrintGoals(const std::vector<Row>& rows, bool with_layers) {
  std::printf("\ngoals (all %zu maps; verdicts on the %s files):\n", rows.size(),
              with_layers ? "default (with layers)" : "cells-only");
  const auto verdict = [](bool pass) { return pass ? "  PASS" : "  FAIL"; };
  for (int kind = with_layers ? 1 : 0; kind >= 0; --kind) {
    const char* what = kind ? "with layers" : "cells only";
    std::vector<double> t1_png2, t1_exact, t3_png4;
    int under_png2 = 0, under_png4 = 0, not_over_exact = 0;
    for (const Row& r : rows) {
      const long* b = kind ? r.layers : r.cells;
      t1_png2.push_back(static_cast<double>(b[1]) / r.png2);
      t1_exact.push_back(static_cast<double>(b[1]) / b[0]);
      t3_png4.push_back(static_cast<double>(b[3]) / r.png4);
      under_png2 += b[1] < r.png2;
      under_png4 += b[3] < r.png4;
      not_over_exact += b[1] <= b[0];
    }
    const int n = static_cast<int>(rows.size());
    // The files a save within T writes are judged; the others are shown.
    const bool judged = kind == (with_layers ? 1 : 0);
    const auto mark = [&](bool pass) { return judged ? verdict(pass) : ""; };
    const double m1 = Median(t1_png2), e1 = Median(t1_exact), m3 = Median(t3_png4);
    std::printf("  %-11s T = 1: under png2x on %d/%d maps%s\n", what, under_png2, n,
                mark(under_png2 == n));
    std::printf("  %-11s T = 1: median %.3f of png2x (goal 0.5)%s\n", what, m1, mark(m1 <= 0.5));
    std::printf("  %-11s T = 1: median %.3f of the exact file (goal 0.6), not larger on %d/%d%s\n",
                what, e1, not_over_exact, n, mark(e1 <= 0.6 && not_over_exact == n));
    std::printf("  %-11s T = 3: under png4x on %d/%d maps%s\n", what, under_png4, n,
                mark(under_png4 == n));
    std::printf("  %-11s T = 3: median %.3f of png4x (goal 0.5)%s\n", what, m3, mark(m3 <= 0.5));
  }
  int held = 0;
  for (const Row& r : rows) {
    bool all = true;
    for (int t = 1; t <= kMaxT; ++t) all = all && r.holds[t];
    held += all;
  }
  std::printf("  every guarantee at T = 1..%d on %d/%zu maps%s\n", kMaxT, held, rows.size(),
              verdict(held == static_cast<int>(rows.size())));
}

// FreeSpaceBytes against the anchors and the files at T = 1 and 3 (cells
// only), medians of the tuning and of the held-out maps.
void PrintFreeSpace(const std::vector<Row>& rows) {
  std::printf(
      "\nthe free space alone, exact (free / not free, --compact --raster-only):\n"
      "  maps      med/png2x  max/png2x  med/png4x  max/png4x  T=1 file/it  T=3 file/it\n");
  for (const bool tuning : {true, false}) {
    std::vector<double> p2, p4, t1, t3;
    for (const Row& r : rows) {
      if (r.tuning != tuning || r.free_space <= 0 || r.cells[1] < 0 || r.cells[3] < 0) continue;
      const double f = static_cast<double>(r.free_space);
      p2.push_back(f / r.png2);
      p4.push_back(f / r.png4);
      t1.push_back(r.cells[1] / f);
      t3.push_back(r.cells[3] / f);
    }
    if (p2.empty()) continue;
    auto mx = [](const std::vector<double>& v) { return *std::max_element(v.begin(), v.end()); };
    std::printf("  %-8s  %9.3f  %9.3f  %9.3f  %9.3f  %11.3f  %11.3f\n",
                tuning ? "tuning" : "held-out", Median(p2), mx(p2), Median(p4), mx(p4), Median(t1),
                Median(t3));
  }
}

// The plans of OtherPlans over all maps, by T.
void PrintOtherPlans(const std::vector<Row>& rows) {
  std::printf(
      "\nplans from starts the encoder did not sample (24 strided starts x ~1000 goals per "
      "map, cells-only files):\n"
      "  T     pairs  gone/new         beyond 3 %%  maps with any  largest difference\n");
  for (int t = 1; t <= kMaxT; ++t) {
    OtherPlans all;
    int maps = 0;
    for (const Row& r : rows) {
      const OtherPlans& o = r.other[t];
      all.pairs += o.pairs;
      all.gone_or_new += o.gone_or_new;
      all.beyond_percent += o.beyond_percent;
      all.worst_steps = std::max(all.worst_steps, o.worst_steps);
      maps += o.gone_or_new + o.beyond_percent > 0;
    }
    const auto share = [&all](long n) { return all.pairs ? 100.0 * n / all.pairs : 0.0; };
    std::printf("  %d  %8ld  %8ld  %7ld (%.3f %%)  %13d  %12d steps\n", t, all.pairs,
                all.gone_or_new, all.beyond_percent, share(all.beyond_percent), maps,
                all.worst_steps);
  }
}

// The curve a user chooses from: bytes against T, as a share of the PNG-9
// of the 2x coarser map (log scale), one faint line per map (cells only),
// the medians of the cells-only and the default files bold, the anchors
// (PNG-9 of the 2x and 4x coarser maps) as horizontal lines and the
// issue's goals (0.5x of them at T = 1 and 3) as crosses.
std::string CurveSvg(const std::vector<Row>& rows) {
  const double w = 640, h = 420, left = 70, right = 170, top = 30, bottom = 50;
  const double lo = std::log(0.2), hi = std::log(4.0);
  auto x = [&](int t) { return left + (w - left - right) * t / kMaxT; };
  auto y = [&](double ratio) {
    const double v = std::clamp(std::log(ratio), lo, hi);
    return top + (h - top - bottom) * (hi - v) / (hi - lo);
  };
  std::string svg;
  auto add = [&](const char* fmt, auto... args) {
    char buf[512];
    std::snprintf(buf, sizeof buf, fmt, args...);
    svg += buf;
  };
  add("<svg xmlns='http://www.w3.org/2000/svg' width='%.0f' height='%.0f' "
      "font-family='sans-serif' font-size='12'>\n<rect width='100%%' height='100%%' "
      "fill='white'/>\n",
      w, h);
  add("<text x='%.0f' y='18' font-size='14'>Bytes against tolerance T (share of the PNG-9 of the "
      "2x coarser map)</text>\n",
      left);
  for (const double r : {0.25, 0.5, 1.0, 2.0, 4.0}) {
    add("<line x1='%.1f' x2='%.1f' y1='%.1f' y2='%.1f' stroke='#ddd'/><text x='%.1f' y='%.1f' "
        "text-anchor='end'>%.2f</text>\n",
        left, w - right, y(r), y(r), left - 6, y(r) + 4, r);
  }
  for (int t = 0; t <= kMaxT; ++t) {
    add("<text x='%.1f' y='%.1f' text-anchor='middle'>T = %d</text>\n", x(t), h - bottom + 20, t);
  }
  auto polyline = [&](const std::vector<double>& v, const char* style) {
    svg += "<polyline fill='none' " + std::string(style) + " points='";
    for (int t = 0; t <= kMaxT; ++t) add("%.1f,%.1f ", x(t), y(v[t]));
    svg += "'/>\n";
  };
  std::vector<std::vector<double>> cells(kMaxT + 1), layers(kMaxT + 1);
  std::vector<double> png4;
  for (const Row& r : rows) {
    std::vector<double> mine;
    for (int t = 0; t <= kMaxT; ++t) {
      mine.push_back(static_cast<double>(r.cells[t]) / r.png2);
      cells[t].push_back(mine.back());
      layers[t].push_back(static_cast<double>(r.layers[t]) / r.png2);
    }
    png4.push_back(static_cast<double>(r.png4) / r.png2);
    polyline(mine, "stroke='#9ecae1' stroke-width='1'");
  }
  std::vector<double> med_cells, med_layers;
  for (int t = 0; t <= kMaxT; ++t) {
    med_cells.push_back(Median(cells[t]));
    med_layers.push_back(Median(layers[t]));
  }
  polyline(med_cells, "stroke='#08519c' stroke-width='3'");
  polyline(med_layers, "stroke='#a63603' stroke-width='3'");
  const double p4 = Median(png4);
  add("<line x1='%.1f' x2='%.1f' y1='%.1f' y2='%.1f' stroke='black' stroke-dasharray='6 4'/>\n",
      left, w - right, y(1.0), y(1.0));
  add("<line x1='%.1f' x2='%.1f' y1='%.1f' y2='%.1f' stroke='#555' stroke-dasharray='2 3'/>\n",
      left, w - right, y(p4), y(p4));
  for (const auto& [t, r] : {std::pair{1, 0.5}, std::pair{3, 0.5 * p4}}) {
    add("<path d='M%.1f %.1f l8 8 m0 -8 l-8 8' stroke='#2ca02c' stroke-width='2' "
        "transform='translate(-4 -4)'/>\n",
        x(t), y(r));
  }
  const double lx = w - right + 12;
  add("<text x='%.1f' y='%.1f' fill='#08519c'>median, cells only</text>\n", lx,
      y(med_cells[kMaxT]));
  add("<text x='%.1f' y='%.1f' fill='#a63603'>median, with layers</text>\n", lx,
      y(med_layers[kMaxT]));
  add("<text x='%.1f' y='%.1f'>PNG-9, 2x coarser</text>\n", lx, y(1.0) + 4);
  add("<text x='%.1f' y='%.1f' fill='#555'>PNG-9, 4x coarser</text>\n", lx, y(p4) + 4);
  add("<text x='%.1f' y='%.1f' fill='#2ca02c'>goals (0.5x)</text>\n", lx, y(0.5 * p4) + 18);
  add("<text x='%.1f' y='%.1f' fill='#6baed6'>each map, cells only</text>\n", lx, top + 10);
  svg += "</svg>\n";
  return svg;
}

int Run(int argc, char** argv) {
  std::string dir = "../shared/maps";
  std::string only;
  std::string dump;  // folder for PNGs of the original and simplified grids
  bool coarse_lmap = false;
  bool free_space = false;
  std::string svg_path;  // the curve's figure
  bool with_layers = true;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto next = [&]() -> const char* { return i + 1 < argc ? argv[++i] : ""; };
    if (a == "--maps") {
      dir = next();
    } else if (a == "--only") {
      only = next();
    } else if (a == "--dump") {
      dump = next();
    } else if (a == "--coarse-lmap") {
      coarse_lmap = true;
    } else if (a == "--free-space") {
      free_space = true;
    } else if (a == "--svg") {
      svg_path = next();
    } else if (a == "--cells-only") {
      with_layers = false;
    } else {
      std::fprintf(stderr, "bench_tolerance: unknown argument '%s'\n", a.c_str());
      return 2;
    }
  }
  std::printf("%-44s %8s %8s  T: %s\n", "map", "png2x", "png4x",
              with_layers ? "cells-only bytes / with layers (ok = guarantees hold)"
                          : "cells-only bytes (ok = guarantees hold)");
  std::vector<Row> rows;
  for (const bench::SplitMap& m : bench::kTuningSplit) {
    if (!only.empty() && std::string(m.path).find(only) == std::string::npos) continue;
    StatusOr<Grid> loaded = LoadRosMap(dir + "/" + m.path);
    if (!loaded.ok()) {
      std::fprintf(stderr, "bench_tolerance: %s: %s\n", m.path, loaded.status().message().c_str());
      continue;
    }
    const Grid& g = *loaded;
    Row row;
    row.name = m.path;
    row.tuning = m.tuning;
    row.png2 = CoarserPngBytes(Coarser(g, 2));
    row.png4 = CoarserPngBytes(Coarser(g, 4));
    std::printf("%-44s %8ld %8ld ", m.path, row.png2, row.png4);
    for (int t = 0; t <= kMaxT; ++t) {
      const Saved cells = SaveWithin(g, t, false);
      row.holds[t] = cells.bytes >= 0 && CheckTolerance(g, cells.decoded, t).Holds();
      row.cells[t] = cells.bytes;
      if (t > 0 && cells.bytes >= 0) AddOtherPlans(g, cells.decoded, &row.other[t]);
      if (with_layers) {
        const Saved layers = SaveWithin(g, t, true);
        row.holds[t] =
            row.holds[t] && layers.bytes >= 0 && CheckTolerance(g, layers.decoded, t).Holds();
        row.layers[t] = layers.bytes;
      } else {
        row.layers[t] = row.cells[t];
      }
      if (!dump.empty() && cells.bytes >= 0) {
        DumpPng(cells.decoded, dump + "/" + FlatName(m.path) + "_t" + std::to_string(t) + ".png");
      }
      if (with_layers) {
        std::printf(" %ld/%ld%s", row.cells[t], row.layers[t], row.holds[t] ? "" : "!");
      } else {
        std::printf(" %ld%s", row.cells[t], row.holds[t] ? "" : "!");
      }
      std::fflush(stdout);
    }
    std::printf("\n");
    if (coarse_lmap) {
      // What the exact coder makes of the coarser maps themselves, and of
      // them drawn back at full resolution (blocks of 2 x 2 / 4 x 4 cells):
      // how much a coder that knew the block lattice could save.
      std::printf("    coarse lmap: 2x %ld, 4x %ld; drawn back at full size: 2x %ld, 4x %ld\n",
                  LmapBytes(Coarser(g, 2), false), LmapBytes(Coarser(g, 4), false),
                  LmapBytes(Upsampled(Coarser(g, 2), 2, g), false),
                  LmapBytes(Upsampled(Coarser(g, 4), 4, g), false));
    }
    if (free_space) {
      row.free_space = FreeSpaceBytes(g);
      std::printf("    free space alone, exact: %ld bytes\n", row.free_space);
    }
    rows.push_back(row);
  }
  PrintSummary(rows, Group::kTuning, with_layers);
  PrintSummary(rows, Group::kHeldOut, with_layers);
  PrintSummary(rows, Group::kAll, with_layers);
  PrintGoals(rows, with_layers);
  if (free_space) PrintFreeSpace(rows);
  PrintOtherPlans(rows);
  if (!svg_path.empty() && !rows.empty()) {
    std::FILE* f = std::fopen(svg_path.c_str(), "w");
    const std::string svg = CurveSvg(rows);
    if (f == nullptr || std::fwrite(svg.data(), 1, svg.size(), f) != svg.size()) {
      std::fprintf(stderr, "bench_tolerance: cannot write '%s'\n", svg_path.c_str());
      if (f) std::fclose(f);
      return 1;
    }
    std::fclose(f);
  }
  return 0;
}

}  // namespace
}  // namespace linemap

int main(int argc, char** argv) { return linemap::Run(argc, argv); }
