// bench_plan: speed and quality figures for the trajectory planner,
// beside Table 1 of Kosteley et al. ("safe zone template" 29 ms, "safe zone
// layout" 3 ms, "wave algorithm" 2 ms, "trajectory region layout" 1 ms,
// "neighbourhood template" 404 ms, "trajectory scenario generation" 1.8 ms
// on a 193 x 175 map).
//
// Usage: bench_plan [--pairs N] [--seed S] [--crop W,H] [--robot W,L,M]
//                   [--dmin A] [--dmax B] MAP.yaml...
// For each map: builds the planner (templates timed 5 times), draws N random
// start/goal pairs among the safe cells, plans each, and compares with an
// 8-connected A* (octile costs, no corner cutting) on the same safe zone.
// --crop cuts a W x H window around the centre of the map's free cells.
// Prints one Markdown table row per map.
//
// Round trip (the fidelity goal): an argument ORIGINAL.yaml::DECODED.yaml
// plans the same N random pairs (map-frame points of safe cells of the
// original) on both maps and reports how often the two agree on whether a
// path exists, and how often the decoded map's best length is within 3 % of
// the original's.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <queue>
#include <random>
#include <string>
#include <vector>

#include "linemap/map_io.h"
#include "linemap/plan.h"

namespace linemap {
namespace {

using Clock = std::chrono::steady_clock;

double MsSince(Clock::time_point t) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
}

// CPU time of this thread: the machine is shared, and wall-clock times
// include the time other processes hold the core.
double ThreadCpuMs() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return ts.tv_sec * 1e3 + ts.tv_nsec * 1e-6;
}

struct Stat {
  double sum = 0, worst = 0;
  int n = 0;
  void Add(double v) {
    sum += v;
    worst = std::max(worst, v);
    ++n;
  }
  double Mean() const { return n ? sum / n : 0.0; }
};

struct AStarPath {
  bool found = false;
  double length = 0.0;
  std::size_t cells = 0;
};

AStarPath AStar(const SafeZone& zone, CellIndex s, CellIndex g) {
  const std::size_t n = zone.safe.size();
  const auto index = [&](int c, int r) { return static_cast<std::size_t>(r) * zone.width + c; };
  const auto h = [&](int c, int r) {
    const double dx = std::abs(c - g.col), dy = std::abs(r - g.row);
    return std::max(dx, dy) + (std::sqrt(2.0) - 1) * std::min(dx, dy);
  };
  std::vector<double> cost(n, 1e300);
  std::vector<int> parent(n, -1);
  std::vector<char> closed(n, 0);
  using Item = std::pair<double, std::size_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> open;
  cost[index(s.col, s.row)] = 0;
  open.push({h(s.col, s.row), index(s.col, s.row)});
  while (!open.empty()) {
    const std::size_t i = open.top().second;
    open.pop();
    if (closed[i]) continue;
    closed[i] = 1;
    const int c = static_cast<int>(i % zone.width), r = static_cast<int>(i / zone.width);
    if (c == g.col && r == g.row) break;
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        if ((dx == 0 && dy == 0) || !zone.CanStep(c, r, dx, dy)) continue;
        const std::size_t j = index(c + dx, r + dy);
        const double next = cost[i] + ((dx && dy) ? std::sqrt(2.0) : 1.0);
        if (next < cost[j] - 1e-12) {
          cost[j] = next;
          parent[j] = static_cast<int>(i);
          open.push({next + h(c + dx, r + dy), j});
        }
      }
    }
  }
  AStarPath path;
  const std::size_t goal = index(g.col, g.row);
  if (!closed[goal]) return path;
  path.found = true;
  path.length = cost[goal];
  for (int i = static_cast<int>(goal); i >= 0; i = parent[i]) ++path.cells;
  return path;
}

Grid Crop(const Grid& grid, int width, int height) {
  long long sc = 0, sr = 0, n = 0;
  for (int r = 0; r < grid.height(); ++r) {
    for (int c = 0; c < grid.width(); ++c) {
      if (grid.at(c, r) == Cell::kFree) sc += c, sr += r, ++n;
    }
  }
  width = std::min(width, grid.width());
  height = std::min(height, grid.height());
  const int c0 = std::clamp(static_cast<int>(n ? sc / n : 0) - width / 2, 0, grid.width() - width);
  const int r0 =
      std::clamp(static_cast<int>(n ? sr / n : 0) - height / 2, 0, grid.height() - height);
  Grid out(width, height);
  out.meta = grid.meta;
  for (int r = 0; r < height; ++r) {
    for (int c = 0; c < width; ++c) out.set(c, r, grid.at(c0 + c, r0 + r));
  }
  return out;
}

struct Args {
  int pairs = 100;
  unsigned seed = 1;
  int crop_w = 0, crop_h = 0;
  bool verbose = false;  // round trip: print the pairs that disagree
  PlanOptions options;
  std::vector<std::string> maps;
};

bool ParseArgs(int argc, char** argv, Args* a) {
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const bool has_value = i + 1 < argc;
    if (arg == "--verbose") {
      a->verbose = true;
    } else if (arg == "--pairs" && has_value) {
      a->pairs = std::atoi(argv[++i]);
    } else if (arg == "--seed" && has_value) {
      a->seed = static_cast<unsigned>(std::atoi(argv[++i]));
    } else if (arg == "--crop" && has_value) {
      if (std::sscanf(argv[++i], "%d,%d", &a->crop_w, &a->crop_h) != 2) return false;
    } else if (arg == "--robot" && has_value) {
      RobotFootprint& r = a->options.robot;
      if (std::sscanf(argv[++i], "%lf,%lf,%lf", &r.width_m, &r.length_m, &r.margin_m) != 3) {
        return false;
      }
    } else if (arg == "--dmin" && has_value) {
      a->options.d_min_m = std::atof(argv[++i]);
    } else if (arg == "--dmax" && has_value) {
      a->options.d_max_m = std::atof(argv[++i]);
    } else if (!arg.empty() && arg[0] == '-') {
      return false;
    } else {
      a->maps.push_back(arg);
    }
  }
  return !a->maps.empty();
}

int BenchMap(const std::string& path, const Args& args) {
  StatusOr<Grid> loaded = LoadRosMap(path);
  if (!loaded.ok()) {
    std::fprintf(stderr, "bench_plan: %s: %s\n", path.c_str(), loaded.status().ToString().c_str());
    return 1;
  }
  const Grid grid = args.crop_w > 0 ? Crop(*loaded, args.crop_w, args.crop_h) : *loaded;
  Stat mask_ms, template_ms;
  StatusOr<Planner> planner = Planner::Create(args.options, grid.meta.resolution);
  if (!planner.ok()) {
    std::fprintf(stderr, "bench_plan: %s: %s\n", path.c_str(), planner.status().ToString().c_str());
    return 1;
  }
  const double resolution = grid.meta.resolution;
  for (int k = 0; k < 5; ++k) {
    double t0 = ThreadCpuMs();
    const ImpassableAreaMask mask =
        ImpassableAreaMask::Build(SafeDistanceMetres(args.options.robot) / resolution);
    mask_ms.Add(ThreadCpuMs() - t0);
    t0 = ThreadCpuMs();
    const MoveTemplate moves = MoveTemplate::Build(args.options.d_max_m / resolution);
    template_ms.Add(ThreadCpuMs() - t0);
  }
  GenerationOptions generation;
  generation.d_min_cells = args.options.d_min_m / resolution;
  generation.max_extra_nodes = args.options.max_extra_nodes;
  generation.max_length_excess = args.options.max_length_excess;
  generation.max_expansions = args.options.max_expansions;
  generation.max_trajectories = args.options.max_trajectories;
  const SafeZone zone = ComputeSafeZone(grid, planner->mask());
  std::vector<CellIndex> safe;
  for (int r = 0; r < zone.height; ++r) {
    for (int c = 0; c < zone.width; ++c) {
      if (zone.IsSafe(c, r)) safe.push_back({c, r});
    }
  }
  if (safe.empty()) {
    std::printf("| %s | %dx%d | no safe cell |\n", path.c_str(), grid.width(), grid.height());
    return 0;
  }
  std::mt19937 rng(args.seed);
  std::uniform_int_distribution<std::size_t> pick(0, safe.size() - 1);
  Stat zone_ms, wave_ms, region_ms, gen_ms, total_ms, ratio, moves, astar_cells, alternatives;
  int reachable = 0, unreachable = 0, mismatched = 0, within = 0, straightened = 0;
  for (int k = 0; k < args.pairs; ++k) {
    const CellIndex s = safe[pick(rng)], g = safe[pick(rng)];
    PlanRequest q;
    grid.CellToWorld(s.col, s.row, &q.start_x, &q.start_y);
    grid.CellToWorld(g.col, g.row, &q.goal_x, &q.goal_y);
    const Clock::time_point t = Clock::now();
    StatusOr<PlanResult> result = planner->Plan(grid, q);
    total_ms.Add(MsSince(t));
    if (!result.ok()) return 1;
    // The stages again, one by one, in CPU time.
    double t0 = ThreadCpuMs();
    const SafeZone stage_zone = ComputeSafeZone(grid, planner->mask());
    double t1 = ThreadCpuMs();
    zone_ms.Add(t1 - t0);
    const LeeWave wave = RunLeeWave(stage_zone, s, g);
    t0 = ThreadCpuMs();
    wave_ms.Add(t0 - t1);
    if (wave.goal_index >= 0) {
      const TrajectoryRegion region = MarkTrajectoryRegion(stage_zone, wave, g);
      t1 = ThreadCpuMs();
      region_ms.Add(t1 - t0);
      const std::vector<CellTrajectory> found = GenerateTrajectories(
          stage_zone, wave, region, planner->move_template(), s, g, generation);
      gen_ms.Add(ThreadCpuMs() - t1);
    }
    const AStarPath reference = AStar(zone, s, g);
    if (reference.found != result->found()) ++mismatched;
    if (!reference.found) {
      ++unreachable;
      continue;
    }
    if (!result->found()) continue;
    ++reachable;
    const PlannedTrajectory& best = result->trajectories.front();
    const double r =
        reference.length > 0 ? best.length_m / grid.meta.resolution / reference.length : 1.0;
    ratio.Add(r);
    if (r <= 1.10 + 1e-9) {
      ++within;
    } else {
      std::fprintf(stderr, "over 10%%: %s %d,%d -> %d,%d: %.3f (%zu moves, A* %.1f cells)\n",
                   path.c_str(), s.col, s.row, g.col, g.row, r, best.cells.size() - 1,
                   reference.length);
    }
    moves.Add(static_cast<double>(best.cells.size() - 1));
    astar_cells.Add(static_cast<double>(reference.cells));
    alternatives.Add(static_cast<double>(result->trajectories.size()));
    if (best.straightened) ++straightened;
  }
  std::printf(
      "| %s | %dx%d | %.2f / %.2f | %.2f / %.2f | %.2f / %.2f | %.2f / %.2f | %.2f / %.2f | %.2f / "
      "%.2f "
      "| %.2f / %.2f | %d+%d | %d | %.3f / %.3f | %d | %.1f | %.1f | %.1f | %d |\n",
      path.c_str(), grid.width(), grid.height(), mask_ms.Mean(), mask_ms.worst, template_ms.Mean(),
      template_ms.worst, zone_ms.Mean(), zone_ms.worst, wave_ms.Mean(), wave_ms.worst,
      region_ms.Mean(), region_ms.worst, gen_ms.Mean(), gen_ms.worst, total_ms.Mean(),
      total_ms.worst, reachable, unreachable, mismatched, ratio.Mean(), ratio.worst, within,
      moves.Mean(), astar_cells.Mean(), alternatives.Mean(), straightened);
  std::fflush(stdout);
  return 0;
}

int BenchRoundTrip(const std::string& original_path, const std::string& decoded_path,
                   const Args& args) {
  StatusOr<Grid> original = LoadRosMap(original_path);
  StatusOr<Grid> decoded = LoadRosMap(decoded_path);
  if (!original.ok() || !decoded.ok()) {
    std::fprintf(stderr, "bench_plan: %s\n",
                 (!original.ok() ? original.status() : decoded.status()).ToString().c_str());
    return 1;
  }
  StatusOr<Planner> on_original = Planner::Create(args.options, original->meta.resolution);
  StatusOr<Planner> on_decoded = Planner::Create(args.options, decoded->meta.resolution);
  if (!on_original.ok() || !on_decoded.ok()) return 1;
  const SafeZone zone = ComputeSafeZone(*original, on_original->mask());
  std::vector<CellIndex> safe;
  for (int r = 0; r < zone.height; ++r) {
    for (int c = 0; c < zone.width; ++c) {
      if (zone.IsSafe(c, r)) safe.push_back({c, r});
    }
  }
  if (safe.empty()) return 0;
  std::mt19937 rng(args.seed);
  std::uniform_int_distribution<std::size_t> pick(0, safe.size() - 1);
  const SafeZone decoded_zone = ComputeSafeZone(*decoded, on_decoded->mask());
  int found_original = 0, found_decoded = 0, agree = 0, both = 0, within = 0;
  int astar_both = 0, astar_within = 0, shortest_within = 0;
  double worst = 0.0, astar_worst = 0.0, shortest_worst = 0.0;
  const auto excess_of = [](double la, double lb) {
    return la > 0 ? std::abs(lb / la - 1.0) : (lb > 0 ? 1.0 : 0.0);
  };
  const auto shortest = [](const PlanResult& p) {
    double best = p.trajectories.front().length_m;
    for (const auto& t : p.trajectories) best = std::min(best, t.length_m);
    return best;
  };
  for (int k = 0; k < args.pairs; ++k) {
    const CellIndex s = safe[pick(rng)], g = safe[pick(rng)];
    PlanRequest q;
    original->CellToWorld(s.col, s.row, &q.start_x, &q.start_y);
    original->CellToWorld(g.col, g.row, &q.goal_x, &q.goal_y);
    StatusOr<PlanResult> a = on_original->Plan(*original, q);
    StatusOr<PlanResult> b = on_decoded->Plan(*decoded, q);
    if (!a.ok() || !b.ok()) return 1;
    found_original += a->found();
    found_decoded += b->found();
    agree += a->found() == b->found();
    if (args.verbose && a->found() != b->found()) {
      std::fprintf(stderr, "%s: (%d,%d) -> (%d,%d): found %d on the original, %d decoded\n",
                   original_path.c_str(), s.col, s.row, g.col, g.row, a->found(), b->found());
    }
    // The same pair on the two safe zones by A*: how much of a difference
    // is the map's, not the planner's.
    const AStarPath ra = AStar(zone, s, g);
    const AStarPath rb = AStar(decoded_zone, s, g);
    if (ra.found && rb.found) {
      ++astar_both;
      const double e = excess_of(ra.length, rb.length);
      astar_worst = std::max(astar_worst, e);
      astar_within += e <= 0.03 + 1e-12;
    }
    if (!a->found() || !b->found()) continue;
    ++both;
    const double excess =
        excess_of(a->trajectories.front().length_m, b->trajectories.front().length_m);
    worst = std::max(worst, excess);
    within += excess <= 0.03 + 1e-12;
    const double shortest_excess = excess_of(shortest(*a), shortest(*b));
    shortest_worst = std::max(shortest_worst, shortest_excess);
    shortest_within += shortest_excess <= 0.03 + 1e-12;
  }
  std::printf(
      "| %s | %d | %d | %d | %d / %d | %d / %d | %.1f %% | %d / %d | %.1f %% | %d / %d | %.1f %% "
      "|\n",
      original_path.c_str(), args.pairs, found_original, found_decoded, agree, args.pairs, within,
      both, 100.0 * worst, shortest_within, both, 100.0 * shortest_worst, astar_within, astar_both,
      100.0 * astar_worst);
  std::fflush(stdout);
  return 0;
}

}  // namespace
}  // namespace linemap

int main(int argc, char** argv) {
  linemap::Args args;
  if (!linemap::ParseArgs(argc, argv, &args)) {
    std::fprintf(stderr,
                 "usage: bench_plan [--pairs N] [--seed S] [--crop W,H] [--robot W,L,M] "
                 "[--dmin A] [--dmax B] MAP.yaml... | ORIGINAL.yaml::DECODED.yaml...\n");
    return 2;
  }
  if (args.maps.front().find("::") != std::string::npos) {
    std::printf(
        "| original map | pairs | found on original | found on decoded | agree | best length "
        "within 3 %% | worst length difference | shortest trajectory within 3 %% | worst | "
        "A* within 3 %% | worst |\n|---|---|---|---|---|---|---|---|---|---|---|\n");
    int rc = 0;
    for (const std::string& arg : args.maps) {
      const std::size_t cut = arg.find("::");
      if (cut == std::string::npos) return 2;
      rc |= linemap::BenchRoundTrip(arg.substr(0, cut), arg.substr(cut + 2), args);
    }
    return rc;
  }
  std::printf(
      "| map | cells | mask template CPU ms (mean / worst) | move template CPU ms | "
      "safe zone CPU ms | wave CPU ms | regions CPU ms | generation CPU ms | whole call wall ms | "
      "pairs reachable+not | found != A* | length / A* (mean / worst) | within 10%% | "
      "moves (mean) | A* cells (mean) | trajectories (mean) | best is straightened |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  int rc = 0;
  for (const std::string& map : args.maps) rc |= linemap::BenchMap(map, args);
  return rc;
}
