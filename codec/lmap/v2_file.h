// A version 2.x file from its parts (spec/format.md sections 2-6), as the
// encoders assemble it: the in-memory one (encoder.cc) and the one that
// takes the map a band of rows at a time (row_encoder.h).
#ifndef LINEMAP_CODEC_LMAP_V2_FILE_H_
#define LINEMAP_CODEC_LMAP_V2_FILE_H_

#include <cstdint>
#include <vector>

#include "codec/layers/layer_extraction.h"
#include "linemap/codec.h"
#include "linemap/grid.h"
#include "linemap/status.h"

namespace linemap {

// A map's size and metadata, as the header stores them.
struct MapFrame {
  int width = 0;
  int height = 0;
  MapMetadata meta;
};

// Header, metadata, the vector layers in sections of `section_side` (LAYR:
// what a viewer reads without the raster) and the cells' chunk
// (`cells_type`: CELL or BLKS). `exact`: the cells are the caller's map
// itself (the header's lossless flag). The minor version names the newest
// feature the file may hold (tiles of model 12: 3, in BLKS and in the
// compact mode's CELL; LAYR 2; BLKS 1 before 2.3), so that an older
// decoder's refusal of it says why.
std::vector<std::uint8_t> WriteV2(const MapFrame& frame, const EncodeOptions& options,
                                  const VectorLayers& layers, int section_side, bool exact,
                                  const char* cells_type,
                                  const std::vector<std::uint8_t>& cells_body);

// A file a decoder with the default limits refuses is not written: on a
// huge map of scattered specks the covering walls alone could pass the
// segment limit.
Status CheckLayersWithinDefaultLimits(const VectorLayers& layers);
// What the default limits bound of a file's layers, counted as they are
// found, before the rest of the map is coded.
struct LayerCounts {
  std::uint64_t walls = 0;
  std::uint64_t segments = 0;
  std::uint64_t rooms = 0;
  std::uint64_t objects = 0;
  // Polygon vertices and chain cells, of the rooms and (apart) of the
  // objects: decoders count both against the chain limit.
  std::uint64_t room_vertices = 0, room_chain_cells = 0;
  std::uint64_t object_vertices = 0, object_chain_cells = 0;
  void Add(const VectorLayers& layers);
};
Status CheckLayerCountsWithinDefaultLimits(const LayerCounts& counts);
std::uint64_t WallSegmentCount(const std::vector<WallPolyline>& walls);

}  // namespace linemap

#endif  // LINEMAP_CODEC_LMAP_V2_FILE_H_
