#include "tests/testing/floor_plan.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <map>
#include <random>
#include <sstream>
#include <utility>

#include "linemap/map_io.h"

namespace linemap::testing {
namespace {

struct Rect {
  int c0 = 0, r0 = 0, c1 = -1, r1 = -1;  // inclusive cells
  int width() const { return c1 - c0 + 1; }
  int height() const { return r1 - r0 + 1; }
};

class Builder {
 public:
  explicit Builder(const FloorPlanOptions& options) : options_(options), rng_(options.seed) {}
  FloorPlan Build();

 private:
  int Cells(double metres) const {
    return std::max(1, static_cast<int>(std::lround(metres / options_.resolution)));
  }
  double Uniform(double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(rng_);
  }
  int UniformInt(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }
  bool Chance(double p) { return Uniform(0, 1) < p; }

  void FillRect(const Rect& rect, Cell value) {
    for (int r = rect.r0; r <= rect.r1; ++r) {
      for (int c = rect.c0; c <= rect.c1; ++c) plan_.grid.set(c, r, value);
    }
  }
  void LabelRect(const Rect& rect, int id) {
    for (int r = rect.r0; r <= rect.r1; ++r) {
      for (int c = rect.c0; c <= rect.c1; ++c) plan_.room_of_cell[plan_.grid.Index(c, r)] = id;
    }
  }
  int AddRoom(const Rect& rect) {
    FillRect(rect, Cell::kFree);
    LabelRect(rect, ++plan_.room_count);
    rooms_.push_back(rect);
    alias_.push_back(plan_.room_count);
    return plan_.room_count;
  }
  void AddDoor(const Rect& opening, int a, int b, double width_m);
  std::vector<int> Widths(int total_cells);
  void AddSide(int first_col, int length, int corridor_row, bool above, int depth);
  void AddFurniture(int room);
  bool Clear(int room, const Rect& rect, int margin) const;
  void Occupy(const Rect& rect, std::uint8_t kind = FloorPlan::kStandAlone);
  void AddNoise();
  void AddNotch(int room, bool above);
  void JoinOpenRooms();

  FloorPlanOptions options_;
  std::mt19937 rng_;
  FloorPlan plan_;
  std::vector<Rect> rooms_;    // by id - 1
  std::vector<int> alias_{0};  // by id: the room it is one with (wide openings)
  int wall_ = 1;               // wall thickness, cells
  double corridor_m_ = 2.0;    // corridor width
};

// A door across a wall: `opening` spans the wall's thickness; its cells are
// free and belong to no room.
void Builder::AddDoor(const Rect& opening, int a, int b, double width_m) {
  FillRect(opening, Cell::kFree);
  LabelRect(opening, 0);
  plan_.doors.push_back(
      {a, b, {(opening.c0 + opening.c1) / 2, (opening.r0 + opening.r1) / 2}, width_m});
}

// Room widths along the corridor filling `total_cells` with walls of
// wall_ cells between them, each 2.5 to 5 m.
std::vector<int> Builder::Widths(int total_cells) {
  std::vector<int> widths;
  int used = 0;
  while (true) {
    const int w = Cells(Uniform(2.5, 5.0));
    if (used + w + wall_ + Cells(2.5) > total_cells) {
      widths.push_back(total_cells - used);
      return widths;
    }
    widths.push_back(w);
    used += w + wall_;
  }
}

// One row of rooms along the corridor, each with a door to it and, now and
// then, one to its left neighbour.
void Builder::AddSide(int first_col, int length, int corridor_row, bool above, int depth) {
  const Rect corridor = rooms_[plan_.corridor - 1];
  int col = first_col;
  int previous = 0;
  for (const int width : Widths(length)) {
    Rect room;
    room.c0 = col;
    room.c1 = col + width - 1;
    room.r0 = above ? corridor.r1 + wall_ + 1 : corridor_row - wall_ - depth;
    room.r1 = room.r0 + depth - 1;
    const int id = AddRoom(room);
    // A door narrower than the corridor by 0.3 m at least: a door as wide
    // as the corridor is no narrowing that anybody could see in the map.
    const double door_m = Uniform(0.7, std::min(1.2, corridor_m_ - 0.3));
    const int door = Cells(door_m);
    const int dc = UniformInt(room.c0 + Cells(0.3), room.c1 - Cells(0.3) - door + 1);
    const Rect opening = above ? Rect{dc, corridor.r1 + 1, dc + door - 1, room.r0 - 1}
                               : Rect{dc, room.r1 + 1, dc + door - 1, corridor.r0 - 1};
    AddDoor(opening, id, plan_.corridor, door_m);
    if (previous && Chance(0.15)) {
      // A wide opening: the two rooms are one.
      const int height = std::min(room.height(), rooms_[previous - 1].height());
      const Rect opening{room.c0 - wall_, room.r0 + Cells(0.3), room.c0 - 1,
                         room.r0 + height - Cells(0.3) - 1};
      FillRect(opening, Cell::kFree);
      LabelRect(opening, previous);
      alias_[id] = alias_[previous];
    } else if (previous && Chance(0.35)) {
      const double side_m = Uniform(0.7, 1.2);
      const int side = Cells(side_m);
      const int height = std::min(room.height(), rooms_[previous - 1].height());
      const int r0 = room.r0 + UniformInt(Cells(0.3), height - Cells(0.3) - side);
      AddDoor({room.c0 - wall_, r0, room.c0 - 1, r0 + side - 1}, previous, id, side_m);
    }
    previous = id;
    col += width + wall_;
  }
}

// True when `rect` grown by `margin` lies in the free cells of `room`, away
// from its doors.
bool Builder::Clear(int room, const Rect& rect, int margin) const {
  for (int r = rect.r0 - margin; r <= rect.r1 + margin; ++r) {
    for (int c = rect.c0 - margin; c <= rect.c1 + margin; ++c) {
      if (!plan_.grid.Contains(c, r)) return false;
      const std::size_t i = plan_.grid.Index(c, r);
      if (plan_.room_of_cell[i] != room || plan_.grid.cells()[i] != Cell::kFree) return false;
    }
  }
  const int keep_off = Cells(1.0);
  for (const FloorPlanDoor& door : plan_.doors) {
    if (door.centre.col >= rect.c0 - keep_off && door.centre.col <= rect.c1 + keep_off &&
        door.centre.row >= rect.r0 - keep_off && door.centre.row <= rect.r1 + keep_off) {
      return false;
    }
  }
  return true;
}

void Builder::Occupy(const Rect& rect, std::uint8_t kind) {
  for (int r = rect.r0; r <= rect.r1; ++r) {
    for (int c = rect.c0; c <= rect.c1; ++c) {
      const std::size_t i = plan_.grid.Index(c, r);
      if (plan_.grid.cells()[i] == Cell::kFree) plan_.furniture[i] = kind;
      plan_.grid.mutable_cells()[i] = Cell::kOccupied;
    }
  }
}

// A table with four legs and two chairs with four legs each, a bin, and a
// cabinet against a wall, each where it fits.
void Builder::AddFurniture(int room) {
  const Rect area = rooms_[room - 1];
  const int leg = Cells(0.05);
  auto legs = [&](const Rect& top, int size) {
    Occupy({top.c0, top.r0, top.c0 + size - 1, top.r0 + size - 1});
    Occupy({top.c1 - size + 1, top.r0, top.c1, top.r0 + size - 1});
    Occupy({top.c0, top.r1 - size + 1, top.c0 + size - 1, top.r1});
    Occupy({top.c1 - size + 1, top.r1 - size + 1, top.c1, top.r1});
  };
  auto place = [&](int w, int h, int margin, Rect* out) {
    for (int attempt = 0; attempt < 40; ++attempt) {
      const int c0 = UniformInt(area.c0, std::max(area.c0, area.c1 - w + 1));
      const int r0 = UniformInt(area.r0, std::max(area.r0, area.r1 - h + 1));
      const Rect rect{c0, r0, c0 + w - 1, r0 + h - 1};
      if (Clear(room, rect, margin)) {
        *out = rect;
        return true;
      }
    }
    return false;
  };
  Rect table;
  if (place(Cells(Uniform(1.0, 1.6)), Cells(0.8), Cells(0.4), &table)) {
    legs(table, std::max(1, UniformInt(leg, 2 * leg)));
    ++plan_.furniture_objects;
    for (int k = 0; k < 2; ++k) {
      Rect chair;
      if (place(Cells(0.45), Cells(0.45), Cells(0.3), &chair)) {
        legs(chair, 1);
        ++plan_.furniture_objects;
      }
    }
  }
  Rect bin;
  if (Chance(0.5) && place(Cells(0.3), Cells(0.3), Cells(0.3), &bin)) {
    Occupy(bin);
    ++plan_.furniture_objects;
  }
  if (Chance(0.5)) {
    // A cabinet against one of the room's walls, off the room's corners: 0.6
    // to 1.6 m along the wall, 0.3 to 0.6 m deep.
    const int along = Cells(Uniform(0.6, 1.6)), depth = Cells(Uniform(0.3, 0.6));
    for (int attempt = 0; attempt < 20; ++attempt) {
      const int side = UniformInt(0, 3);  // bottom, top, left, right
      Rect cabinet;
      if (side < 2) {
        const int c0 = UniformInt(area.c0 + 1, std::max(area.c0 + 1, area.c1 - along));
        cabinet = {c0, side == 1 ? area.r1 - depth + 1 : area.r0, c0 + along - 1,
                   side == 1 ? area.r1 : area.r0 + depth - 1};
      } else {
        const int r0 = UniformInt(area.r0 + 1, std::max(area.r0 + 1, area.r1 - along));
        cabinet = {side == 3 ? area.c1 - depth + 1 : area.c0, r0,
                   side == 3 ? area.c1 : area.c0 + depth - 1, r0 + along - 1};
      }
      // Against wall the whole way (not in front of a wide opening).
      const Rect behind =
          side == 0   ? Rect{cabinet.c0 - 1, area.r0 - 1, cabinet.c1 + 1, area.r0 - 1}
          : side == 1 ? Rect{cabinet.c0 - 1, area.r1 + 1, cabinet.c1 + 1, area.r1 + 1}
          : side == 2 ? Rect{area.c0 - 1, cabinet.r0 - 1, area.c0 - 1, cabinet.r1 + 1}
                      : Rect{area.c1 + 1, cabinet.r0 - 1, area.c1 + 1, cabinet.r1 + 1};
      bool walled = true;
      for (int r = behind.r0; r <= behind.r1; ++r) {
        for (int c = behind.c0; c <= behind.c1; ++c) {
          walled = walled && plan_.grid.at(c, r) == Cell::kOccupied;
        }
      }
      if (walled && Clear(room, cabinet, 0)) {
        Occupy(cabinet, FloorPlan::kAgainstWall);
        ++plan_.furniture_objects;
        break;
      }
    }
  }
}

// Specks in the free space and cells lost along the walls (occupied or
// unknown), as a laser scan leaves them.
void Builder::AddNoise() {
  Grid& grid = plan_.grid;
  const Grid before = grid;
  for (int r = 1; r + 1 < grid.height(); ++r) {
    for (int c = 1; c + 1 < grid.width(); ++c) {
      if (before.at(c, r) != Cell::kFree) continue;
      const bool by_wall =
          before.at(c - 1, r) == Cell::kOccupied || before.at(c + 1, r) == Cell::kOccupied ||
          before.at(c, r - 1) == Cell::kOccupied || before.at(c, r + 1) == Cell::kOccupied;
      if (by_wall && Chance(0.12)) {
        grid.set(c, r, Chance(0.7) ? Cell::kOccupied : Cell::kUnknown);
      } else if (!by_wall && Chance(0.0008)) {
        grid.set(c, r, Cell::kOccupied);
      }
    }
  }
}

// Makes the room an L: a block of wall in one of its back corners (away
// from the corridor), unless a doorway is near.
void Builder::AddNotch(int room, bool above) {
  const Rect area = rooms_[room - 1];
  const int w = static_cast<int>(area.width() * Uniform(0.3, 0.45));
  const int h = static_cast<int>(area.height() * Uniform(0.3, 0.45));
  const bool left = Chance(0.5);
  Rect notch;
  notch.c0 = left ? area.c0 : area.c1 - w + 1;
  notch.c1 = notch.c0 + w - 1;
  notch.r0 = above ? area.r1 - h + 1 : area.r0;
  notch.r1 = notch.r0 + h - 1;
  const int keep_off = Cells(0.6);
  for (int r = notch.r0 - keep_off; r <= notch.r1 + keep_off; ++r) {
    for (int c = notch.c0 - keep_off; c <= notch.c1 + keep_off; ++c) {
      if (!plan_.grid.Contains(c, r)) continue;
      const std::size_t i = plan_.grid.Index(c, r);
      const bool doorway = plan_.grid.cells()[i] == Cell::kFree && plan_.room_of_cell[i] == 0;
      const bool opening = plan_.grid.cells()[i] == Cell::kFree && plan_.room_of_cell[i] != room &&
                           plan_.room_of_cell[i] != 0 && (c < area.c0 || c > area.c1);
      if (doorway || opening) return;
    }
  }
  FillRect(notch, Cell::kOccupied);
  LabelRect(notch, 0);
}

// Rooms joined by wide openings get one id; ids are renumbered 1..n in
// order, the doors follow.
void Builder::JoinOpenRooms() {
  std::vector<int> id_of(alias_.size(), 0);
  int next = 0;
  for (std::size_t k = 1; k < alias_.size(); ++k) {
    int root = static_cast<int>(k);
    while (alias_[root] != root) root = alias_[root];
    if (!id_of[root]) id_of[root] = ++next;
    id_of[k] = id_of[root];
  }
  for (std::int32_t& id : plan_.room_of_cell) id = id_of[id];
  for (FloorPlanDoor& door : plan_.doors) {
    door.room_a = id_of[door.room_a];
    door.room_b = id_of[door.room_b];
  }
  plan_.corridor = id_of[plan_.corridor];
  plan_.room_count = next;
}

FloorPlan Builder::Build() {
  const double res = options_.resolution;
  wall_ = options_.thick_walls ? Cells(Uniform(0.15, 0.30)) : Cells(Uniform(0.05, 0.10));
  const int margin = Cells(1.0);
  corridor_m_ = Uniform(1.4, 2.4);
  const int corridor_w = Cells(corridor_m_);
  const int depth_below = Cells(Uniform(3.0, 5.0));
  const int depth_above = Cells(Uniform(3.0, 5.0));
  const int length = Cells(options_.rooms_per_side * 3.75);
  const int width = 2 * margin + 2 * wall_ + length;
  const int height = 2 * margin + 4 * wall_ + depth_below + corridor_w + depth_above;
  plan_.grid = Grid(width, height, Cell::kUnknown);
  plan_.grid.meta.resolution = res;
  plan_.room_of_cell.assign(plan_.grid.size(), 0);
  plan_.furniture.assign(plan_.grid.size(), 0);
  FillRect({margin, margin, width - margin - 1, height - margin - 1}, Cell::kOccupied);
  const int first_col = margin + wall_;
  const int corridor_row = margin + 2 * wall_ + depth_below;
  plan_.corridor =
      AddRoom({first_col, corridor_row, first_col + length - 1, corridor_row + corridor_w - 1});
  AddSide(first_col, length, corridor_row, false, depth_below);
  AddSide(first_col, length, corridor_row, true, depth_above);
  for (int id = 1; id <= plan_.room_count; ++id) {
    if (id != plan_.corridor && Chance(0.3)) AddNotch(id, rooms_[id - 1].r0 > corridor_row);
  }
  if (options_.furniture) {
    for (int id = 1; id <= plan_.room_count; ++id) {
      if (id != plan_.corridor) AddFurniture(id);
    }
  }
  if (options_.noise) AddNoise();
  JoinOpenRooms();
  plan_.name = "seed" + std::to_string(options_.seed) +
               (options_.thick_walls ? "-thick" : "-thin") +
               (options_.furniture ? "-furnished" : "") + (options_.noise ? "-noisy" : "");
  return std::move(plan_);
}

}  // namespace

FloorPlan GenerateFloorPlan(const FloorPlanOptions& options) { return Builder(options).Build(); }

RoomScores ScoreRooms(const std::vector<std::int32_t>& truth,
                      const std::vector<std::int32_t>& segment_of) {
  std::map<std::pair<std::int32_t, std::int32_t>, std::size_t> overlap;
  std::map<std::int32_t, std::size_t> truth_size, segment_size, truth_best, segment_best;
  for (std::size_t i = 0; i < truth.size(); ++i) {
    if (!truth[i]) continue;
    ++truth_size[truth[i]];
    if (!segment_of[i]) continue;
    ++segment_size[segment_of[i]];
    ++overlap[{truth[i], segment_of[i]}];
  }
  for (const auto& [key, n] : overlap) {
    truth_best[key.first] = std::max(truth_best[key.first], n);
    segment_best[key.second] = std::max(segment_best[key.second], n);
  }
  std::size_t truth_total = 0, segment_total = 0, recall_hits = 0, precision_hits = 0;
  for (const auto& [id, n] : truth_size) {
    truth_total += n;
    recall_hits += truth_best[id];
  }
  for (const auto& [id, n] : segment_size) {
    segment_total += n;
    precision_hits += segment_best[id];
  }
  RoomScores scores;
  scores.recall = truth_total ? static_cast<double>(recall_hits) / truth_total : 1.0;
  scores.precision = segment_total ? static_cast<double>(precision_hits) / segment_total : 1.0;
  return scores;
}

StatusOr<HandTruth> LoadHandTruth(const std::string& path, const std::string& maps_dir) {
  std::ifstream in(path);
  if (!in) return NotFoundError(path + ": cannot open");
  std::string map;
  std::vector<std::array<int, 4>> cuts;
  std::vector<std::array<int, 2>> outside;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string key;
    if (!(words >> key) || key[0] == '#') continue;
    if (key == "map") {
      words >> map;
    } else if (key == "cut") {
      std::array<int, 4> cut{};
      if (!(words >> cut[0] >> cut[1] >> cut[2] >> cut[3])) {
        return InvalidArgumentError(path + ": bad line '" + line + "'");
      }
      cuts.push_back(cut);
    } else if (key == "outside") {
      std::array<int, 2> at{};
      if (!(words >> at[0] >> at[1]))
        return InvalidArgumentError(path + ": bad line '" + line + "'");
      outside.push_back(at);
    } else {
      return InvalidArgumentError(path + ": unknown key '" + key + "'");
    }
  }
  HandTruth truth;
  LINEMAP_ASSIGN_OR_RETURN(truth.grid, LoadRosMap(maps_dir + "/" + map));
  const Grid& grid = truth.grid;
  const int w = grid.width(), h = grid.height();
  // Image pixel (col, image row) to grid cell.
  auto cell = [&](int col, int image_row) { return CellIndex{col, h - 1 - image_row}; };
  std::vector<std::uint8_t> blocked(grid.size(), 0);
  for (std::size_t i = 0; i < grid.size(); ++i) blocked[i] = grid.cells()[i] != Cell::kFree;
  for (const auto& cut : cuts) {
    const int n = std::max(std::abs(cut[2] - cut[0]), std::abs(cut[3] - cut[1]));
    for (int k = 0; k <= n; ++k) {
      const double t = n ? static_cast<double>(k) / n : 0.0;
      const CellIndex c = cell(static_cast<int>(std::lround(cut[0] + t * (cut[2] - cut[0]))),
                               static_cast<int>(std::lround(cut[1] + t * (cut[3] - cut[1]))));
      if (grid.Contains(c.col, c.row)) blocked[grid.Index(c.col, c.row)] = 1;
    }
  }
  // Paint bucket: 4-connected components of the unblocked free cells.
  std::vector<std::int32_t> component(grid.size(), 0);
  std::vector<std::size_t> size{0};
  for (std::size_t seed = 0; seed < grid.size(); ++seed) {
    if (blocked[seed] || component[seed]) continue;
    const std::int32_t id = static_cast<std::int32_t>(size.size());
    size.push_back(0);
    std::vector<std::size_t> stack{seed};
    component[seed] = id;
    while (!stack.empty()) {
      const std::size_t i = stack.back();
      stack.pop_back();
      ++size[id];
      const int c = static_cast<int>(i % w), r = static_cast<int>(i / w);
      const int dc[4] = {1, -1, 0, 0}, dr[4] = {0, 0, 1, -1};
      for (int d = 0; d < 4; ++d) {
        const int nc = c + dc[d], nr = r + dr[d];
        if (nc < 0 || nr < 0 || nc >= w || nr >= h) continue;
        const std::size_t j = grid.Index(nc, nr);
        if (blocked[j] || component[j]) continue;
        component[j] = id;
        stack.push_back(j);
      }
    }
  }
  std::vector<std::uint8_t> skip(size.size(), 0);
  for (const auto& at : outside) {
    const CellIndex c = cell(at[0], at[1]);
    if (grid.Contains(c.col, c.row)) skip[component[grid.Index(c.col, c.row)]] = 1;
  }
  const double cell_area = grid.meta.resolution * grid.meta.resolution;
  std::vector<std::int32_t> room_of(size.size(), 0);
  truth.room_of_cell.assign(grid.size(), 0);
  for (std::size_t i = 0; i < grid.size(); ++i) {
    const std::int32_t k = component[i];
    if (!k || skip[k] || size[k] * cell_area < 1.0) continue;
    if (!room_of[k]) room_of[k] = ++truth.rooms;
    truth.room_of_cell[i] = room_of[k];
  }
  return truth;
}

FloorPlanOptions FloorPlanKind(int kind, std::uint32_t seed) {
  FloorPlanOptions options;
  options.seed = seed;
  options.thick_walls = (kind & 1) != 0;
  options.furniture = (kind & 2) != 0;
  options.noise = (kind & 4) != 0;
  return options;
}

}  // namespace linemap::testing
