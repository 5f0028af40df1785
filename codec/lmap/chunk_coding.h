// Chunk bodies shared by the encoder and decoder: the payload coder byte,
// the header, metadata, lattice segments and chains (spec/format.md section
// "Chunk payloads").
#ifndef LINEMAP_CODEC_LMAP_CHUNK_CODING_H_
#define LINEMAP_CODEC_LMAP_CHUNK_CODING_H_

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "format/byte_io.h"
#include "linemap/codec.h"

namespace linemap {

// Chunk types (the order a file must keep is in the decoders).
inline constexpr char kHeaderChunk[] = "LMHD";
inline constexpr char kRoomChunk[] = "ROOM";
inline constexpr char kFreeChunk[] = "FREE";
inline constexpr char kSegmentChunk[] = "SEGS";
inline constexpr char kBlobChunk[] = "BLOB";
inline constexpr char kOccupiedChunk[] = "OCCP";
inline constexpr char kResidualChunk[] = "RESD";
inline constexpr char kMetadataChunk[] = "meta";
// Version 2.x: the vector layers, then the tiled cells (ROOM keeps its
// type with a 2.0 body).
inline constexpr char kWallChunk[] = "WALL";
inline constexpr char kFurnitureChunk[] = "FURN";
inline constexpr char kCellChunk[] = "CELL";
// Version 2.1: the cells of a file saved within a tolerance, in blocks.
inline constexpr char kBlockChunk[] = "BLKS";
// Version 2.2: the three vector layers in sections (instead of WALL, ROOM
// and FURN).
inline constexpr char kLayerChunk[] = "LAYR";

// Payload coders (the first byte of every payload but LMHD's).
enum class PayloadCoder : std::uint8_t { kRaw = 0, kDeflate = 1, kDraco = 2 };

// Body -> payload: tries raw and deflate (for `allow_deflate`) and keeps the
// smaller (raw on a tie).
std::vector<std::uint8_t> WrapPayload(const std::vector<std::uint8_t>& body, bool allow_deflate);
// Payload -> body (inflated when needed, bounded by the limits).
StatusOr<std::vector<std::uint8_t>> UnwrapPayload(const std::uint8_t* payload, std::size_t size,
                                                  const DecodeLimits& limits, PayloadCoder* coder);
// As UnwrapPayload, for a chunk of a 2.x file: no 2.x chunk uses the Draco
// coder (it is for 1.0's SEGS), so a Draco payload is corrupt there.
StatusOr<std::vector<std::uint8_t>> UnwrapV2Payload(const std::uint8_t* payload, std::size_t size,
                                                    const DecodeLimits& limits,
                                                    PayloadCoder* coder);
// The coder byte of a 2.x chunk whose body is left unread (the cells of a
// layers-only read): the errors UnwrapV2Payload gives for it, so that a
// file a whole read refuses is not read in part as if it were fine.
Status CheckV2PayloadCoder(const std::uint8_t* payload, std::size_t size);

struct HeaderFields {
  int width = 0;
  int height = 0;
  MapMetadata meta;
  bool lossless = false;
};
std::vector<std::uint8_t> WriteHeader(const HeaderFields& header);
StatusOr<HeaderFields> ReadHeader(const std::uint8_t* data, std::size_t size,
                                  const DecodeLimits& limits);

std::vector<std::uint8_t> WriteMetadata(
    const std::vector<std::pair<std::string, std::string>>& entries);
StatusOr<std::vector<std::pair<std::string, std::string>>> ReadMetadata(
    const std::vector<std::uint8_t>& body);

StatusOr<std::vector<LatticeSegment>> ReadSegments(const std::vector<std::uint8_t>& body, int width,
                                                   int height, const DecodeLimits& limits);

StatusOr<std::vector<std::vector<CellIndex>>> ReadChains(const std::vector<std::uint8_t>& body,
                                                         int width, int height,
                                                         const DecodeLimits& limits);

}  // namespace linemap

#endif  // LINEMAP_CODEC_LMAP_CHUNK_CODING_H_
