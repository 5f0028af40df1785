// The edge cells that linemap's extractor (linemap_extractor.cc) works on:
// their coordinates and their 8 neighbours, shared by all its steps.
#ifndef LINEMAP_CODEC_LINES_EDGE_CELLS_H_
#define LINEMAP_CODEC_LINES_EDGE_CELLS_H_

#include <cstdint>

namespace linemap::lines_internal {

// 4-neighbours first, then diagonals.
inline constexpr int kDcol[8] = {1, 0, -1, 0, 1, -1, -1, 1};
inline constexpr int kDrow[8] = {0, 1, 0, -1, 1, 1, -1, -1};

struct CellXY {
  int col;
  int row;
};

inline CellXY CellOfIndex(std::uint32_t index, int width) {
  return {static_cast<int>(index % static_cast<std::uint32_t>(width)),
          static_cast<int>(index / static_cast<std::uint32_t>(width))};
}

}  // namespace linemap::lines_internal

#endif  // LINEMAP_CODEC_LINES_EDGE_CELLS_H_
