// What the files of the encoder's layer extraction (layer_extraction.h)
// share: the robot's cell, the edge cells the walls are measured against,
// the steps from the extractor's lines to the file's walls, and the rooms
// and furniture. Encoder-only, as layer_extraction.h is.
#ifndef LINEMAP_CODEC_LAYERS_LAYER_EXTRACTION_INTERNAL_H_
#define LINEMAP_CODEC_LAYERS_LAYER_EXTRACTION_INTERNAL_H_

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "codec/layers/layer_extraction.h"
#include "linemap/codec.h"
#include "linemap/grid.h"
#include "linemap/lines.h"
#include "linemap/status.h"

namespace linemap::layer_extraction_internal {

// Distance (cells) from `p` to the segment from `a` to `b`.
inline double PointSegmentDistance(CellIndex p, CellIndex a, CellIndex b) {
  const double dx = b.col - a.col, dy = b.row - a.row;
  const double px = p.col - a.col, py = p.row - a.row;
  const double len2 = dx * dx + dy * dy;
  const double t = len2 > 0 ? std::clamp((px * dx + py * dy) / len2, 0.0, 1.0) : 0.0;
  // sqrt, not std::hypot: the operands are below 2^31, so nothing
  // overflows, and hypot's care for that made it 3 % of an encode.
  const double ex = px - t * dx, ey = py - t * dy;
  return std::sqrt(ex * ex + ey * ey);
}

// Edge cells this near a segment (cells) count as near it when segments are
// moved or dropped: eval's one cell, and the cells just beyond, whose
// distance to the nearest wall DisPL_ave averages too.
inline constexpr double kNearCells = 1.5;

// The edge cells of the grid (occupied, with a free 4-neighbour): what
// `linemap eval` measures the walls against (MeasureLayerFidelity).
class EdgeCells {
 public:
  explicit EdgeCells(const Grid& grid);

  // The edge cells within kNearCells (Euclidean, to the segment) of the
  // segment with their distances, by cell index. They lie within two cells
  // of the segment's rasterisation. Not const: it marks the cells it lists
  // in the edge bytes while it runs (so one object serves one thread).
  std::vector<std::pair<std::size_t, double>> Near(const LatticeSegment& s);

  // One byte per cell, non-zero exactly at the edge cells (as
  // ComputeEdgeMap's is_edge), except while Near() runs: it marks the cells
  // it lists and restores them before it returns.
  const std::uint8_t* bytes() const { return edge_.get(); }

 private:
  static constexpr std::uint8_t kEdge = 1, kEdgeSeen = 2;
  template <typename Take>
  void ForEachNewNeighbour(std::optional<CellIndex> previous, CellIndex at, Take&& take) const;

  const Grid& grid_;
  // 0, kEdge, or kEdgeSeen for an edge cell already listed by the running
  // Near() (which restores kEdge before it returns).
  std::unique_ptr<std::uint8_t[]> edge_;
};

// The extractor's lines (ExtractWallLines) on the lattice, cut to the runs
// that stay on the walls and straightened where that keeps them as near the
// edge cells (wall_segments.cc).
StatusOr<std::vector<LatticeSegment>> WallSegments(const Grid& grid, const EncodeOptions& options);

// Drops the segments whose near edge cells other kept segments hold about
// as near (wall_segments.cc says how near, and why).
void DropRedundantSegments(EdgeCells* edges, std::vector<LatticeSegment>* segments);

// JoinSegments without the canonical order: a map's blocks are ordered
// once, all together (ExtractVectorLayers), not each on its own first.
std::vector<WallPolyline> JoinSegmentsUnordered(const std::vector<LatticeSegment>& segments);

// Rooms and furniture from SegmentMap(); chains the file cannot store (an
// open or broken chain) are left out rather than failing the save.
Status RoomAndFurnitureLayers(const Grid& grid, const EncodeOptions& options, VectorLayers* layers);

}  // namespace linemap::layer_extraction_internal

#endif  // LINEMAP_CODEC_LAYERS_LAYER_EXTRACTION_INTERNAL_H_
