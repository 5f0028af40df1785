// bench_rooms: room segmentation (SegmentMap, method kRooms) against ground
// truth on generated floor plans (tests/testing/floor_plan.h), and its speed
// on real maps.
//
// Usage: bench_rooms [--seeds N] [--verbose] [--dump DIR] [--truth FILE.truth...]...
//                    [--maps-dir DIR] [--min-door M] [--max-door M] [MAP.yaml...]
// --min-door / --max-door M set the door width range (metres) to try
// other values than SegmentationOptions' defaults.
// --truth scores a hand-labelled map (any argument ending in .truth does,
// so that --truth DIR/*.truth takes them all) (tests/data/rooms/*.truth; its map is
// found under --maps-dir, default ../shared/maps) with the same recall and
// precision; rooms found = true rooms whose best segment is the best one of
// no other true room.
// --dump writes a PPM picture of every segmentation into DIR.
// Generated set: seeds 1..N (default 10) x {thin, thick walls} x {plain,
// furnished} x {clean, noisy}. Per variant it prints the survey's
// area-weighted recall and precision (Bormann et al., ICRA 2016), the share
// of doors found (the two rooms a door joins fall in different segments, each
// the best match of its room), rooms found / true, and on furnished plans the
// furniture figures cell by cell: recall = furniture cells inside a blob (its
// cells or its outline's interior), for all furniture, for the cabinets
// against walls and for the free-standing pieces (tables, chairs, bins);
// precision = of the non-free cells blobs cover, the share that is
// furniture, for all blobs, for the blobs against walls and for the
// free-standing ones (and the share that is no wall: furniture or scan
// specks). Then, per MAP, segmentation CPU time
// (best of 5) and ms per Mcell, rooms, corridors, doors and blobs. The
// recall and precision of the distance-transform method of the survey
// (distance_baseline.h) are printed beside ours.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "linemap/map_io.h"
#include "linemap/segmentation.h"
#include "tests/testing/floor_plan.h"
#include "tools/bench_rooms/distance_baseline.h"

namespace linemap {
namespace {

double ThreadCpuMs() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return ts.tv_sec * 1e3 + ts.tv_nsec * 1e-6;
}

struct Totals {
  double recall = 0, precision = 0;
  double base_recall = 0, base_precision = 0;  // the distance-transform baseline
  int plans = 0, doors = 0, doors_found = 0, rooms_true = 0, rooms_found = 0;
  std::size_t furniture = 0, furniture_covered = 0, blob_blocked = 0, blob_furniture = 0;
  std::size_t standalone = 0, standalone_covered = 0, blob_not_wall = 0;
  std::size_t against_wall = 0, against_wall_covered = 0;
  // Non-free cells covered by blobs against walls / free-standing blobs, and
  // of those the furniture cells.
  std::size_t wall_blob_blocked = 0, wall_blob_furniture = 0;
  std::size_t free_blob_blocked = 0, free_blob_furniture = 0;
  std::size_t blobs = 0, objects = 0;
  double ms = 0, mcells = 0;

  void Add(const Totals& o) {
    recall += o.recall, precision += o.precision;
    base_recall += o.base_recall, base_precision += o.base_precision;
    plans += o.plans, doors += o.doors, doors_found += o.doors_found;
    rooms_true += o.rooms_true, rooms_found += o.rooms_found;
    furniture += o.furniture, furniture_covered += o.furniture_covered;
    blob_blocked += o.blob_blocked, blob_furniture += o.blob_furniture;
    standalone += o.standalone, standalone_covered += o.standalone_covered;
    blob_not_wall += o.blob_not_wall, blobs += o.blobs, objects += o.objects;
    against_wall += o.against_wall, against_wall_covered += o.against_wall_covered;
    wall_blob_blocked += o.wall_blob_blocked, wall_blob_furniture += o.wall_blob_furniture;
    free_blob_blocked += o.free_blob_blocked, free_blob_furniture += o.free_blob_furniture;
    ms += o.ms, mcells += o.mcells;
  }
};

// For each true room, the segment holding most of its cells.
std::map<int, int> BestSegment(const testing::FloorPlan& plan,
                               const std::vector<std::int32_t>& segment_of) {
  std::map<std::pair<int, int>, int> overlap;
  for (std::size_t i = 0; i < plan.room_of_cell.size(); ++i) {
    if (plan.room_of_cell[i] && segment_of[i]) ++overlap[{plan.room_of_cell[i], segment_of[i]}];
  }
  std::map<int, int> best, best_n;
  for (const auto& [key, n] : overlap) {
    if (n > best_n[key.first]) {
      best_n[key.first] = n;
      best[key.first] = key.second;
    }
  }
  return best;
}

void Evaluate(const testing::FloorPlan& plan, const Segmentation& seg, Totals* t, bool verbose) {
  const Grid& grid = plan.grid;
  const testing::RoomScores scores = testing::ScoreRooms(plan.room_of_cell, seg.room_of_cell);
  const std::map<int, int> best = BestSegment(plan, seg.room_of_cell);
  int found = 0;
  for (const testing::FloorPlanDoor& door : plan.doors) {
    const auto a = best.find(door.room_a), b = best.find(door.room_b);
    found += a != best.end() && b != best.end() && a->second != b->second;
  }
  // Furniture, cell by cell.
  // 1: covered by a free-standing blob, 2: by one against a wall.
  std::vector<std::uint8_t> covered(grid.size(), 0);
  for (const FurnitureBlob& blob : seg.blobs) {
    const std::uint8_t kind = blob.against_wall ? 2 : 1;
    for (const CellIndex& cell : blob.cells) covered[grid.Index(cell.col, cell.row)] = kind;
    if (blob.outline.size() >= 3) {
      const BinaryMask fill = FillChainPolygon(blob.outline, grid.width(), grid.height());
      for (int r = blob.box.min_row; r <= blob.box.max_row; ++r) {
        for (int c = blob.box.min_col; c <= blob.box.max_col; ++c) {
          if (fill.at(c, r)) covered[grid.Index(c, r)] = kind;
        }
      }
    }
  }
  std::size_t furniture = 0, hit = 0, blocked = 0, blocked_furniture = 0;
  std::size_t standalone = 0, standalone_hit = 0, not_wall = 0;
  for (std::size_t i = 0; i < grid.size(); ++i) {
    furniture += plan.furniture[i] != 0;
    hit += plan.furniture[i] && covered[i];
    standalone += plan.furniture[i] == testing::FloorPlan::kStandAlone;
    standalone_hit += plan.furniture[i] == testing::FloorPlan::kStandAlone && covered[i];
    t->against_wall += plan.furniture[i] == testing::FloorPlan::kAgainstWall;
    t->against_wall_covered += plan.furniture[i] == testing::FloorPlan::kAgainstWall && covered[i];
    if (covered[i] && grid.cells()[i] != Cell::kFree) {
      ++blocked;
      blocked_furniture += plan.furniture[i] != 0;
      not_wall += plan.room_of_cell[i] != 0;  // furniture or a speck in a room
      if (covered[i] == 2) {
        ++t->wall_blob_blocked;
        t->wall_blob_furniture += plan.furniture[i] != 0;
      } else {
        ++t->free_blob_blocked;
        t->free_blob_furniture += plan.furniture[i] != 0;
      }
    }
  }
  t->recall += scores.recall;
  t->precision += scores.precision;
  const testing::RoomScores base =
      testing::ScoreRooms(plan.room_of_cell, bench_rooms::DistanceBaseline(grid));
  t->base_recall += base.recall;
  t->base_precision += base.precision;
  ++t->plans;
  t->doors += static_cast<int>(plan.doors.size());
  t->doors_found += found;
  t->rooms_true += plan.room_count;
  t->rooms_found += static_cast<int>(seg.rooms.size());
  t->furniture += furniture;
  t->furniture_covered += hit;
  t->standalone += standalone;
  t->standalone_covered += standalone_hit;
  t->blob_not_wall += not_wall;
  t->blob_blocked += blocked;
  t->blob_furniture += blocked_furniture;
  t->blobs += seg.blobs.size();
  t->objects += plan.furniture_objects;
  t->ms += seg.timings.total_ms;
  t->mcells += grid.size() / 1e6;
  if (verbose) {
    std::printf("  %-32s recall %.3f precision %.3f doors %d/%zu rooms %zu/%d blobs %zu/%d\n",
                plan.name.c_str(), scores.recall, scores.precision, found, plan.doors.size(),
                seg.rooms.size(), plan.room_count, seg.blobs.size(), plan.furniture_objects);
  }
}

// A picture of the segmentation (top row = last grid row): rooms in
// colours by id, walls black, unknown grey, blob cells red.
void WritePpm(const std::string& path, const Grid& grid, const Segmentation& seg) {
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) return;
  std::fprintf(f, "P6\n%d %d\n255\n", grid.width(), grid.height());
  std::vector<std::uint8_t> blob(grid.size(), 0);
  for (const FurnitureBlob& b : seg.blobs) {
    for (const CellIndex& cell : b.cells) blob[grid.Index(cell.col, cell.row)] = 1;
  }
  std::vector<std::uint8_t> chain(grid.size(), 0);
  for (const RoomBorder& room : seg.rooms) {
    for (const CellIndex& cell : room.chain) chain[grid.Index(cell.col, cell.row)] = 1;
  }
  for (int r = grid.height() - 1; r >= 0; --r) {
    for (int c = 0; c < grid.width(); ++c) {
      const std::size_t i = grid.Index(c, r);
      std::uint8_t rgb[3] = {128, 128, 128};
      const int id = seg.room_of_cell.empty() ? 0 : seg.room_of_cell[i];
      if (blob[i]) {
        rgb[0] = 255, rgb[1] = 0, rgb[2] = 0;
      } else if (grid.cells()[i] == Cell::kOccupied) {
        rgb[0] = rgb[1] = rgb[2] = 0;
      } else if (id) {
        const unsigned h = static_cast<unsigned>(id) * 2654435761u;
        rgb[0] = 100 + (h >> 8) % 156, rgb[1] = 100 + (h >> 16) % 156,
        rgb[2] = 100 + (h >> 24) % 156;
        if (chain[i]) rgb[0] /= 2, rgb[1] /= 2, rgb[2] /= 2;
      } else if (grid.cells()[i] == Cell::kFree) {
        rgb[0] = rgb[1] = rgb[2] = 255;
      }
      std::fwrite(rgb, 1, 3, f);
    }
  }
  std::fclose(f);
}

double Share(std::size_t a, std::size_t b) { return b ? static_cast<double>(a) / b : 1.0; }

int RunGenerated(int seeds, bool verbose, const std::string& dump,
                 const SegmentationOptions& seg_options) {
  std::printf(
      "| plans | recall | precision | doors found | rooms found/true | furniture recall |"
      " against-wall recall | stand-alone recall | furniture precision | against-wall"
      " precision | stand-alone precision | blob cells not wall | blobs/objects |"
      " ms per Mcell | DT baseline recall | DT baseline precision |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  Totals all;
  for (int variant = 0; variant < testing::kFloorPlanKinds; ++variant) {
    Totals t;
    const testing::FloorPlanOptions options = testing::FloorPlanKind(variant, 1);
    for (int seed = 1; seed <= seeds; ++seed) {
      const testing::FloorPlan plan = testing::GenerateFloorPlan(
          testing::FloorPlanKind(variant, static_cast<std::uint32_t>(seed)));
      StatusOr<Segmentation> seg = SegmentMap(plan.grid, seg_options);
      if (!seg.ok()) {
        std::fprintf(stderr, "bench_rooms: %s: %s\n", plan.name.c_str(),
                     seg.status().message().c_str());
        return 1;
      }
      Totals one;
      Evaluate(plan, *seg, &one, verbose);
      t.Add(one);
      all.Add(one);
      if (!dump.empty()) WritePpm(dump + "/" + plan.name + ".ppm", plan.grid, *seg);
    }
    const auto figure = [&](std::size_t a, std::size_t b) {
      char text[32] = "-";
      if (options.furniture) std::snprintf(text, sizeof(text), "%.3f", Share(a, b));
      return std::string(text);
    };
    std::printf(
        "| %s %s %s | %.3f | %.3f | %d/%d | %d/%d | %s | %s | %s | %s | %s | %s | %s | %zu/%zu | "
        "%.1f | %.3f | %.3f |\n",
        options.thick_walls ? "thick" : "thin", options.furniture ? "furnished" : "plain",
        options.noise ? "noisy" : "clean", t.recall / t.plans, t.precision / t.plans, t.doors_found,
        t.doors, t.rooms_found, t.rooms_true, figure(t.furniture_covered, t.furniture).c_str(),
        figure(t.against_wall_covered, t.against_wall).c_str(),
        figure(t.standalone_covered, t.standalone).c_str(),
        figure(t.blob_furniture, t.blob_blocked).c_str(),
        figure(t.wall_blob_furniture, t.wall_blob_blocked).c_str(),
        figure(t.free_blob_furniture, t.free_blob_blocked).c_str(),
        figure(t.blob_not_wall, t.blob_blocked).c_str(), t.blobs, t.objects, t.ms / t.mcells,
        t.base_recall / t.plans, t.base_precision / t.plans);
  }
  std::printf(
      "| all %d plans | %.3f | %.3f | %d/%d | %d/%d | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | "
      "%.3f | %zu/%zu | %.1f | %.3f | %.3f |\n",
      all.plans, all.recall / all.plans, all.precision / all.plans, all.doors_found, all.doors,
      all.rooms_found, all.rooms_true, Share(all.furniture_covered, all.furniture),
      Share(all.against_wall_covered, all.against_wall),
      Share(all.standalone_covered, all.standalone), Share(all.blob_furniture, all.blob_blocked),
      Share(all.wall_blob_furniture, all.wall_blob_blocked),
      Share(all.free_blob_furniture, all.free_blob_blocked),
      Share(all.blob_not_wall, all.blob_blocked), all.blobs, all.objects, all.ms / all.mcells,
      all.base_recall / all.plans, all.base_precision / all.plans);
  return 0;
}

int RunHandTruth(const std::vector<std::string>& paths, const std::string& maps_dir,
                 const std::string& dump, const SegmentationOptions& seg_options) {
  if (paths.empty()) return 0;
  std::printf(
      "\n| hand-labelled map | recall | precision | rooms found/true | DT baseline recall |"
      " DT baseline precision |\n|---|---|---|---|---|---|\n");
  for (const std::string& path : paths) {
    StatusOr<testing::HandTruth> truth = testing::LoadHandTruth(path, maps_dir);
    if (!truth.ok()) {
      std::fprintf(stderr, "bench_rooms: skipping %s: %s\n", path.c_str(),
                   truth.status().message().c_str());
      continue;
    }
    StatusOr<Segmentation> seg = SegmentMap(truth->grid, seg_options);
    if (!seg.ok()) {
      std::fprintf(stderr, "bench_rooms: %s: %s\n", path.c_str(), seg.status().message().c_str());
      return 1;
    }
    const testing::RoomScores scores = testing::ScoreRooms(truth->room_of_cell, seg->room_of_cell);
    // Rooms found: segments that are the best match of some true room.
    std::map<std::pair<int, int>, std::size_t> overlap;
    for (std::size_t i = 0; i < truth->room_of_cell.size(); ++i) {
      if (truth->room_of_cell[i] && seg->room_of_cell[i]) {
        ++overlap[{truth->room_of_cell[i], seg->room_of_cell[i]}];
      }
    }
    std::map<int, std::pair<std::size_t, int>> best;
    for (const auto& [key, n] : overlap) {
      if (n > best[key.first].first) best[key.first] = {n, key.second};
    }
    std::map<int, int> times_best;
    for (const auto& [room, match] : best) ++times_best[match.second];
    int found = 0;
    for (const auto& [room, match] : best) found += times_best[match.second] == 1;
    const testing::RoomScores base =
        testing::ScoreRooms(truth->room_of_cell, bench_rooms::DistanceBaseline(truth->grid));
    std::printf("| %s | %.3f | %.3f | %d/%d | %.3f | %.3f |\n", path.c_str(), scores.recall,
                scores.precision, found, truth->rooms, base.recall, base.precision);
    if (!dump.empty()) {
      std::string name = path;
      std::replace(name.begin(), name.end(), '/', '_');
      Segmentation shown;
      shown.room_of_cell = truth->room_of_cell;
      WritePpm(dump + "/" + name + ".truth.ppm", truth->grid, shown);
    }
  }
  return 0;
}

int RunMaps(const std::vector<std::string>& paths, const std::string& dump,
            const SegmentationOptions& seg_options) {
  std::printf(
      "\n| map | cells | ms (CPU, best of 5) | ms per Mcell | rooms | corridors | doors |"
      " blobs |\n|---|---|---|---|---|---|---|---|\n");
  for (const std::string& path : paths) {
    StatusOr<Grid> grid = LoadRosMap(path);
    if (!grid.ok()) {
      std::fprintf(stderr, "bench_rooms: skipping %s: %s\n", path.c_str(),
                   grid.status().message().c_str());
      continue;
    }
    double best = 1e300;
    Segmentation seg;
    for (int run = 0; run < 5; ++run) {
      const double start = ThreadCpuMs();
      StatusOr<Segmentation> result = SegmentMap(*grid, seg_options);
      best = std::min(best, ThreadCpuMs() - start);
      if (!result.ok()) {
        std::fprintf(stderr, "bench_rooms: %s: %s\n", path.c_str(),
                     result.status().message().c_str());
        return 1;
      }
      seg = std::move(*result);
    }
    if (!dump.empty()) {
      std::string name = path;
      std::replace(name.begin(), name.end(), '/', '_');
      WritePpm(dump + "/" + name + ".ppm", *grid, seg);
    }
    const int corridors = static_cast<int>(
        std::count_if(seg.rooms.begin(), seg.rooms.end(),
                      [](const RoomBorder& room) { return room.kind == RoomKind::kCorridor; }));
    std::printf("| %s | %zu | %.2f | %.1f | %zu | %d | %zu | %zu |\n", path.c_str(), grid->size(),
                best, best / (grid->size() / 1e6), seg.rooms.size(), corridors, seg.doors.size(),
                seg.blobs.size());
  }
  return 0;
}

}  // namespace
}  // namespace linemap

int main(int argc, char** argv) {
  int seeds = 10;
  bool verbose = false;
  std::string dump;
  std::string maps_dir = "../shared/maps";
  std::vector<std::string> truths;
  linemap::SegmentationOptions seg_options;
  std::vector<std::string> maps;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--seeds" && i + 1 < argc) {
      seeds = std::atoi(argv[++i]);
    } else if (arg == "--min-door" && i + 1 < argc) {
      seg_options.min_door_width_m = std::atof(argv[++i]);
    } else if (arg == "--max-door" && i + 1 < argc) {
      seg_options.max_door_width_m = std::atof(argv[++i]);
    } else if (arg == "--truth" && i + 1 < argc) {
      truths.push_back(argv[++i]);
    } else if (arg.size() > 6 && arg.substr(arg.size() - 6) == ".truth") {
      truths.push_back(arg);
    } else if (arg == "--maps-dir" && i + 1 < argc) {
      maps_dir = argv[++i];
    } else if (arg == "--dump" && i + 1 < argc) {
      dump = argv[++i];
    } else if (arg == "--verbose") {
      verbose = true;
    } else if (!arg.empty() && arg[0] == '-') {
      std::fprintf(
          stderr,
          "usage: bench_rooms [--seeds N] [--verbose] [--dump DIR] [--truth FILE.truth...]..."
          " [--maps-dir DIR] [--min-door M] [--max-door M] [MAP.yaml...]\n");
      return 2;
    } else {
      maps.push_back(arg);
    }
  }
  if (seeds < 0) seeds = 0;
  if (seeds > 0) {
    if (const int rc = linemap::RunGenerated(seeds, verbose, dump, seg_options)) return rc;
  }
  if (const int rc = linemap::RunHandTruth(truths, maps_dir, dump, seg_options)) return rc;
  return linemap::RunMaps(maps, dump, seg_options);
}
