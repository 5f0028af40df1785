// The .lmap encoder (spec/format.md section 9, "Encoding (informative)").
//
// A 2.0 file is written in the order the decoder reads it: LMHD, meta, the
// vector layers (WALL, ROOM, FURN: what a viewer reads without the
// raster), then CELL, the exact cells in tiles, each coded against the
// hints the layers draw into it (a cell on a wall is cheap to confirm as
// occupied, one inside a room as free).
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "codec/codec/cell_tiles.h"
#include "codec/codec/chunk_coding.h"
#include "codec/codec/encoder_v1.h"
#include "codec/codec/layer_coding.h"
#include "codec/codec/layer_extraction.h"
#include "codec/codec/layer_hints.h"
#include "codec/codec/tolerance.h"
#include "format/container.h"
#include "format/file_io.h"
#include "linemap/codec.h"

namespace linemap {
namespace {

Status CheckEncodeInput(const Grid& grid, const EncodeOptions& options) {
  const int w = grid.width();
  const int h = grid.height();
  if (w < 0 || h < 0 || grid.size() != static_cast<std::size_t>(w) * static_cast<std::size_t>(h)) {
    return InvalidArgumentError("grid dimensions do not match its cells");
  }
  if (!(grid.meta.resolution > 0) || !std::isfinite(grid.meta.resolution)) {
    return InvalidArgumentError("grid resolution must be a positive number");
  }
  if (options.max_threads < 0) return InvalidArgumentError("max_threads must not be negative");
  if (options.min_segment_cells < 1) {
    return InvalidArgumentError("min_segment_cells must be at least 1");
  }
  if (options.tolerance_cells < 0 || options.tolerance_cells > kMaxToleranceCells) {
    return InvalidArgumentError("tolerance " + std::to_string(options.tolerance_cells) +
                                " cells: must be 0 (exact) to " +
                                std::to_string(kMaxToleranceCells));
  }
  if (options.tile_size_cells < kMinTileSize || options.tile_size_cells > kMaxTileSize) {
    return InvalidArgumentError("tile size must be 16..65536 cells");
  }
  return Status::Ok();
}

// `exact`: `grid` is the caller's map itself (the header's lossless flag).
StatusOr<std::vector<std::uint8_t>> EncodeV2(const Grid& grid, const EncodeOptions& options,
                                             bool exact) {
  VectorLayers layers;
  if (options.vector_layers) {
    LINEMAP_ASSIGN_OR_RETURN(layers, ExtractVectorLayers(grid, options));
  }
  ContainerWriter writer;
  writer.AddChunk(kHeaderChunk,
                  WriteHeader(HeaderFields{grid.width(), grid.height(), grid.meta, exact}));
  const auto metadata = MetadataOf(options);
  if (!metadata.empty()) {
    writer.AddChunk(kMetadataChunk, WrapPayload(WriteMetadata(metadata), true));
  }
  // Range-coded bodies gain nothing from deflate: stored raw.
  if (!layers.walls.empty())
    writer.AddChunk(kWallChunk, WrapPayload(EncodeWalls(layers.walls), false));
  if (!layers.rooms.empty())
    writer.AddChunk(kRoomChunk, WrapPayload(EncodeRooms(layers.rooms), false));
  if (!layers.furniture.empty()) {
    writer.AddChunk(kFurnitureChunk, WrapPayload(EncodeFurniture(layers.furniture), false));
  }
  const LayerIndex index(layers.walls, layers.rooms, layers.furniture);
  writer.AddChunk(kCellChunk, WrapPayload(EncodeCellChunk(grid, index, options.tile_size_cells,
                                                          options.max_threads),
                                          false));
  return writer.Finish();
}

}  // namespace

StatusOr<std::vector<std::uint8_t>> EncodeLmap(const Grid& grid, const EncodeOptions& options) {
  LINEMAP_RETURN_IF_ERROR(CheckEncodeInput(grid, options));
  if (options.format_v1) return EncodeLmapV1(grid, options);
  if (options.tolerance_cells == 0) return EncodeV2(grid, options, true);
  // Within a tolerance the file is the exact file of the map simplified
  // within it: every guarantee is checked on that grid, which is exactly
  // what the file decodes to (SimplifyWithinTolerance undoes what fails).
  // Where the simplification saves nothing (a clean plan, or the layers'
  // cost), the exact file is kept: never larger than it.
  LINEMAP_ASSIGN_OR_RETURN(Grid simplified, SimplifyWithinTolerance(grid, options.tolerance_cells));
  LINEMAP_ASSIGN_OR_RETURN(std::vector<std::uint8_t> within,
                           EncodeV2(simplified, options, simplified == grid));
  LINEMAP_ASSIGN_OR_RETURN(std::vector<std::uint8_t> exact, EncodeV2(grid, options, true));
  return within.size() < exact.size() ? within : exact;
}

Status SaveLmap(const std::string& path, const Grid& grid, const EncodeOptions& options) {
  LINEMAP_ASSIGN_OR_RETURN(std::vector<std::uint8_t> bytes, EncodeLmap(grid, options));
  return WriteFileAtomic(
      path, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
}

}  // namespace linemap
