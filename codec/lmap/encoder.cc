// The .lmap encoder (spec/format.md section 9, "Encoding (informative)").
//
// A 2.x file is written in the order the decoder reads it: LMHD, meta, the
// vector layers (LAYR: what a viewer reads without the raster), then the cells in tiles: CELL, the
// exact cells, each tile coded against the hints the layers draw into it (a cell on a wall is cheap
// to confirm as occupied, one inside a room as free), or, within a tolerance, BLKS, the map drawn
// in blocks of T + 1 cells a side (tolerance/tolerance_blocks.cc says why).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

#include "codec/cells/block_tiles.h"
#include "codec/cells/cell_tiles.h"
#include "codec/layers/layer_coding.h"
#include "codec/layers/layer_extraction.h"
#include "codec/layers/layer_hints.h"
#include "codec/layers/layer_sections.h"
#include "codec/layers/section_order.h"
#include "codec/lmap/chunk_coding.h"
#include "codec/lmap/row_encoder.h"
#include "codec/lmap/v2_file.h"
#include "codec/tolerance/simplify.h"
#include "codec/tolerance/tolerance_blocks.h"
#include "format/container.h"
#include "format/file_io.h"
#include "linemap/codec.h"

namespace linemap {
namespace {

Status CheckEncodeOptions(const EncodeOptions& options);

// The robot pose stored as metadata names a point of the map: a cell holds
// it (CellHoldingPoint), as --pose, --room-at and a window take points.
Status CheckRobotPose(int width, int height, const MapMetadata& meta,
                      const EncodeOptions& options) {
  if (!options.robot_pose) return Status::Ok();
  const Pose2D& pose = *options.robot_pose;
  if (!std::isfinite(pose.x) || !std::isfinite(pose.y) || !std::isfinite(pose.yaw)) {
    return InvalidArgumentError("robot pose is not finite");
  }
  if (CellHoldingPoint(meta, width, height, pose.x, pose.y)) return Status::Ok();
  char text[160];
  std::snprintf(text, sizeof(text), "robot pose %.3f,%.3f m is outside the map (%d x %d cells)",
                pose.x, pose.y, width, height);
  return InvalidArgumentError(text);
}

Status CheckEncodeInput(const Grid& grid, const EncodeOptions& options) {
  const int w = grid.width();
  const int h = grid.height();
  if (w < 0 || h < 0 || grid.size() != static_cast<std::size_t>(w) * static_cast<std::size_t>(h)) {
    return InvalidArgumentError("grid dimensions do not match its cells");
  }
  if (!(grid.meta.resolution > 0) || !std::isfinite(grid.meta.resolution)) {
    return InvalidArgumentError("grid resolution must be a positive number");
  }
  if (options.tolerance_cells > 0 && options.max_tolerance_cells != 0 &&
      grid.size() > options.max_tolerance_cells) {
    return OverLimitError(
        Limit::kToleranceCells,
        "a map of " + std::to_string(grid.size()) + " cells is over the limit of " +
            std::to_string(options.max_tolerance_cells) +
            " cells for saving within a tolerance (its checks hold about 25 bytes a cell, " +
            std::to_string(grid.size() * 25 / 1000000) +
            " MB here): save it exact (tolerance 0) or raise the limit (max_tolerance_cells, "
            "--max-tolerance-cells)");
  }
  LINEMAP_RETURN_IF_ERROR(CheckRobotPose(w, h, grid.meta, options));
  return CheckEncodeOptions(options);
}

Status CheckEncodeOptions(const EncodeOptions& options) {
  if (options.max_threads < 0) return InvalidArgumentError("max_threads must not be negative");
  // As ExtractLines asks of its epsilon: under half a cell no lattice line
  // holds a wall's cells.
  if (!(options.epsilon_cells >= 0.5)) {
    return InvalidArgumentError("epsilon must be at least 0.5 cells");
  }
  if (options.tolerance_cells < 0 || options.tolerance_cells > kMaxToleranceCells) {
    return InvalidArgumentError("tolerance " + std::to_string(options.tolerance_cells) +
                                " cells: must be 0 (exact) to " +
                                std::to_string(kMaxToleranceCells));
  }
  if (options.simplified_within_cells < 0) {
    return InvalidArgumentError("simplified_within_cells must not be negative");
  }
  if (options.simplified_within_cells > 0 && options.tolerance_cells > 0) {
    return InvalidArgumentError(
        "a map already simplified within " + std::to_string(options.simplified_within_cells) +
        " cells cannot be saved within a tolerance again (the guarantees against the original "
        "map would not hold): save the original map within the tolerance");
  }
  if (options.tile_size_cells != 0 &&
      (options.tile_size_cells < kMinTileSize || options.tile_size_cells > kMaxTileSize)) {
    return InvalidArgumentError("tile size must be 0 (automatic) or 16..65536 cells");
  }
  if (options.layer_section_cells != 0 && options.layer_section_cells < kMinSectionSide) {
    return InvalidArgumentError("layer section side must be 0 (automatic) or at least 16 cells");
  }
  return Status::Ok();
}

MapFrame FrameOf(const Grid& grid) { return {grid.width(), grid.height(), grid.meta}; }

// The exact cells: CELL tiles coded against the layers' hints.
std::vector<std::uint8_t> ExactCells(const Grid& grid, const EncodeOptions& options,
                                     const VectorLayers& layers) {
  const LayerIndex index(layers.walls, layers.rooms, layers.furniture);
  return EncodeCellChunk(grid, index,
                         TileSide(grid.width(), grid.height(), options.tile_size_cells),
                         options.max_threads, options.compact);
}

// The share of a save within a tolerance done after `rounds` rounds of
// checks (FitBlockCells), which take some 85 % of its time (tsc at T = 1:
// 7.4 of 8.6 s in 13 rounds, measured beside other jobs). How many rounds
// a map needs is not known ahead (at most 96), so each round takes a fifth
// of what is left of the rounds' share: the bar moves with every round and
// does not reach the end before the file is written.
constexpr double kProgressBeforeRounds = 0.05;  // the layers and the exact cells
constexpr double kProgressOfRounds = 0.85;
constexpr double kProgressWithinFile = 0.95;  // then the exact file, to compare with

double ToleranceRoundsProgress(int rounds) {
  return kProgressBeforeRounds + kProgressOfRounds * (1.0 - std::pow(0.8, rounds));
}

// The cells within a tolerance: BLKS tiles, the tile side of TileSide()
// down to a multiple of the block side (spec/format.md 6.4).
StatusOr<std::vector<std::uint8_t>> CellsWithinTolerance(const Grid& grid,
                                                         const EncodeOptions& options,
                                                         const VectorLayers& layers, bool* exact) {
  const auto after_round = [&options](int rounds) {
    if (options.progress) options.progress(ToleranceRoundsProgress(rounds));
  };
  LINEMAP_ASSIGN_OR_RETURN(BlockCells blocks, FitBlockCells(grid, options.tolerance_cells,
                                                            after_round, options.max_threads));
  // Exact when what the blocks draw is the map, restored everywhere or not
  // (blocks of one value each draw it too): then the file names no T.
  *exact = ComposeBlockCells(grid, blocks).cells() == grid.cells();
  const int f = blocks.block_cells;
  int tile = TileSide(grid.width(), grid.height(), options.tile_size_cells) / f * f;
  if (tile < kMinTileSize) tile += f;  // a side of 16 with blocks of 3 or 5
  const LayerIndex index(layers.walls, layers.rooms, layers.furniture);
  return EncodeBlockChunk(grid, blocks, index, tile, options.max_threads);
}

// A version 2 file at options.tolerance_cells.
StatusOr<std::vector<std::uint8_t>> EncodeV2(const Grid& grid, const EncodeOptions& options) {
  // The exact file of a map of several layer sections is the one its rows
  // code a band at a time (as SaveRosMapAsLmap codes it from an image).
  if (EncodesByRows(grid.width(), grid.height(), options)) {
    return EncodeGridByRows(grid, options);
  }
  // The layers are drawn from the map itself at every tolerance.
  VectorLayers layers;
  if (options.vector_layers) {
    LINEMAP_ASSIGN_OR_RETURN(layers, ExtractVectorLayers(grid, options, /*with_chains=*/false));
  }
  // The layers in the order LAYR lists them: the cells' hints are drawn
  // from them in that order, as the decoder draws them.
  const int section_side =
      LayerSectionSide(grid.width(), grid.height(), options.layer_section_cells);
  ArrangeLayersInSections(grid.width(), grid.height(), section_side, &layers.walls, &layers.rooms,
                          &layers.furniture);
  LINEMAP_RETURN_IF_ERROR(CheckLayersWithinDefaultLimits(layers));
  std::vector<std::uint8_t> exact_cells = ExactCells(grid, options, layers);
  if (options.tolerance_cells == 0) {
    return WriteV2(FrameOf(grid), options, layers, section_side, true, kCellChunk, exact_cells);
  }
  // Within a tolerance the cells are the map drawn in blocks of T + 1
  // cells, with cells restored where a guarantee fails (FitBlockCells
  // checks every one on exactly what the file decodes to). Where the blocks
  // save nothing (a clean plan at T = 1) the exact cells are kept: never
  // larger than the exact file. The files are compared whole: the blocks'
  // file also names its tolerance in the metadata.
  bool exact = false;
  if (options.progress) options.progress(ToleranceRoundsProgress(0));
  LINEMAP_ASSIGN_OR_RETURN(std::vector<std::uint8_t> block_cells,
                           CellsWithinTolerance(grid, options, layers, &exact));
  std::vector<std::uint8_t> blocks_file =
      WriteV2(FrameOf(grid), options, layers, section_side, exact, kBlockChunk, block_cells);
  std::vector<std::uint8_t> cells_file =
      WriteV2(FrameOf(grid), options, layers, section_side, true, kCellChunk, exact_cells);
  return blocks_file.size() < cells_file.size() ? blocks_file : cells_file;
}

// The file EncodeLmap returns (its progress reports aside).
StatusOr<std::vector<std::uint8_t>> EncodeFile(const Grid& grid, const EncodeOptions& options) {
  LINEMAP_RETURN_IF_ERROR(CheckEncodeInput(grid, options));
  if (options.tolerance_cells == 0) return EncodeV2(grid, options);
  // Within a tolerance the walls differ from the exact file's (straight,
  // fitted within T cells), so where neither they nor the blocks save
  // anything (navtut/lse_arena at T = 4: 133 against 132 bytes) the exact
  // file is written: never larger than it. The exact encode costs a tenth
  // of the tolerance one (whose guarantees are checked cell by cell).
  LINEMAP_ASSIGN_OR_RETURN(std::vector<std::uint8_t> within, EncodeV2(grid, options));
  if (options.progress) options.progress(kProgressWithinFile);
  EncodeOptions exact_options = options;
  exact_options.tolerance_cells = 0;
  exact_options.progress = nullptr;  // a tenth of the time: the bar ends at 1 after it
  LINEMAP_ASSIGN_OR_RETURN(std::vector<std::uint8_t> exact, EncodeV2(grid, exact_options));
  return within.size() < exact.size() ? within : exact;
}

}  // namespace

StatusOr<std::vector<std::uint8_t>> EncodeLmap(const Grid& grid, const EncodeOptions& options) {
  StatusOr<std::vector<std::uint8_t>> file = EncodeFile(grid, options);
  if (file.ok() && options.progress) options.progress(1.0);
  return file;
}

namespace {

// A map file's rows as the row encoder takes them.
class MapFileRows : public CellRowSource {
 public:
  explicit MapFileRows(MapRowReader* reader) : reader_(reader) {}
  Status ReadRow(Cell* cells) override {
    Status status = reader_->ReadRow(cells);
    read_failed_ = !status.ok();
    return status;
  }
  // Whether the last row could not be read (the error names the image).
  bool read_failed() const { return read_failed_; }

 private:
  MapRowReader* reader_;
  bool read_failed_ = false;
};

// The file of the map `map_path` names: coded as its rows are read when
// the row encoder takes it, else from the loaded grid.
StatusOr<std::vector<std::uint8_t>> EncodeMapFile(const std::string& map_path,
                                                  const EncodeOptions& options,
                                                  const MapLoadOptions& load,
                                                  LmapSaveSummary* summary) {
  LINEMAP_RETURN_IF_ERROR(CheckEncodeOptions(options));
  LINEMAP_ASSIGN_OR_RETURN(std::unique_ptr<MapRowReader> reader,
                           MapRowReader::Open(map_path, load));
  summary->width = reader->width();
  summary->height = reader->height();
  const std::string where = "'" + map_path + "'";
  const Status pose = CheckRobotPose(reader->width(), reader->height(), reader->meta(), options);
  if (!pose.ok()) return pose.WithContext(where);
  if (!EncodesByRows(reader->width(), reader->height(), options)) {
    reader.reset();
    LINEMAP_ASSIGN_OR_RETURN(Grid grid, LoadRosMap(map_path, load));
    StatusOr<std::vector<std::uint8_t>> bytes = EncodeLmap(grid, options);
    if (!bytes.ok()) return bytes.status().WithContext(where);
    return bytes;
  }
  MapFileRows rows(reader.get());
  const MapFrame frame{reader->width(), reader->height(), reader->meta()};
  StatusOr<std::vector<std::uint8_t>> bytes = EncodeLmapByRows(frame, options, &rows);
  if (bytes.ok()) {
    if (options.progress) options.progress(1.0);
    return bytes;
  }
  // A defect of the image names the image; of a map YAML's image, the YAML
  // too (as LoadRosMap says it).
  const bool names_the_map = rows.read_failed() && reader->is_bare_image();
  return names_the_map ? bytes.status() : bytes.status().WithContext(where);
}

Status WriteAndCommit(const std::vector<std::uint8_t>& bytes, AtomicFileWriter* out) {
  LINEMAP_RETURN_IF_ERROR(
      out->Append(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size())));
  return out->Commit();
}

}  // namespace

StatusOr<LmapSaveSummary> SaveRosMapAsLmap(const std::string& map_path,
                                           const std::string& lmap_path,
                                           const EncodeOptions& options, const MapLoadOptions& load,
                                           Durability durability) {
  // The output is opened first: a missing directory or a read-only file
  // is reported before the encode (minutes within a tolerance on a large
  // map) rather than after it; the unnamed temporary leaves no trace when
  // the encode fails.
  LINEMAP_ASSIGN_OR_RETURN(AtomicFileWriter out, AtomicFileWriter::Open(lmap_path, durability));
  LmapSaveSummary summary;
  LINEMAP_ASSIGN_OR_RETURN(std::vector<std::uint8_t> bytes,
                           EncodeMapFile(map_path, options, load, &summary));
  LINEMAP_RETURN_IF_ERROR(WriteAndCommit(bytes, &out));
  summary.bytes = bytes.size();
  return summary;
}

Status SaveLmap(const std::string& path, const Grid& grid, const EncodeOptions& options) {
  // Opened first, as in SaveRosMapAsLmap.
  LINEMAP_ASSIGN_OR_RETURN(AtomicFileWriter out, AtomicFileWriter::Open(path));
  LINEMAP_ASSIGN_OR_RETURN(std::vector<std::uint8_t> bytes, EncodeLmap(grid, options));
  return WriteAndCommit(bytes, &out);
}

}  // namespace linemap
