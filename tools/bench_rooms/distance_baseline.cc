#include "tools/bench_rooms/distance_baseline.h"

#include <algorithm>
#include <cstddef>
#include <deque>

namespace linemap::bench_rooms {
namespace {

// Chamfer 3-4 distance of free cells to the nearest other cell (the map
// edge counts as an obstacle); 0 off the free space.
std::vector<int> Distances(const Grid& grid) {
  const int w = grid.width(), h = grid.height();
  std::vector<int> d(grid.size(), 0);
  const int far = 1 << 29;
  for (std::size_t i = 0; i < grid.size(); ++i) d[i] = grid.cells()[i] == Cell::kFree ? far : 0;
  auto get = [&](int c, int r) { return grid.Contains(c, r) ? d[grid.Index(c, r)] : 0; };
  for (int r = 0; r < h; ++r) {
    for (int c = 0; c < w; ++c) {
      int& v = d[grid.Index(c, r)];
      if (!v) continue;
      v = std::min(
          {v, get(c - 1, r) + 3, get(c, r - 1) + 3, get(c - 1, r - 1) + 4, get(c + 1, r - 1) + 4});
    }
  }
  for (int r = h - 1; r >= 0; --r) {
    for (int c = w - 1; c >= 0; --c) {
      int& v = d[grid.Index(c, r)];
      if (!v) continue;
      v = std::min(
          {v, get(c + 1, r) + 3, get(c, r + 1) + 3, get(c + 1, r + 1) + 4, get(c - 1, r + 1) + 4});
    }
  }
  return d;
}

// 4-connected components of cells with d >= level; returns their labels
// (1..n) and sizes (index 0 unused).
std::vector<std::int32_t> Components(const Grid& grid, const std::vector<int>& d, int level,
                                     std::vector<std::size_t>* sizes) {
  const int w = grid.width(), h = grid.height();
  std::vector<std::int32_t> label(grid.size(), 0);
  sizes->assign(1, 0);
  std::vector<std::size_t> stack;
  for (std::size_t seed = 0; seed < grid.size(); ++seed) {
    if (d[seed] < level || label[seed]) continue;
    const std::int32_t id = static_cast<std::int32_t>(sizes->size());
    sizes->push_back(0);
    label[seed] = id;
    stack.assign(1, seed);
    while (!stack.empty()) {
      const std::size_t i = stack.back();
      stack.pop_back();
      ++(*sizes)[id];
      const int c = static_cast<int>(i % w), r = static_cast<int>(i / w);
      const int dc[4] = {1, -1, 0, 0}, dr[4] = {0, 0, 1, -1};
      for (int k = 0; k < 4; ++k) {
        const int nc = c + dc[k], nr = r + dr[k];
        if (nc < 0 || nr < 0 || nc >= w || nr >= h) continue;
        const std::size_t j = grid.Index(nc, nr);
        if (d[j] >= level && !label[j]) {
          label[j] = id;
          stack.push_back(j);
        }
      }
    }
  }
  return label;
}

}  // namespace

std::vector<std::int32_t> DistanceBaseline(const Grid& grid, double min_area_m2,
                                           double max_area_m2) {
  const std::vector<int> d = Distances(grid);
  const double cell_area = grid.meta.resolution * grid.meta.resolution;
  int top = 0;
  for (const int v : d) top = std::max(top, v);
  int best_level = 0, best_count = -1;
  std::vector<std::size_t> sizes;
  for (int level = 3; level <= top; level += 3) {  // every cell of distance
    Components(grid, d, level, &sizes);
    int count = 0;
    for (std::size_t k = 1; k < sizes.size(); ++k) {
      const double area = sizes[k] * cell_area;
      count += area >= min_area_m2 && area <= max_area_m2;
    }
    if (count > best_count) {
      best_count = count;
      best_level = level;
    }
  }
  std::vector<std::int32_t> room(grid.size(), 0);
  if (best_level == 0) return room;
  const std::vector<std::int32_t> label = Components(grid, d, best_level, &sizes);
  std::vector<std::int32_t> id_of(sizes.size(), 0);
  std::int32_t rooms = 0;
  std::deque<std::size_t> front;
  for (std::size_t i = 0; i < grid.size(); ++i) {
    const std::int32_t k = label[i];
    if (!k) continue;
    const double area = sizes[k] * cell_area;
    if (area < min_area_m2 || area > max_area_m2) continue;
    if (!id_of[k]) id_of[k] = ++rooms;
    room[i] = id_of[k];
    front.push_back(i);
  }
  // Wavefront over the free cells.
  const int w = grid.width(), h = grid.height();
  while (!front.empty()) {
    const std::size_t i = front.front();
    front.pop_front();
    const int c = static_cast<int>(i % w), r = static_cast<int>(i / w);
    const int dc[4] = {1, -1, 0, 0}, dr[4] = {0, 0, 1, -1};
    for (int k = 0; k < 4; ++k) {
      const int nc = c + dc[k], nr = r + dr[k];
      if (nc < 0 || nr < 0 || nc >= w || nr >= h) continue;
      const std::size_t j = grid.Index(nc, nr);
      if (d[j] && !room[j]) {
        room[j] = room[i];
        front.push_back(j);
      }
    }
  }
  return room;
}

}  // namespace linemap::bench_rooms
