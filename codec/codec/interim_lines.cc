#include "codec/codec/interim_lines.h"

namespace linemap {

std::vector<LatticeSegment> InterimAxisRunSegments(const std::vector<std::uint8_t>& wall, int width,
                                                   int height, int min_run_cells) {
  std::vector<LatticeSegment> segments;
  auto at = [&](int c, int r) { return wall[static_cast<std::size_t>(r) * width + c] != 0; };
  for (int r = 0; r < height; ++r) {
    for (int c = 0; c < width;) {
      if (!at(c, r)) {
        ++c;
        continue;
      }
      int end = c;
      while (end + 1 < width && at(end + 1, r)) ++end;
      if (end - c + 1 >= min_run_cells) segments.push_back({{c, r}, {end, r}});
      c = end + 1;
    }
  }
  for (int c = 0; c < width; ++c) {
    for (int r = 0; r < height;) {
      if (!at(c, r)) {
        ++r;
        continue;
      }
      int end = r;
      while (end + 1 < height && at(c, end + 1)) ++end;
      if (end - r + 1 >= min_run_cells) segments.push_back({{c, r}, {c, end}});
      r = end + 1;
    }
  }
  return segments;
}

}  // namespace linemap
