// Decoding of 2.x files (spec/format.md sections 3-7): the layers without
// the raster, the whole grid, or a window of it.
#ifndef LINEMAP_CODEC_CODEC_DECODER_V2_H_
#define LINEMAP_CODEC_CODEC_DECODER_V2_H_

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "codec/codec/chunk_coding.h"
#include "format/container.h"
#include "linemap/codec.h"

namespace linemap {

// Everything but the cells, and the CELL body when asked for.
struct V2File {
  HeaderFields header;
  std::vector<WallPolyline> walls;
  std::vector<RoomOutline> rooms;
  std::vector<FurnitureObject> furniture;
  std::vector<std::pair<std::string, std::string>> metadata;
  std::vector<LmapChunkInfo> chunks;
  bool has_cells = false;
  std::vector<std::uint8_t> cell_body;  // only with read_cells
};

// `expand_chains` false leaves the rooms' and objects' chains empty (their
// polygons are read): enough to draw the tiles' hints, and on a map with
// tens of thousands of rooms some hundred MB less.
StatusOr<V2File> ReadV2File(const ContainerView& view, const DecodeLimits& limits, bool read_cells,
                            bool expand_chains = true);

// The whole file into `out` (grid, layers, metadata, chunk list).
Status DecodeV2Contents(const ContainerView& view, const DecodeLimits& limits, LmapContents* out);

// The cells of `window` (already checked to lie inside the map).
StatusOr<Grid> DecodeV2Region(const ContainerView& view, const CellWindow& window,
                              const DecodeLimits& limits);

// The grid of a window's cells with the window's origin in the map frame.
Grid WindowGrid(const MapMetadata& meta, const CellWindow& window);

}  // namespace linemap

#endif  // LINEMAP_CODEC_CODEC_DECODER_V2_H_
