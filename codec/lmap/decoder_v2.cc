// 2.x files: LMHD, then WALL, ROOM, FURN or LAYR, then CELL or BLKS (each
// optional, at most once, in this order), meta and unknown ancillary chunks
// anywhere after LMHD.
#include "codec/lmap/decoder_v2.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "codec/cells/block_tiles.h"
#include "codec/cells/cell_tiles.h"
#include "codec/layers/layer_coding.h"
#include "codec/layers/layer_hints.h"
#include "codec/layers/layer_sections.h"
#include "format/byte_io.h"

namespace linemap {
namespace {

constexpr const char* kV2CriticalOrder[] = {kWallChunk, kRoomChunk, kFurnitureChunk, kCellChunk};

// CELL and BLKS are the two forms of the cells: either may come last. LAYR
// holds the three layers: it takes FURN's place, and a file with it has
// none of WALL, ROOM and FURN (ReadV2Chunk).
int V2Rank(const std::string& type) {
  if (type == kBlockChunk) return 3;
  if (type == kLayerChunk) return 2;
  for (int i = 0; i < 4; ++i) {
    if (type == kV2CriticalOrder[i]) return i;
  }
  return -1;
}

// One chunk after LMHD into `file`.
Status ReadV2Chunk(const Chunk& chunk, const DecodeLimits& limits, bool read_cells,
                   bool expand_chains, int* last_rank, V2File* file) {
  if (chunk.type == kHeaderChunk) return CorruptError("a second LMHD chunk");
  const int rank = V2Rank(chunk.type);
  if (rank < 0 && chunk.type != kMetadataChunk) {
    if (chunk.critical()) return UnsupportedError("unknown critical chunk");
    file->chunks.push_back({chunk.type, chunk.size, "skipped"});
    return Status::Ok();
  }
  if (rank >= 0) {
    if (rank <= *last_rank) return CorruptError("chunk out of order or repeated");
    if (chunk.type == kLayerChunk && *last_rank >= 0) {
      return CorruptError("LAYR in a file with WALL, ROOM or FURN");
    }
    *last_rank = rank;
  }
  const bool cells = chunk.type == kCellChunk || chunk.type == kBlockChunk;
  if (cells) {
    file->has_cells = true;
    file->cells_in_blocks = chunk.type == kBlockChunk;
  }
  if (cells && !read_cells) {
    // The layers alone (spec 7.1): the body is left unread, but its coder
    // byte says whether this decoder could read it at all, as for every
    // chunk a decoder reads (a file a full decode refuses as unsupported
    // is not exported as if it were fine).
    LINEMAP_RETURN_IF_ERROR(CheckV2PayloadCoder(chunk.payload, chunk.size));
    file->chunks.push_back({chunk.type, chunk.size, "tiles"});
    return Status::Ok();
  }
  PayloadCoder coder = PayloadCoder::kRaw;
  LINEMAP_ASSIGN_OR_RETURN(std::vector<std::uint8_t> body,
                           UnwrapV2Payload(chunk.payload, chunk.size, limits, &coder));
  const bool range = rank >= 0 && !cells;
  const bool raw = coder == PayloadCoder::kRaw;
  file->chunks.push_back({chunk.type, chunk.size,
                          cells                       ? "tiles"
                          : chunk.type == kLayerChunk ? (raw ? "sections" : "sections+deflate")
                          : range                     ? (raw ? "range" : "range+deflate")
                                                      : (raw ? "raw" : "deflate")});
  const int w = file->header.width;
  const int h = file->header.height;
  if (chunk.type == kMetadataChunk) {
    LINEMAP_ASSIGN_OR_RETURN(file->metadata, ReadMetadata(body));
  } else if (chunk.type == kWallChunk) {
    LINEMAP_ASSIGN_OR_RETURN(file->walls, DecodeWalls(body, w, h, limits));
  } else if (chunk.type == kRoomChunk) {
    LINEMAP_ASSIGN_OR_RETURN(file->rooms, DecodeRooms(body, w, h, limits, expand_chains));
  } else if (chunk.type == kFurnitureChunk) {
    LINEMAP_ASSIGN_OR_RETURN(file->furniture, DecodeFurniture(body, w, h, limits, expand_chains));
  } else if (chunk.type == kLayerChunk) {
    file->has_layer_sections = true;
    // The table is checked now, in file order; the streams are read once
    // the window is known.
    LINEMAP_ASSIGN_OR_RETURN(file->layer_table, ReadLayerSectionTable(body, w, h, limits));
    file->layer_body = std::move(body);
  } else {
    file->cell_body = std::move(body);
  }
  return Status::Ok();
}

}  // namespace

namespace {

// `window` grown to the tiles of the cells' chunk that meet it.
StatusOr<CellRect> WindowTiles(const V2File& file, CellRect window) {
  LINEMAP_ASSIGN_OR_RETURN(int tile, V2CellDecoder::TileSizeOf(file));
  const int w = file.header.width, h = file.header.height;
  return CellRect{window.x0 / tile * tile, window.y0 / tile * tile,
                  static_cast<int>(std::min<std::int64_t>(
                      (std::int64_t{window.x1} + tile - 1) / tile * tile, w)),
                  static_cast<int>(std::min<std::int64_t>(
                      (std::int64_t{window.y1} + tile - 1) / tile * tile, h))};
}

// LAYR's layers into `file`: those of the sections whose box meets
// `region`, or all of them. The body stays for other regions.
Status ReadSectionsMeeting(const DecodeLimits& limits, bool expand_chains, const CellRect* region,
                           V2File* file) {
  StatusOr<DecodedLayers> layers =
      DecodeLayerSections(file->layer_body, file->layer_table, file->header.width,
                          file->header.height, limits, expand_chains, region);
  if (!layers.ok()) return layers.status().WithContext(std::string("chunk ") + kLayerChunk);
  file->walls = std::move(layers->walls);
  file->wall_indices = std::move(layers->wall_indices);
  file->rooms = std::move(layers->rooms);
  file->furniture = std::move(layers->furniture);
  return Status::Ok();
}

// LAYR's layers into `file`: all of them, or those that draw into the
// tiles meeting `window`.
Status ReadLayerSections(const DecodeLimits& limits, bool expand_chains, const CellRect* window,
                         V2File* file) {
  std::optional<CellRect> tiles;
  if (window != nullptr && file->has_cells && !file->cell_body.empty()) {
    LINEMAP_ASSIGN_OR_RETURN(tiles, WindowTiles(*file, *window));
  }
  return ReadSectionsMeeting(limits, expand_chains, tiles ? &*tiles : nullptr, file);
}

}  // namespace

StatusOr<int> LayerBandRows(const V2File& file) {
  constexpr std::int64_t kMaxBands = 16;
  LINEMAP_ASSIGN_OR_RETURN(const int tile, V2CellDecoder::TileSizeOf(file));
  const std::int64_t height = std::max(file.header.height, 1);
  // The side is checked (16..2^31-1) and a tile is 1..65536 cells: no sum
  // here wraps.
  const std::int64_t rows =
      std::max<std::int64_t>(file.layer_table.side, (height + kMaxBands - 1) / kMaxBands);
  return static_cast<int>(std::min<std::int64_t>((rows + tile - 1) / tile * tile, height));
}

Status ReadLayersReaching(const DecodeLimits& limits, const CellRect& rect, V2File* file) {
  if (!file->has_layer_sections) return Status::Ok();
  return ReadLayerSections(limits, false, &rect, file);
}

Status ReadLayersMeeting(const DecodeLimits& limits, const CellRect& rect, V2File* file) {
  if (!file->has_layer_sections) return Status::Ok();
  return ReadSectionsMeeting(limits, /*expand_chains=*/true, &rect, file);
}

Status CheckLayersWithoutCells(const DecodeLimits& limits, V2File* file) {
  if (!file->has_layer_sections || file->has_cells) return Status::Ok();
  LINEMAP_RETURN_IF_ERROR(ReadLayerSections(limits, /*expand_chains=*/false, nullptr, file));
  std::vector<WallPolyline>().swap(file->walls);
  std::vector<std::uint64_t>().swap(file->wall_indices);
  std::vector<RoomOutline>().swap(file->rooms);
  std::vector<FurnitureObject>().swap(file->furniture);
  return Status::Ok();
}

StatusOr<V2File> ReadV2File(const ContainerView& view, const DecodeLimits& limits, bool read_cells,
                            bool expand_chains, const CellRect* window, bool defer_sections) {
  if (view.chunks.empty() || view.chunks[0].type != kHeaderChunk) {
    return CorruptError("the first chunk is not LMHD");
  }
  V2File file;
  const Chunk& head = view.chunks[0];
  StatusOr<HeaderFields> header = ReadHeader(head.payload, head.size, limits);
  if (!header.ok()) return header.status().WithContext("chunk LMHD");
  file.header = *header;
  file.chunks.push_back({head.type, head.size, "header"});
  int last_rank = -1;
  for (std::size_t i = 1; i < view.chunks.size(); ++i) {
    const Status status =
        ReadV2Chunk(view.chunks[i], limits, read_cells, expand_chains, &last_rank, &file);
    if (!status.ok()) return status.WithContext("chunk " + view.chunks[i].type);
  }
  if (file.has_layer_sections && !defer_sections) {
    LINEMAP_RETURN_IF_ERROR(ReadLayerSections(limits, expand_chains, window, &file));
    file.layer_body = {};
  }
  return file;
}

Status CheckWindow(const CellWindow& w, int width, int height) {
  if (w.col0 < 0 || w.row0 < 0 || w.col1 > width || w.row1 > height || w.col0 >= w.col1 ||
      w.row0 >= w.row1) {
    return InvalidArgumentError("window [" + std::to_string(w.col0) + ", " +
                                std::to_string(w.col1) + ") x [" + std::to_string(w.row0) + ", " +
                                std::to_string(w.row1) + ") is empty or not inside the map's " +
                                std::to_string(width) + " x " + std::to_string(height) + " cells");
  }
  return Status::Ok();
}

Grid WindowGrid(const MapMetadata& meta, const CellWindow& window) {
  Grid grid(window.col1 - window.col0, window.row1 - window.row0, Cell::kUnknown);
  grid.meta = meta;
  // The window's lower-left corner: the map origin moved by (col0, row0)
  // cells along the map's rotated axes.
  const double dx = window.col0 * meta.resolution;
  const double dy = window.row0 * meta.resolution;
  const double c = std::cos(meta.origin.yaw), s = std::sin(meta.origin.yaw);
  grid.meta.origin.x = meta.origin.x + c * dx - s * dy;
  grid.meta.origin.y = meta.origin.y + s * dx + c * dy;
  return grid;
}

namespace {

Status DecodeCells(const V2File& file, const CellWindow& window, const DecodeLimits& limits,
                   Grid* out) {
  const CellRect rect{window.col0, window.row0, window.col1, window.row1};
  return V2CellDecoder(file).Decode(rect, limits.max_threads, out->mutable_cells().data());
}

std::string CellChunkName(const V2File& file) {
  return std::string("chunk ") + (file.cells_in_blocks ? kBlockChunk : kCellChunk);
}

}  // namespace

V2CellDecoder::V2CellDecoder(const V2File& file)
    : file_(file), index_(file.walls, file.rooms, file.furniture) {}

StatusOr<int> V2CellDecoder::TileSizeOf(const V2File& file) {
  if (!file.has_cells) return 1;
  ByteCursor cursor(file.cell_body);
  // BLKS puts its block side first; both decoders check the side again.
  if (file.cells_in_blocks) LINEMAP_RETURN_IF_ERROR(cursor.ReadU8("block side").status());
  StatusOr<std::uint64_t> tile_size = cursor.ReadVarint("tile size");
  if (tile_size.ok() && (*tile_size < kMinTileSize || *tile_size > kMaxTileSize)) {
    tile_size = CorruptError("tile size " + std::to_string(*tile_size) + " outside 16..65536");
  }
  if (!tile_size.ok()) return tile_size.status().WithContext(CellChunkName(file));
  return static_cast<int>(*tile_size);
}

Status V2CellDecoder::Decode(CellRect window, int threads, Cell* out) const {
  if (!file_.has_cells) return Status::Ok();  // no cells' chunk: all unknown
  const int w = file_.header.width, h = file_.header.height;
  const Status status = file_.cells_in_blocks
                            ? DecodeBlockChunk(file_.cell_body, index_, w, h, window, threads, out)
                            : DecodeCellChunk(file_.cell_body, index_, w, h, window, threads, out);
  return status.ok() ? status : status.WithContext(ChunkName());
}

std::string V2CellDecoder::ChunkName() const { return CellChunkName(file_); }

Status DecodeV2Contents(const ContainerView& view, const DecodeLimits& limits, LmapContents* out) {
  LINEMAP_ASSIGN_OR_RETURN(V2File file, ReadV2File(view, limits, true));
  const HeaderFields& h = file.header;
  out->grid = Grid(h.width, h.height, Cell::kUnknown);
  out->grid.meta = h.meta;
  out->lossless = h.lossless;
  // Also on a grid without cells (0 columns or rows): the cells' chunk
  // must still be well formed (its tile side, an empty index), as for a
  // decoder that reads it before knowing the grid is empty.
  LINEMAP_RETURN_IF_ERROR(
      DecodeCells(file, CellWindow{0, 0, h.width, h.height}, limits, &out->grid));
  out->walls = std::move(file.walls);
  out->rooms = std::move(file.rooms);
  out->furniture = std::move(file.furniture);
  out->metadata = std::move(file.metadata);
  out->chunks = std::move(file.chunks);
  return Status::Ok();
}

StatusOr<Grid> DecodeV2Region(const ContainerView& view, const CellWindow& window,
                              const DecodeLimits& limits) {
  const CellRect rect{window.col0, window.row0, window.col1, window.row1};
  LINEMAP_ASSIGN_OR_RETURN(V2File file, ReadV2File(view, limits, true, /*expand_chains=*/false,
                                                   &rect, /*defer_sections=*/true));
  Grid grid = WindowGrid(file.header.meta, window);
  // Without cells the grid is all unknown, whatever the layers draw; they
  // are read all the same (a corrupt stream is a corrupt file either way).
  if (!file.has_layer_sections || !file.has_cells) {
    LINEMAP_RETURN_IF_ERROR(CheckLayersWithoutCells(limits, &file));
    LINEMAP_RETURN_IF_ERROR(DecodeCells(file, window, limits, &grid));
    return grid;
  }
  // Band by band, each with the layers of the sections that reach it.
  LINEMAP_ASSIGN_OR_RETURN(const int band, LayerBandRows(file));
  const std::size_t width = static_cast<std::size_t>(rect.x1 - rect.x0);
  for (int y0 = rect.y0; y0 < rect.y1;) {
    const int y1 =
        static_cast<int>(std::min<std::int64_t>(rect.y1, (std::int64_t{y0} / band + 1) * band));
    const CellRect part{rect.x0, y0, rect.x1, y1};
    LINEMAP_RETURN_IF_ERROR(ReadLayersReaching(limits, part, &file));
    Cell* out = grid.mutable_cells().data() + static_cast<std::size_t>(y0 - rect.y0) * width;
    LINEMAP_RETURN_IF_ERROR(V2CellDecoder(file).Decode(part, limits.max_threads, out));
    y0 = y1;
  }
  return grid;
}

}  // namespace linemap
