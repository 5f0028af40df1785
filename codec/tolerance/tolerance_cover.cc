// FreeCover(): which lost free cells to give back for the distance
// guarantee of a tolerance (linemap/tolerance.h 2).
#include <algorithm>
#include <cstdint>
#include <vector>

#include "codec/tolerance/tolerance_internal.h"

namespace linemap::tolerance_internal {

// Greedy, in raster order: the score of a candidate is twice the lost cells
// it serves plus one when it touches free space, so touching only breaks
// ties. (Requiring it cost 1-2 % on tsc and avz: a touching cell often
// serves fewer, and the cells the topology check gives back for a lone
// one are fewer than those saved.)
std::vector<std::size_t> FreeCover(const Grid& original, const Grid& decoded,
                                   const std::vector<std::size_t>& lost, int t) {
  const int w = original.width(), h = original.height();
  std::vector<std::uint8_t> is_lost(original.size(), 0), served(original.size(), 0);
  std::vector<std::uint8_t> free_now(original.size(), 0);
  for (std::size_t i = 0; i < original.size(); ++i) free_now[i] = decoded.cells()[i] == Cell::kFree;
  for (const std::size_t i : lost) is_lost[i] = 1;
  auto unserved_near = [&](int c, int r) {
    int count = 0;
    for (int y = std::max(0, r - t); y <= std::min(h - 1, r + t); ++y) {
      for (int x = std::max(0, c - t); x <= std::min(w - 1, c + t); ++x) {
        const std::size_t j = original.Index(x, y);
        count += is_lost[j] && !served[j];
      }
    }
    return count;
  };
  auto touches_free = [&](int c, int r) {
    return (c > 0 && free_now[original.Index(c - 1, r)]) ||
           (c + 1 < w && free_now[original.Index(c + 1, r)]) ||
           (r > 0 && free_now[original.Index(c, r - 1)]) ||
           (r + 1 < h && free_now[original.Index(c, r + 1)]);
  };
  std::vector<std::size_t> out;
  for (const std::size_t i : lost) {
    if (served[i]) continue;
    const int c = static_cast<int>(i % w), r = static_cast<int>(i / w);
    std::size_t best = i;
    int best_score = -1;
    for (int y = std::max(0, r - t); y <= std::min(h - 1, r + t); ++y) {
      for (int x = std::max(0, c - t); x <= std::min(w - 1, c + t); ++x) {
        const std::size_t j = original.Index(x, y);
        if (original.cells()[j] != Cell::kFree || free_now[j]) continue;
        const int score = 2 * unserved_near(x, y) + (touches_free(x, y) ? 1 : 0);
        if (score > best_score) {
          best_score = score;
          best = j;
        }
      }
    }
    out.push_back(best);
    free_now[best] = 1;
    const int bc = static_cast<int>(best % w), br = static_cast<int>(best / w);
    for (int y = std::max(0, br - t); y <= std::min(h - 1, br + t); ++y) {
      for (int x = std::max(0, bc - t); x <= std::min(w - 1, bc + t); ++x) {
        served[original.Index(x, y)] = 1;
      }
    }
  }
  return out;
}

}  // namespace linemap::tolerance_internal
