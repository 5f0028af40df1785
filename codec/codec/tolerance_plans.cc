// Plans compared on two grids: breadth-first 4-connected paths over free
// cells (what a planner that treats unknown as an obstacle can use) between
// sampled cells free in both grids.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "codec/codec/tolerance.h"
#include "codec/codec/tolerance_internal.h"

namespace linemap::tolerance_internal {
namespace {

// Sampled cells: kSources starts, each paired with every other sampled cell.
// 6 sources x 23 goals = 132 pairs for 12 breadth-first searches per check.
constexpr int kSampledCells = 24;
constexpr int kSources = 6;
constexpr int kDrawsPerCell = 64;

// Steps from `source` to every cell over free cells; -1 where unreachable.
std::vector<std::int32_t> FreeSteps(const Grid& grid, std::size_t source) {
  std::vector<std::int32_t> steps(grid.size(), -1);
  std::vector<std::size_t> queue;
  queue.reserve(1024);
  steps[source] = 0;
  queue.push_back(source);
  const std::size_t w = static_cast<std::size_t>(grid.width());
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const std::size_t i = queue[head];
    const int c = static_cast<int>(i % w);
    const int r = static_cast<int>(i / w);
    auto visit = [&](int nc, int nr) {
      if (!grid.Contains(nc, nr)) return;
      const std::size_t n = grid.Index(nc, nr);
      if (steps[n] >= 0 || grid.cells()[n] != Cell::kFree) return;
      steps[n] = steps[i] + 1;
      queue.push_back(n);
    };
    visit(c + 1, r);
    visit(c - 1, r);
    visit(c, r + 1);
    visit(c, r - 1);
  }
  return steps;
}

// The cells of one shortest path from the search's source to `goal`.
void AppendPath(const Grid& grid, const std::vector<std::int32_t>& steps, std::size_t goal,
                std::vector<std::size_t>* out) {
  const std::size_t w = static_cast<std::size_t>(grid.width());
  std::size_t i = goal;
  out->push_back(i);
  while (steps[i] > 0) {
    const int c = static_cast<int>(i % w);
    const int r = static_cast<int>(i / w);
    const int dc[4] = {1, -1, 0, 0};
    const int dr[4] = {0, 0, 1, -1};
    for (int k = 0; k < 4; ++k) {
      if (!grid.Contains(c + dc[k], r + dr[k])) continue;
      const std::size_t n = grid.Index(c + dc[k], r + dr[k]);
      if (steps[n] == steps[i] - 1) {
        i = n;
        break;
      }
    }
    out->push_back(i);
  }
}

// Cells free in both grids, drawn by a fixed linear congruential sequence.
std::vector<std::size_t> SampleCells(const Grid& a, const Grid& b) {
  std::vector<std::size_t> cells;
  if (a.empty()) return cells;
  std::uint64_t state = 0x9E3779B97F4A7C15ull;
  for (int draw = 0; draw < kSampledCells * kDrawsPerCell && cells.size() < kSampledCells; ++draw) {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    const std::size_t i = static_cast<std::size_t>((state >> 17) % a.size());
    if (a.cells()[i] == Cell::kFree && b.cells()[i] == Cell::kFree) cells.push_back(i);
  }
  return cells;
}

}  // namespace

PlanFaults ComparePlans(const Grid& original, const Grid& decoded, bool want_paths) {
  PlanFaults out;
  const std::vector<std::size_t> cells = SampleCells(original, decoded);
  const int sources = std::min<int>(kSources, static_cast<int>(cells.size()));
  for (int s = 0; s < sources; ++s) {
    const std::vector<std::int32_t> a = FreeSteps(original, cells[s]);
    const std::vector<std::int32_t> b = FreeSteps(decoded, cells[s]);
    for (std::size_t g = s + 1; g < cells.size(); ++g) {
      ++out.pairs;
      const std::int32_t la = a[cells[g]];
      const std::int32_t lb = b[cells[g]];
      const bool agree =
          (la < 0) == (lb < 0) && (la < 0 || std::abs(lb - la) <= kPlanLengthTolerance * la);
      if (agree) continue;
      ++out.disagreements;
      if (!want_paths) continue;
      if (la >= 0) AppendPath(original, a, cells[g], &out.paths);
      if (lb >= 0) AppendPath(decoded, b, cells[g], &out.paths);
      // Neither path exists on one side: the start and goal themselves.
      out.paths.push_back(cells[s]);
      out.paths.push_back(cells[g]);
    }
  }
  return out;
}

}  // namespace linemap::tolerance_internal
