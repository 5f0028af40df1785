#include "tools/linemap/layer_fidelity.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "linemap/lines.h"
#include "linemap/segmentation.h"

namespace linemap::cli {

namespace {

// 1 for every cell inside the fill of some furniture outline. Each outline
// is filled in its own bounding box, so many small objects on a big map
// cost their own area, not the map's each.
std::vector<std::uint8_t> FurnitureFill(const LmapVectors& file, int width, int height) {
  std::vector<std::uint8_t> fill(static_cast<std::size_t>(width) * height, 0);
  for (const FurnitureObject& object : file.furniture) {
    if (object.outline.empty()) continue;
    int c0 = object.outline[0].col, c1 = c0, r0 = object.outline[0].row, r1 = r0;
    for (const CellIndex& c : object.outline) {
      c0 = std::min(c0, c.col);
      c1 = std::max(c1, c.col);
      r0 = std::min(r0, c.row);
      r1 = std::max(r1, c.row);
    }
    std::vector<CellIndex> local;
    local.reserve(object.outline.size());
    for (const CellIndex& c : object.outline) local.push_back({c.col - c0, c.row - r0});
    const BinaryMask mask = FillChainPolygon(local, c1 - c0 + 1, r1 - r0 + 1);
    for (int r = 0; r < mask.height; ++r) {
      for (int c = 0; c < mask.width; ++c) {
        const int col = c + c0, row = r + r0;
        if (mask.bits[mask.Index(c, r)] && col >= 0 && row >= 0 && col < width && row < height) {
          fill[static_cast<std::size_t>(row) * width + col] = 1;
        }
      }
    }
  }
  return fill;
}

}  // namespace

LayerFidelity MeasureLayerFidelity(const Grid& original, const LmapVectors& file) {
  LayerFidelity result;
  // Without a robot position every free cell seeds the flood, so the edge
  // map is exactly the occupied cells with a free 4-neighbour.
  const EdgeMap edges = ComputeEdgeMap(original);
  result.edge_cells = edges.edge_count;
  std::vector<LineSegment> segments;
  for (const WallPolyline& wall : file.walls) {
    for (std::size_t i = 1; i < wall.points.size(); ++i) {
      const CellIndex a = wall.points[i - 1], b = wall.points[i];
      segments.push_back({static_cast<double>(a.col), static_cast<double>(a.row),
                          static_cast<double>(b.col), static_cast<double>(b.row)});
    }
  }
  // The edge cells no furniture fill covers: their distance to the walls
  // decides whether they are covered.
  const std::vector<std::uint8_t> fill = FurnitureFill(file, edges.width, edges.height);
  EdgeMap outside = edges;
  for (std::size_t i = 0; i < outside.is_edge.size(); ++i) {
    if (outside.is_edge[i] && fill[i]) {
      outside.is_edge[i] = 0;
      --outside.edge_count;
      ++result.in_furniture;
    }
  }
  result.covered = result.in_furniture;
  if (segments.empty()) return result;
  const LineFidelity all = MeasureLineFidelity(edges, segments);
  result.displ_ave_cells = all.displ_ave_cells;
  result.displ_max_cells = all.displ_max_cells;
  result.within_1_of_wall = static_cast<std::size_t>(
      std::llround(all.share_within_1 * static_cast<double>(all.edge_cells)));
  const LineFidelity rest = MeasureLineFidelity(outside, segments);
  result.covered += static_cast<std::size_t>(
      std::llround(rest.share_within_1 * static_cast<double>(rest.edge_cells)));
  return result;
}

}  // namespace linemap::cli
