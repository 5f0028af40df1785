// DecodeLmapToRosMap (include/linemap/codec.h): an .lmap file to a ROS map
// (YAML + PGM) in memory that does not grow with the map. The CELL chunk's
// tiles decode on their own (spec/format.md section 6), so the map is
// decoded one band of tile rows at a time, from the top of the map down (the
// PGM's first row is the grid's last), and each band is written to the PGM
// before the next is decoded.
#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "codec/cells/cell_tiles.h"
#include "codec/layers/layer_hints.h"
#include "codec/lmap/decoder_v2.h"
#include "format/byte_io.h"
#include "format/container.h"
#include "format/file_io.h"
#include "linemap/codec.h"
#include "linemap/map_io.h"

namespace linemap {
namespace {

// Cells decoded at a time: 24 MB of band, so that a 20,768-cell-wide map
// takes its tile rows whole (512 rows, or 1024 when it was saved so) (one write per band, all tiles
// of the row spread over the threads) and a wider one is cut into column groups.
constexpr std::uint64_t kBandCells = std::uint64_t{24} << 20;
// Rows per band at least: with small tiles (16 cells) a band of one tile row
// would re-read the tile index once per 16 rows.
constexpr int kMinBandRows = 1024;

void AddCounts(const Cell* cells, std::size_t n, CellCounts* counts) {
  std::size_t by_value[3] = {0, 0, 0};
  for (std::size_t i = 0; i < n; ++i) ++by_value[static_cast<int>(cells[i])];
  counts->free += by_value[static_cast<int>(Cell::kFree)];
  counts->occupied += by_value[static_cast<int>(Cell::kOccupied)];
  counts->unknown += by_value[static_cast<int>(Cell::kUnknown)];
}

// The band layout: rows and columns per band, multiples of the tile side
// (but never more than the map).
struct Bands {
  int rows = 0;
  int cols = 0;
};

Bands ChooseBands(int width, int height, int tile_size) {
  Bands bands;
  const int tile_rows = std::max(1, (kMinBandRows + tile_size - 1) / tile_size);
  bands.rows = static_cast<int>(
      std::min<std::int64_t>(height, static_cast<std::int64_t>(tile_rows) * tile_size));
  const std::uint64_t cols_in_budget = kBandCells / static_cast<std::uint64_t>(bands.rows);
  const std::uint64_t tiles_across =
      std::max<std::uint64_t>(1, cols_in_budget / static_cast<std::uint64_t>(tile_size));
  bands.cols = static_cast<int>(
      std::min<std::uint64_t>(width, tiles_across * static_cast<std::uint64_t>(tile_size)));
  return bands;
}

// Writes a map with no cells' chunk: every cell unknown.
Status WriteUnknown(int width, int height, RosMapWriter* writer, CellCounts* counts) {
  const int rows = static_cast<int>(std::max<std::int64_t>(1, (std::int64_t{1} << 20) / width));
  const std::vector<Cell> band(static_cast<std::size_t>(rows) * width, Cell::kUnknown);
  for (int row1 = height; row1 > 0; row1 -= rows) {
    const int row0 = std::max(0, row1 - rows);
    LINEMAP_RETURN_IF_ERROR(writer->WriteCells(0, row0, width, row1 - row0, band.data()));
  }
  counts->unknown = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  return Status::Ok();
}

// The cells of a 2.x file, band by band from the top of the map. Decoding
// errors get `where` (the .lmap file) as context; writing errors name the
// output already.
Status WriteCellBands(V2File* file, const DecodeLimits& limits, const std::string& where,
                      RosMapWriter* writer, CellCounts* counts) {
  const int width = file->header.width;
  const int height = file->header.height;
  if (!file->has_cells) {
    const Status layers = CheckLayersWithoutCells(limits, file);
    if (!layers.ok()) return layers.WithContext(where);
    return WriteUnknown(width, height, writer, counts);
  }
  StatusOr<int> tile_size = V2CellDecoder::TileSizeOf(*file);
  if (!tile_size.ok()) return tile_size.status().WithContext(where);
  const Bands bands = ChooseBands(width, height, *tile_size);
  // The layers of LAYR's sections are read for one band of section rows at
  // a time, and kept while the cell bands stay inside it.
  int layer_rows = height;
  if (file->has_layer_sections) {
    StatusOr<int> rows = LayerBandRows(*file);
    if (!rows.ok()) return rows.status().WithContext(where);
    layer_rows = *rows;
  }
  int held_row0 = -1, held_row1 = -1;
  std::optional<V2CellDecoder> cells;
  std::vector<Cell> band(static_cast<std::size_t>(bands.rows) * bands.cols);
  // Bands start on tile rows counted from row 0, so each decodes whole tiles:
  // the top band is the partial one.
  const int top_band_row0 = (height - 1) / bands.rows * bands.rows;
  for (int row0 = top_band_row0; row0 >= 0; row0 -= bands.rows) {
    const int row1 = std::min(height, row0 + bands.rows);
    if (!cells || row0 < held_row0 || row1 > held_row1) {
      held_row0 = row0 / layer_rows * layer_rows;
      held_row1 = static_cast<int>(std::min<std::int64_t>(
          height, (std::int64_t{row1} + layer_rows - 1) / layer_rows * layer_rows));
      cells.reset();  // its index points into the layers replaced next
      const Status read =
          ReadLayersReaching(limits, CellRect{0, held_row0, width, held_row1}, file);
      if (!read.ok()) return read.WithContext(where);
      cells.emplace(*file);
    }
    for (int col0 = 0; col0 < width; col0 += bands.cols) {
      const int col1 = std::min(width, col0 + bands.cols);
      const std::size_t n = static_cast<std::size_t>(col1 - col0) * (row1 - row0);
      // No fill first: the tiles cover the band, and each writes its cells.
      const Status decoded =
          cells->Decode(CellRect{col0, row0, col1, row1}, limits.max_threads, band.data());
      if (!decoded.ok()) return decoded.WithContext(where);
      AddCounts(band.data(), n, counts);
      LINEMAP_RETURN_IF_ERROR(
          writer->WriteCells(col0, row0, col1 - col0, row1 - row0, band.data()));
    }
  }
  return Status::Ok();
}

}  // namespace

StatusOr<MapFileSummary> DecodeLmapToRosMap(const std::string& lmap_path,
                                            const std::string& yaml_path,
                                            const DecodeLimits& limits, Durability durability) {
  const std::string where = "'" + lmap_path + "'";
  // The file's bytes are read whole: a 282-Mcell map is a 1.4 MB file.
  LINEMAP_ASSIGN_OR_RETURN(std::vector<std::uint8_t> bytes,
                           ReadFileBytes(lmap_path, limits.max_file_bytes));
  StatusOr<ContainerView> view = ParseContainer(bytes, limits.max_chunk_bytes);
  if (!view.ok()) return view.status().WithContext(where);
  MapFileSummary summary;
  if (view->major == 1) {
    StatusOr<Grid> grid = DecodeLmap(bytes, limits);
    if (!grid.ok()) return grid.status().WithContext(where);
    LINEMAP_RETURN_IF_ERROR(SaveRosMap(yaml_path, *grid, durability));
    summary.width = grid->width();
    summary.height = grid->height();
    summary.meta = grid->meta;
    summary.counts = grid->Count();
    return summary;
  }
  StatusOr<V2File> file = ReadV2File(*view, limits, /*read_cells=*/true, /*expand_chains=*/false,
                                     /*window=*/nullptr, /*defer_sections=*/true);
  if (!file.ok()) return file.status().WithContext(where);
  summary.width = file->header.width;
  summary.height = file->header.height;
  summary.meta = file->header.meta;
  // A grid of no cells cannot be saved as an image, but a defect of the
  // file comes first: its cells' chunk is checked (it has no tiles).
  if (summary.width == 0 || summary.height == 0) {
    const Status cells = V2CellDecoder(*file).Decode(CellRect{0, 0, summary.width, summary.height},
                                                     limits.max_threads, nullptr);
    if (!cells.ok()) return cells.WithContext(where);
  }
  LINEMAP_ASSIGN_OR_RETURN(
      RosMapWriter writer,
      RosMapWriter::Open(yaml_path, summary.width, summary.height, summary.meta, durability));
  LINEMAP_RETURN_IF_ERROR(WriteCellBands(&*file, limits, where, &writer, &summary.counts));
  LINEMAP_RETURN_IF_ERROR(writer.Commit());
  return summary;
}

}  // namespace linemap
