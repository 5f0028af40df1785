#include "tests/testing/reference_components.h"

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

}  // namespace linemap::testing
