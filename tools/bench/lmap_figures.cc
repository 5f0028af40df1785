#include "tools/bench/lmap_figures.h"

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "linemap/codec.h"
#include "linemap/lmap_vectors.h"
#include "tools/bench/measure.h"

namespace linemap::bench {
namespace {

constexpr double kMb = 1024.0 * 1024.0;

void Note(MapResult* result, const std::string& what, const Status& status) {
  result->notes.push_back(what + ": " + status.message());
}

// Decodes `file` and counts the cells that differ from `grid` under
// `cells_key`; a decode that fails gets every cell counted.
void AddRoundTrip(const Grid& grid, const std::vector<std::uint8_t>& file, const char* cells_key,
                  const std::string& label, MapResult* result) {
  StatusOr<Grid> decoded = DecodeLmap(file);
  if (!decoded.ok()) {
    result->figures[cells_key] = static_cast<double>(grid.size());
    return Note(result, label + " decode", decoded.status());
  }
  const std::size_t wrong = CellsWrong(grid, *decoded);
  result->figures[cells_key] = static_cast<double>(wrong);
  if (wrong > 0) {
    result->notes.push_back(label + ": the decode differs from the map in " +
                            std::to_string(wrong) + " cells");
  }
  if (!(decoded->meta == grid.meta)) {
    result->notes.push_back(label + ": the decoded resolution or origin differs from the map's");
  }
}

// The file's layers for the overlay SVG: walls cut into their segments.
MapResult::LmapGeometry Geometry(const LmapVectors& vectors) {
  MapResult::LmapGeometry geometry;
  for (const WallPolyline& wall : vectors.walls) {
    for (std::size_t i = 1; i < wall.points.size(); ++i) {
      const CellIndex a = wall.points[i - 1], b = wall.points[i];
      geometry.segments.push_back({static_cast<double>(a.col), static_cast<double>(a.row),
                                   static_cast<double>(b.col), static_cast<double>(b.row)});
    }
  }
  for (const RoomOutline& room : vectors.rooms) geometry.room_chains.push_back(room.chain);
  for (const FurnitureObject& object : vectors.furniture) {
    geometry.blob_outlines.push_back(object.outline);
  }
  return geometry;
}

void AddFidelity(const Grid& grid, const LayerFidelity& fidelity, MapResult* result) {
  auto& f = result->figures;
  f[key::kLmapEdgeCells] = static_cast<double>(fidelity.edge_cells);
  // No edge cell: nothing to miss (as LayerFidelity::covered_share() says).
  f[key::kLmapWithin1Share] = fidelity.edge_cells == 0
                                  ? 1.0
                                  : static_cast<double>(fidelity.within_1_of_wall) /
                                        static_cast<double>(fidelity.edge_cells);
  f[key::kLmapCoveredShare] = fidelity.covered_share();
  // A file without walls has no DisPL_ave. With no edge cell either there is
  // nothing to be far from (0, as RM-Line's mean over no cell); with edge
  // cells the figure stays out and the DisPL goal counts the map as missed.
  std::optional<double> displ = fidelity.displ_ave_cells;
  if (!displ && fidelity.edge_cells == 0) displ = 0.0;
  if (displ) {
    f[key::kLmapDisplCells] = *displ;
    f[key::kLmapDisplCm] = *displ * grid.meta.resolution * 100.0;
  } else {
    result->notes.push_back(".lmap 2.0: no walls for " + std::to_string(fidelity.edge_cells) +
                            " edge cells");
  }
}

// The layers as a viewer reads them (no raster decode), counted and scored
// against the map.
Status AddLayers(const Grid& grid, const std::vector<std::uint8_t>& file, MapResult* result) {
  LINEMAP_ASSIGN_OR_RETURN(LmapVectors vectors, DecodeLmapVectors(file));
  LINEMAP_ASSIGN_OR_RETURN(LayerFidelity fidelity, MeasureLayerFidelity(grid, vectors));
  MapResult::LmapGeometry geometry = Geometry(vectors);
  auto& f = result->figures;
  f[key::kLmapWalls] = static_cast<double>(vectors.walls.size());
  f[key::kLmapWallSegments] = static_cast<double>(geometry.segments.size());
  f[key::kLmapRooms] = static_cast<double>(vectors.rooms.size());
  f[key::kLmapFurniture] = static_cast<double>(vectors.furniture.size());
  AddFidelity(grid, fidelity, result);
  result->lmap_geometry = std::move(geometry);
  return Status::Ok();
}

// Encode and decode CPU time (median of `what.repeats`, in blocks beside
// the rival's when given) and peak memory of the default file, as `linemap
// encode` / `decode` do it.
void AddSpeed(const Grid& grid, const std::vector<std::uint8_t>& file, const LmapMeasure& what,
              MapResult* result) {
  auto encode = [&] { (void)EncodeLmap(grid, EncodeOptions{}); };
  auto decode = [&] { (void)DecodeLmap(file); };
  if (what.rival) {
    const auto [rival_encode, lmap_encode] =
        TimeRunsInBlocks(what.rival->encode, encode, what.repeats);
    const auto [rival_decode, lmap_decode] =
        TimeRunsInBlocks(what.rival->decode, decode, what.repeats);
    result->figures[what.rival->encode_ms_key] = Median(rival_encode);
    result->figures[what.rival->decode_ms_key] = Median(rival_decode);
    result->figures[key::kLmapEncodeMs] = Median(lmap_encode);
    result->figures[key::kLmapDecodeMs] = Median(lmap_decode);
  } else {
    result->figures[key::kLmapEncodeMs] = Median(TimeSamples(encode, what.repeats));
    result->figures[key::kLmapDecodeMs] = Median(TimeSamples(decode, what.repeats));
  }
  if (!what.memory) return;
  if (auto peak = PeakExtraMemoryBytes(encode)) {
    result->figures[key::kLmapEncodePeakMb] = *peak / kMb;
  }
  if (auto peak = PeakExtraMemoryBytes(decode)) {
    result->figures[key::kLmapDecodePeakMb] = *peak / kMb;
  }
}

// An exact file written with `options`: its size under `bytes_key`, the
// cells its decode gets wrong under `cells_key`; the file, if written.
std::optional<std::vector<std::uint8_t>> AddExactFile(const Grid& grid,
                                                      const EncodeOptions& options,
                                                      const char* bytes_key, const char* cells_key,
                                                      const std::string& label, MapResult* result) {
  StatusOr<std::vector<std::uint8_t>> file = EncodeLmap(grid, options);
  if (!file.ok()) {
    result->figures[cells_key] = static_cast<double>(grid.size());
    Note(result, label, file.status());
    return std::nullopt;
  }
  result->figures[bytes_key] = static_cast<double>(file->size());
  AddRoundTrip(grid, *file, cells_key, label, result);
  return std::move(*file);
}

void AddRasterOnly(const Grid& grid, MapResult* result) {
  EncodeOptions options;
  options.vector_layers = false;
  AddExactFile(grid, options, key::kLmapRasterBytes, key::kLmapRasterCellsWrong,
               ".lmap 2.0 --raster-only", result);
}

// The files coded for size (--compact), with the layers and without, and
// the decode time of the first (median of `repeats`), timed in blocks
// beside the default file's decode (`default_file`) as that one is beside
// libpng's, so that each timed run follows an untimed one rather than the
// encodes' fresh memory. (Only the compact times are kept: the report's
// ratios divide them by the default file's times beside libpng's.) The
// median still moves by a third from one bench run to the next on this
// project's VM (2.6 and 3.6 ms at the median map).
void AddCompact(const Grid& grid, const std::vector<std::uint8_t>& default_file, int repeats,
                MapResult* result) {
  EncodeOptions options;
  options.compact = true;
  const std::optional<std::vector<std::uint8_t>> file =
      AddExactFile(grid, options, key::kLmapCompactBytes, key::kLmapCompactCellsWrong,
                   ".lmap 2.3 --compact", result);
  if (file) {
    const auto decode_default = [&] { (void)DecodeLmap(default_file); };
    const auto decode_compact = [&] { (void)DecodeLmap(*file); };
    result->figures[key::kLmapCompactDecodeMs] =
        Median(TimeRunsInBlocks(decode_default, decode_compact, repeats).second);
  }
  options.vector_layers = false;
  AddExactFile(grid, options, key::kLmapRasterCompactBytes, key::kLmapRasterCompactCellsWrong,
               ".lmap 2.3 --compact --raster-only", result);
}

}  // namespace

std::size_t CellsWrong(const Grid& original, const Grid& decoded) {
  if (original.width() != decoded.width() || original.height() != decoded.height()) {
    return original.size();
  }
  std::size_t wrong = 0;
  for (std::size_t i = 0; i < original.size(); ++i) {
    wrong += original.cells()[i] != decoded.cells()[i] ? 1 : 0;
  }
  return wrong;
}

Status AddLmapFigures(const Grid& grid, const LmapMeasure& what, MapResult* result) {
  StatusOr<std::vector<std::uint8_t>> file = EncodeLmap(grid, EncodeOptions{});
  if (!file.ok()) {
    result->figures[key::kLmapCellsWrong] = static_cast<double>(grid.size());
    if (what.rival) {  // nothing to take turns with
      result->figures[what.rival->encode_ms_key] =
          Median(TimeSamples(what.rival->encode, what.repeats));
      result->figures[what.rival->decode_ms_key] =
          Median(TimeSamples(what.rival->decode, what.repeats));
    }
    return file.status();
  }
  result->figures[key::kLmapBytes] = static_cast<double>(file->size());
  AddRoundTrip(grid, *file, key::kLmapCellsWrong, ".lmap 2.0", result);
  Status layers = AddLayers(grid, *file, result);
  if (!layers.ok()) Note(result, ".lmap 2.0 layers", layers);
  AddSpeed(grid, *file, what, result);
  AddRasterOnly(grid, result);
  AddCompact(grid, *file, what.repeats, result);
  return Status::Ok();
}

}  // namespace linemap::bench
