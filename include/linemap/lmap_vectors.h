// The vector layers of an .lmap file, read without decoding the raster:
// what a viewer, a planner or a GIS takes from the file.
//
// Geometry is on the integer cell lattice (the centre of cell (col, row) is
// the point (col, row), row 0 at the origin); ToWorld() gives map-frame
// metres as Grid::CellToWorld does.
#ifndef LINEMAP_LMAP_VECTORS_H_
#define LINEMAP_LMAP_VECTORS_H_

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "linemap/cells.h"
#include "linemap/codec.h"
#include "linemap/grid.h"
#include "linemap/status.h"
#include "linemap/vector_layers.h"

namespace linemap {

struct LmapVectors {
  int major = 0;
  int minor = 0;
  int width = 0;   // cells
  int height = 0;  // cells
  MapMetadata meta;
  std::vector<WallPolyline> walls;
  std::vector<RoomOutline> rooms;
  std::vector<FurnitureObject> furniture;
  // Walls have no stored id: a wall's id is its index among the walls of
  // the whole file. A read of part of the file (DecodeLmapVectorsInWindow)
  // keeps some of them, and says which here: walls[i] is the file's wall
  // wall_indices[i] (increasing). Empty when `walls` are all of the file's
  // walls, in order (DecodeLmapVectors). WallIndex() reads either.
  std::vector<std::uint64_t> wall_indices;

  // The index of walls[i] among the walls of the whole file.
  std::uint64_t WallIndex(std::size_t i) const {
    return wall_indices.empty() ? std::uint64_t{i} : wall_indices[i];
  }
  // Map-frame metres of a lattice point.
  void ToWorld(const CellIndex& p, double* x, double* y) const;
};

// How well the layers hold the original map's walls, the RM-Line paper's
// way: over the edge cells of `original` (occupied cells with a free
// 4-neighbour), DisPL_ave is the mean distance (cells) from the cell centre
// to the nearest wall segment; `covered` counts the edge cells within one
// cell of a wall segment or inside a furniture outline (fill rule of
// spec/format.md section 8.2).
struct LayerFidelity {
  std::size_t edge_cells = 0;
  // Mean and largest distance (cells); nullopt when the file has no walls.
  std::optional<double> displ_ave_cells;
  std::optional<double> displ_max_cells;
  std::size_t within_1_of_wall = 0;  // edge cells within one cell of a wall segment
  std::size_t in_furniture = 0;      // edge cells inside a furniture outline's fill
  std::size_t covered = 0;           // edge cells in either
  double covered_share() const {
    return edge_cells == 0 ? 1.0 : static_cast<double>(covered) / static_cast<double>(edge_cells);
  }
};
// `original` must have the vectors' width and height (else invalid argument).
// Part of the full library (linemap::linemap), not of the decoder alone.
StatusOr<LayerFidelity> MeasureLayerFidelity(const Grid& original, const LmapVectors& vectors);

StatusOr<LmapVectors> DecodeLmapVectors(const std::vector<std::uint8_t>& bytes,
                                        const DecodeLimits& limits = {});
StatusOr<LmapVectors> LoadLmapVectors(const std::string& path, const DecodeLimits& limits = {});

// What a viewer of a large map reads first: the map's size and frame from
// the file's header, and the file's metadata, without its layers or cells
// (on a 282-Mcell map the layers alone take about 0.2 s to read).
struct LmapHeader {
  int major = 0;
  int minor = 0;
  bool lossless = false;
  int width = 0;   // cells
  int height = 0;  // cells
  MapMetadata meta;
  // The entries of the file's last `meta` chunk (spec/format.md 4.3), key
  // and value, in file order: `creator`, `time`, `frame_id`, `robot_pose`,
  // `tolerance` (ToleranceCellsOf() reads it) and any others.
  std::vector<std::pair<std::string, std::string>> metadata;
};
StatusOr<LmapHeader> DecodeLmapHeader(const std::vector<std::uint8_t>& bytes,
                                      const DecodeLimits& limits = {});
StatusOr<LmapHeader> LoadLmapHeader(const std::string& path, const DecodeLimits& limits = {});
// The T the .lmap file at `path` was saved within, as its header and
// metadata name it (ToleranceCellsOf); nullopt for an exact file or one
// that names none. Reads the file (its CRCs checked) but decodes neither
// layers nor cells.
StatusOr<std::optional<int>> LoadLmapToleranceCells(const std::string& path,
                                                    const DecodeLimits& limits = {});

// The items of the layers whose bounding box (of their points or polygon
// vertices, which holds their cells) meets `window`, in file order, with
// their ids: exactly the items of LoadLmapVectors that meet it, the walls'
// whole-file indices in `wall_indices` (always filled here, one per wall). `window`
// must be non-empty and inside the map (else invalid argument). A file of
// version 2.2 or later reads only the layer sections whose box meets the window (spec 5.6), and
// like DecodeLmapRegion leaves the other sections' streams unchecked; older
// files are read whole and filtered.
StatusOr<LmapVectors> DecodeLmapVectorsInWindow(const std::vector<std::uint8_t>& bytes,
                                                const CellWindow& window,
                                                const DecodeLimits& limits = {});
StatusOr<LmapVectors> LoadLmapVectorsInWindow(const std::string& path, const CellWindow& window,
                                              const DecodeLimits& limits = {});

// One room and its cells: what a viewer shows when the user picks a point.
struct LmapRoom {
  RoomOutline room;   // in the cells of the whole map
  CellWindow window;  // the box of its border chain
  Grid grid;          // the cells of `window`, origin at its lower-left corner
};
// The room holding `cell`: of the rooms whose border chain encloses it
// (spec/format.md section 8.2), the one whose polygon has the smallest area,
// the first in file order on a tie (rooms nest: a corridor's border runs
// around the rooms that open off it, and borders may run over walls and
// enclose obstacles). With the cells of its border's box; nullopt when no
// room's border encloses the cell (unknown space, a file without rooms).
// Reads the layer sections around the cell and the tiles of the box only: on
// the 282-Mcell office map a room loads in milliseconds (a corridor that
// spans the map has the map's box, and its cells are the whole grid). A cell
// outside the map is an invalid argument.
StatusOr<std::optional<LmapRoom>> DecodeLmapRoomAt(const std::vector<std::uint8_t>& bytes,
                                                   CellIndex cell, const DecodeLimits& limits = {});
StatusOr<std::optional<LmapRoom>> LoadLmapRoomAt(const std::string& path, CellIndex cell,
                                                 const DecodeLimits& limits = {});

}  // namespace linemap

#endif  // LINEMAP_LMAP_VECTORS_H_
