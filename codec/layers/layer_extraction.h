// The encoder's side of the vector layers: walls from the line extractor
// joined into polylines, rooms and furniture from the segmentation.
#ifndef LINEMAP_CODEC_LAYERS_LAYER_EXTRACTION_H_
#define LINEMAP_CODEC_LAYERS_LAYER_EXTRACTION_H_

#include <string>
#include <utility>
#include <vector>

#include "linemap/codec.h"
#include "linemap/lines.h"
#include "linemap/vector_layers.h"

namespace linemap {

struct VectorLayers {
  std::vector<WallPolyline> walls;
  std::vector<RoomOutline> rooms;
  std::vector<FurnitureObject> furniture;
};

// Maps wider or taller than this are given their layers block by block
// (cells): the extractor and the segmentation need tens of bytes per cell,
// a 20,768 x 13,612 map at once 6.8 GB. On that map blocks of 4096 cells
// peaked at 739 MB (2.6 bytes per cell) and 15.6 s of CPU; blocks of 2048 at
// 545 MB (1.9) and 13.4 s, the smaller blocks' work staying in cache, for
// 644 more rooms cut at block borders (of 20,811) and a 0.9 % larger file.
inline constexpr int kLayerBlockCells = 2048;

// Blocks whose layers are extracted at once. Each holds some 55 MB while
// it is (a 2048 x 2048 block at about 13 bytes a cell), so that with one
// per core a 12-core machine would hold 660 MB: two keep the peak of the
// 282-Mcell office map's exact save under 0.9 bytes per cell on any
// machine, the tiles still being coded on every core.
inline constexpr int kMaxBlocksAtOnce = 2;

// Walls, rooms and furniture of `grid`; the line extraction and the
// segmentation run on two threads unless options.max_threads is 1. On maps
// larger than a block the layers are extracted block by block,
// kMaxBlocksAtOnce blocks at a time (each block's walls and rooms in
// turn), and end at the block borders (a room across a border is two
// rooms); the result does not depend on the threads. Without
// `with_chains`, the rooms' chains of a map larger than a block are left
// empty (ChainOfPolygon makes one from the polygon): the encoder needs only
// the polygons, and on the 282-Mcell office map the 20,000 rooms' chains held
// through the later blocks' extraction were some 100 MB of its peak.
StatusOr<VectorLayers> ExtractVectorLayers(const Grid& grid, const EncodeOptions& options,
                                           bool with_chains = true);

// One block of a map larger than a block, as ExtractVectorLayers extracts
// it: `block` holds the map's cells from (x0, y0) (at most kLayerBlockCells
// a side, metadata included). The items come back in map cells, walls
// without repeated points, room ids the block's own, on the
// calling thread unless options.max_threads allows the walls a thread of
// their own. Every item lies inside the block (an internal error
// otherwise): the cells of a map coded a band of rows at a time are coded
// against the hints of the bands' items alone (lmap/row_encoder.h).
StatusOr<VectorLayers> ExtractBlockLayers(const Grid& block, int x0, int y0,
                                          const EncodeOptions& options, bool with_chains);

// Appends a block's items to `all`, its room ids (and its objects' room
// ids) moved past the last room id there, so that ids stay unique.
void AppendBlockLayers(VectorLayers block, VectorLayers* all);

// The extractor's lines for the grid: the pixel steps of slanted walls at a
// tight distance budget (EncodeOptions::straight_walls false, the default),
// or StraightWalls() (one segment per straight wall).
StatusOr<std::vector<LineSegment>> ExtractWallLines(const Grid& grid, const EncodeOptions& options);

// Quantises an extracted line to the lattice: endpoints rounded to the
// nearest cell centre and clamped into the map.
LatticeSegment ToLattice(const LineSegment& line, int width, int height);

// Segments that share an end joined into polylines (each segment used once;
// at a junction of three or more the first unused segment continues the
// polyline), canonical (CanonicalizeWalls).
std::vector<WallPolyline> JoinSegments(const std::vector<LatticeSegment>& segments);

// The `meta` entries of the options (creator, time, frame_id, robot_pose).
std::vector<std::pair<std::string, std::string>> MetadataOf(const EncodeOptions& options);

}  // namespace linemap

#endif  // LINEMAP_CODEC_LAYERS_LAYER_EXTRACTION_H_
