// LoadLmapVectors(): the vector layers of a file (include/linemap/lmap_vectors.h).
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "codec/layers/raster.h"
#include "codec/lmap/decoder_v2.h"
#include "format/container.h"
#include "format/file_io.h"
#include "linemap/lines.h"
#include "linemap/lmap_vectors.h"

namespace linemap {

const char* RoomKindName(RoomKind kind) {
  switch (kind) {
    case RoomKind::kRoom:
      return "room";
    case RoomKind::kCorridor:
      return "corridor";
    case RoomKind::kUnspecified:
      break;
  }
  return "unspecified";
}

void LmapVectors::ToWorld(const CellIndex& p, double* x, double* y) const {
  Grid frame;
  frame.meta = meta;
  frame.CellToWorld(p.col, p.row, x, y);
}

StatusOr<LmapVectors> DecodeLmapVectors(const std::vector<std::uint8_t>& bytes,
                                        const DecodeLimits& limits) {
  LINEMAP_ASSIGN_OR_RETURN(ContainerView view, ParseContainer(bytes, limits.max_chunk_bytes));
  if (view.major >= 2) {
    // The layers come before CELL and are read without touching it.
    LINEMAP_ASSIGN_OR_RETURN(V2File file, ReadV2File(view, limits, false));
    LmapVectors v;
    v.major = view.major;
    v.minor = view.minor;
    v.width = file.header.width;
    v.height = file.header.height;
    v.meta = file.header.meta;
    v.walls = std::move(file.walls);
    v.rooms = std::move(file.rooms);
    v.furniture = std::move(file.furniture);
    return v;
  }
  // Version 1.0 files keep their layers between raster chunks, so they are
  // read with the raster; each 1.0 segment is a two-point wall.
  LINEMAP_ASSIGN_OR_RETURN(LmapContents contents, DecodeLmapContents(bytes, limits));
  LmapVectors v;
  v.major = contents.major;
  v.minor = contents.minor;
  v.width = contents.grid.width();
  v.height = contents.grid.height();
  v.meta = contents.grid.meta;
  for (const LatticeSegment& s : contents.segments) v.walls.push_back({{s.a, s.b}});
  for (std::size_t i = 0; i < contents.room_chains.size(); ++i) {
    // A 1.0 chain is its own polygon: every cell a vertex.
    v.rooms.push_back({static_cast<std::uint32_t>(i), RoomKind::kUnspecified,
                       contents.room_chains[i], contents.room_chains[i]});
  }
  for (std::size_t i = 0; i < contents.blob_outlines.size(); ++i) {
    v.furniture.push_back(
        {static_cast<std::uint32_t>(i), -1, contents.blob_outlines[i], contents.blob_outlines[i]});
  }
  return v;
}

StatusOr<LmapVectors> LoadLmapVectors(const std::string& path, const DecodeLimits& limits) {
  LINEMAP_ASSIGN_OR_RETURN(std::vector<std::uint8_t> bytes,
                           ReadFileBytes(path, limits.max_file_bytes));
  StatusOr<LmapVectors> vectors = DecodeLmapVectors(bytes, limits);
  if (!vectors.ok()) return vectors.status().WithContext("'" + path + "'");
  return vectors;
}

}  // namespace linemap
