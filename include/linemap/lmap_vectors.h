// The vector layers of an .lmap file, read without decoding the raster:
// what a viewer, a planner or a GIS takes from the file.
//
// Geometry is on the integer cell lattice (the centre of cell (col, row) is
// the point (col, row), row 0 at the origin); ToWorld() gives map-frame
// metres as Grid::CellToWorld does.
#ifndef LINEMAP_LMAP_VECTORS_H_
#define LINEMAP_LMAP_VECTORS_H_

#include <cstdint>
#include <string>
#include <vector>

#include "linemap/cells.h"
#include "linemap/vector_layers.h"
#include "linemap/codec.h"
#include "linemap/grid.h"
#include "linemap/status.h"

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

  // Map-frame metres of a lattice point.
  void ToWorld(const CellIndex& p, double* x, double* y) const;
};

StatusOr<LmapVectors> DecodeLmapVectors(const std::vector<std::uint8_t>& bytes,
                                        const DecodeLimits& limits = {});
StatusOr<LmapVectors> LoadLmapVectors(const std::string& path, const DecodeLimits& limits = {});

}  // namespace linemap

#endif  // LINEMAP_LMAP_VECTORS_H_
