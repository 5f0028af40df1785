// A version 2.x file from its parts (v2_file.h).
#include "codec/lmap/v2_file.h"

#include <string>
#include <string_view>

#include "codec/layers/layer_sections.h"
#include "codec/lmap/chunk_coding.h"
#include "format/container.h"

namespace linemap {

std::vector<std::uint8_t> WriteV2(const MapFrame& frame, const EncodeOptions& options,
                                  const VectorLayers& layers, int section_side, bool exact,
                                  const char* cells_type,
                                  const std::vector<std::uint8_t>& cells_body) {
  const bool blocks = std::string_view(cells_type) == kBlockChunk;
  const bool has_layers =
      !layers.walls.empty() || !layers.rooms.empty() || !layers.furniture.empty();
  const int minor = options.compact || blocks ? 3 : has_layers ? 2 : 0;
  ContainerWriter writer(kFormatMajor, static_cast<std::uint8_t>(minor));
  // Cells that are exactly a map simplified before (a file saved within a
  // tolerance, saved again) are not the robot's map either.
  const int simplified = exact ? options.simplified_within_cells : options.tolerance_cells;
  writer.AddChunk(kHeaderChunk, WriteHeader(HeaderFields{frame.width, frame.height, frame.meta,
                                                         /*lossless=*/simplified == 0}));
  auto metadata = MetadataOf(options);
  // A reader learns what a file promises from the file itself: the guarantees
  // of a map simplified within T cells (linemap/tolerance.h) depend on T.
  if (simplified > 0) {
    metadata.emplace_back(kToleranceMetadataKey, std::to_string(simplified));
  }
  if (!metadata.empty()) {
    writer.AddChunk(kMetadataChunk, WrapPayload(WriteMetadata(metadata), true));
  }
  // Range-coded bodies gain nothing from deflate: stored raw.
  if (has_layers) {
    writer.AddChunk(kLayerChunk,
                    WrapPayload(EncodeLayerSections(layers.walls, layers.rooms, layers.furniture,
                                                    frame.width, frame.height, section_side),
                                false));
  }
  writer.AddChunk(cells_type, WrapPayload(cells_body, false));
  return writer.Finish();
}

Status CheckLayersWithinDefaultLimits(const VectorLayers& layers) {
  LayerCounts counts;
  counts.Add(layers);
  return CheckLayerCountsWithinDefaultLimits(counts);
}

std::uint64_t WallSegmentCount(const std::vector<WallPolyline>& walls) {
  std::uint64_t segments = 0;
  for (const WallPolyline& wall : walls) segments += wall.points.size() - 1;
  return segments;
}

void LayerCounts::Add(const VectorLayers& layers) {
  walls += layers.walls.size();
  segments += WallSegmentCount(layers.walls);
  rooms += layers.rooms.size();
  objects += layers.furniture.size();
  for (const RoomOutline& room : layers.rooms) {
    room_vertices += room.polygon.size();
    room_chain_cells += room.chain.size();
  }
  for (const FurnitureObject& object : layers.furniture) {
    object_vertices += object.polygon.size();
    object_chain_cells += object.outline.size();
  }
}

// Over what decoders read by default: resource exhausted, but over no limit
// the caller set (Limit::kNone), since only saving without the layers
// lifts it.
Status DefaultLimitError(std::string message) {
  return Status(StatusCode::kResourceExhausted, std::move(message));
}

Status CheckLayerCountsWithinDefaultLimits(const LayerCounts& counts) {
  const DecodeLimits defaults;
  const std::string advice =
      ", more than decoders read by default: save the cells only (vector layers off, "
      "--raster-only)";
  if (counts.walls > defaults.max_segments || counts.segments > defaults.max_segments) {
    return DefaultLimitError("the walls have " + std::to_string(counts.segments) +
                             " segments (limit " + std::to_string(defaults.max_segments) + ")" +
                             advice);
  }
  if (counts.rooms > defaults.max_objects || counts.objects > defaults.max_objects) {
    return DefaultLimitError("the layers have " + std::to_string(counts.rooms) + " rooms and " +
                             std::to_string(counts.objects) + " furniture objects (limit " +
                             std::to_string(defaults.max_objects) + " each)" + advice);
  }
  const std::uint64_t chains = defaults.max_chain_length;
  if (counts.room_vertices > chains || counts.room_chain_cells > chains ||
      counts.object_vertices > chains || counts.object_chain_cells > chains) {
    return DefaultLimitError("the room and furniture outlines have " +
                             std::to_string(counts.room_chain_cells + counts.object_chain_cells) +
                             " chain cells (limit " + std::to_string(chains) +
                             " for the rooms and for the objects)" + advice);
  }
  return Status::Ok();
}

}  // namespace linemap
