#include "tests/testing/reference_components.h"

#include <map>
#include <set>
#include <utility>

namespace linemap::testing {

FreeComponents FreeComponentsByFloodFill(const Grid& grid) {
  FreeComponents out;
  out.id.assign(grid.size(), 0);
  out.sizes = {0};
  for (int r = 0; r < grid.height(); ++r) {
    for (int c = 0; c < grid.width(); ++c) {
      if (grid.at(c, r) != Cell::kFree || out.id[grid.Index(c, r)]) continue;
      const int k = static_cast<int>(out.sizes.size());
      out.sizes.push_back(0);
      std::vector<CellIndex> stack{{c, r}};
      out.id[grid.Index(c, r)] = k;
      while (!stack.empty()) {
        const CellIndex cur = stack.back();
        stack.pop_back();
        ++out.sizes[k];
        const int dc[4] = {1, -1, 0, 0}, dr[4] = {0, 0, 1, -1};
        for (int d = 0; d < 4; ++d) {
          const int nc = cur.col + dc[d], nr = cur.row + dr[d];
          if (!grid.Contains(nc, nr) || grid.at(nc, nr) != Cell::kFree) continue;
          if (out.id[grid.Index(nc, nr)]) continue;
          out.id[grid.Index(nc, nr)] = k;
          stack.push_back({nc, nr});
        }
      }
    }
  }
  return out;
}

int PlansOnOneGridOnly(const Grid& a, const Grid& b) {
  if (a.width() != b.width() || a.height() != b.height()) return -1;
  const FreeComponents ca = FreeComponentsByFloodFill(a), cb = FreeComponentsByFloodFill(b);
  std::set<std::pair<int, int>> meet;  // (component in a, component in b)
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (ca.id[i] && cb.id[i]) meet.insert({ca.id[i], cb.id[i]});
  }
  std::map<int, int> per_a, per_b;
  for (const auto& [x, y] : meet) {
    ++per_a[x];
    ++per_b[y];
  }
  int extra = 0;
  for (const auto& [x, n] : per_a) extra += n - 1;
  for (const auto& [y, n] : per_b) extra += n - 1;
  return extra;
}

}  // namespace linemap::testing
