// Decoding of 2.x files (spec/format.md sections 3-7): the layers without
// the raster, the whole grid, or a window of it.
#ifndef LINEMAP_CODEC_LMAP_DECODER_V2_H_
#define LINEMAP_CODEC_LMAP_DECODER_V2_H_

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "codec/layers/layer_hints.h"
#include "codec/layers/layer_sections.h"
#include "codec/lmap/chunk_coding.h"
#include "format/container.h"
#include "linemap/codec.h"

namespace linemap {

// Everything but the cells, and the CELL body when asked for.
struct V2File {
  HeaderFields header;
  std::vector<WallPolyline> walls;
  // LAYR's: the index of each of `walls` among all the file's walls
  // (DecodedLayers::wall_indices); empty for WALL's, read whole.
  std::vector<std::uint64_t> wall_indices;
  std::vector<RoomOutline> rooms;
  std::vector<FurnitureObject> furniture;
  std::vector<std::pair<std::string, std::string>> metadata;
  std::vector<LmapChunkInfo> chunks;
  bool has_cells = false;
  bool cells_in_blocks = false;          // the cells are BLKS, not CELL
  std::vector<std::uint8_t> cell_body;   // only with read_cells
  bool has_layer_sections = false;       // the layers are LAYR's
  std::vector<std::uint8_t> layer_body;  // LAYR's, until read
  LayerSectionTable layer_table;         // LAYR's, read with the chunk
};

// Windows of a file's cells (CELL or BLKS; all unknown without either).
// The layers' index is built once, for all the windows of a map decoded
// band by band.
class V2CellDecoder {
 public:
  explicit V2CellDecoder(const V2File& file);
  // The tile side of the cells' chunk (1 without cells).
  StatusOr<int> TileSize() const { return TileSizeOf(file_); }
  // The same without a decoder, whose layers' index (its buckets over every
  // wall segment and outline) the tile side does not need.
  static StatusOr<int> TileSizeOf(const V2File& file);
  // The cells of `window` (inside the map, non-empty) into `out`, a
  // (x1 - x0) x (y1 - y0) array, row-major from y0; errors name the chunk,
  // and leave the cells of `out` unspecified.
  Status Decode(CellRect window, int threads, Cell* out) const;

 private:
  std::string ChunkName() const;

  const V2File& file_;
  LayerIndex index_;
};

// `expand_chains` false leaves the rooms' and objects' chains empty (their
// polygons are read): enough to draw the tiles' hints, and on a map with
// tens of thousands of rooms some hundred MB less. With `window` (and
// read_cells), the layers of a LAYR chunk are read only where they can
// draw into the tiles that meet the window (sections, spec 5.6); 2.0 layer
// chunks are read whole. With `defer_sections`, LAYR is only checked for
// its place and kept in `layer_body` for the caller to read part by part.
StatusOr<V2File> ReadV2File(const ContainerView& view, const DecodeLimits& limits, bool read_cells,
                            bool expand_chains = true, const CellRect* window = nullptr,
                            bool defer_sections = false);

// Reading a deferred LAYR (ReadV2File's `defer_sections`) part by part, so
// that a decode holds the layers of one band of rows at a time (on the
// 282-Mcell map a quarter of them):
// the rows of such a band: LAYR's section side, or a sixteenth of the map if
// more (a section's items may reach any band, so more bands could multiply
// the work), rounded up to whole tiles of the cells' chunk, so that bands
// start on tile rows and no tile is decoded twice;
StatusOr<int> LayerBandRows(const V2File& file);
// the layers of the sections that draw into the tiles meeting `rect`, in
// place of those `file` held (nothing to do without LAYR).
Status ReadLayersReaching(const DecodeLimits& limits, const CellRect& rect, V2File* file);

// The layers of the LAYR sections whose box meets `rect` (chains
// expanded), in place of those `file` held: what a reader of the items near
// a window needs, with no tiles involved (nothing to do without LAYR; the
// layers of older files were read whole by ReadV2File).
Status ReadLayersMeeting(const DecodeLimits& limits, const CellRect& rect, V2File* file);

// For a file with LAYR and no CELL or BLKS: reads every section (which is
// what ReadLayersReaching reads for any window when there are no tiles)
// and keeps none of their items. Such a file decodes to all unknown cells,
// but its layers must be valid all the same (spec 7.1). The items of the
// whole map are held meanwhile: the reference encoder never writes LAYR
// without CELL.
Status CheckLayersWithoutCells(const DecodeLimits& limits, V2File* file);

// The whole file into `out` (grid, layers, metadata, chunk list).
Status DecodeV2Contents(const ContainerView& view, const DecodeLimits& limits, LmapContents* out);

// The cells of `window` (already checked to lie inside the map).
StatusOr<Grid> DecodeV2Region(const ContainerView& view, const CellWindow& window,
                              const DecodeLimits& limits);

// Invalid argument unless `window` is non-empty and inside a width x height
// map; the message names both.
Status CheckWindow(const CellWindow& window, int width, int height);

// The grid of a window's cells with the window's origin in the map frame.
Grid WindowGrid(const MapMetadata& meta, const CellWindow& window);

}  // namespace linemap

#endif  // LINEMAP_CODEC_LMAP_DECODER_V2_H_
