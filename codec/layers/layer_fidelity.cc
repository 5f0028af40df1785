// MeasureLayerFidelity(): how well a file's walls and furniture hold the
// map's edge cells, the RM-Line paper's way. An evaluation of the layers
// against a map, not a step of decoding: it needs the edge map and the
// segment index of the line extractor, which a decoder does not link.
#include <algorithm>
#include <string>
#include <vector>

#include "codec/layers/raster.h"
#include "codec/lines/segment_index.h"
#include "linemap/lines.h"
#include "linemap/lmap_vectors.h"

namespace linemap {

StatusOr<LayerFidelity> MeasureLayerFidelity(const Grid& original, const LmapVectors& vectors) {
  if (original.width() != vectors.width || original.height() != vectors.height) {
    return InvalidArgumentError("the map is " + std::to_string(original.width()) + " x " +
                                std::to_string(original.height()) + " cells, the file " +
                                std::to_string(vectors.width) + " x " +
                                std::to_string(vectors.height));
  }
  std::vector<LineSegment> segments;
  for (const WallPolyline& wall : vectors.walls) {
    for (std::size_t i = 1; i < wall.points.size(); ++i) {
      const CellIndex a = wall.points[i - 1], b = wall.points[i];
      segments.push_back({static_cast<double>(a.col), static_cast<double>(a.row),
                          static_cast<double>(b.col), static_cast<double>(b.row)});
    }
  }
  std::vector<std::uint8_t> in_furniture(original.size(), 0);
  for (const FurnitureObject& object : vectors.furniture) {
    FillChain(object.outline, [&](int c, int r) { in_furniture[original.Index(c, r)] = 1; });
  }
  const EdgeMap edges = ComputeEdgeMap(original);
  lines_internal::SegmentIndex index(&segments, original.width(), original.height());
  LayerFidelity f;
  double sum = 0, max = 0;
  for (int r = 0; r < original.height(); ++r) {
    for (int c = 0; c < original.width(); ++c) {
      const std::size_t i = original.Index(c, r);
      if (!edges.is_edge[i]) continue;
      ++f.edge_cells;
      const double d = segments.empty() ? 0.0 : index.NearestDistance(c, r);
      const bool near = !segments.empty() && d <= 1.0;
      sum += d;
      max = std::max(max, d);
      f.within_1_of_wall += near;
      f.in_furniture += in_furniture[i];
      f.covered += near || in_furniture[i];
    }
  }
  if (!segments.empty()) {
    f.displ_ave_cells = f.edge_cells > 0 ? sum / static_cast<double>(f.edge_cells) : 0.0;
    f.displ_max_cells = max;
  }
  return f;
}

}  // namespace linemap
