// Fidelity of an .lmap file's vector layers to the map they came from, the
// RM-Line paper's way (Liu & Zhang 2022, Eq. 5): how far the original map's
// edge cells lie from the file's walls.
#ifndef LINEMAP_TOOLS_LINEMAP_LAYER_FIDELITY_H_
#define LINEMAP_TOOLS_LINEMAP_LAYER_FIDELITY_H_

#include <cstddef>
#include <optional>

#include "linemap/grid.h"
#include "linemap/lmap_vectors.h"

namespace linemap::cli {

struct LayerFidelity {
  // Occupied cells of the original with a free 4-neighbour.
  std::size_t edge_cells = 0;
  // Mean and largest Euclidean distance (cells) from an edge cell's centre
  // to the nearest wall segment; nullopt when the file has no walls.
  std::optional<double> displ_ave_cells;
  std::optional<double> displ_max_cells;
  // Edge cells within 1 cell (distance <= 1) of a wall segment.
  std::size_t within_1_of_wall = 0;
  // Edge cells inside the fill of a furniture outline (FillChainPolygon:
  // the chain's cells and the cells whose centres it encloses).
  std::size_t in_furniture = 0;
  // Edge cells within 1 cell of a wall or inside a furniture fill.
  std::size_t covered = 0;
};

// `original` and the file must have the same width and height (cells).
LayerFidelity MeasureLayerFidelity(const Grid& original, const LmapVectors& file);

}  // namespace linemap::cli

#endif  // LINEMAP_TOOLS_LINEMAP_LAYER_FIDELITY_H_
