// How the module tells map files apart, as the CLI does
// (tools/linemap/map_input.cc): .lmap files by name or signature, map YAML
// by name, anything else as a bare image. Names are matched in any case
// ("MAP.LMAP", "Map.Yaml"), as the library's map readers and the CLI's
// output checks match them.
#ifndef LINEMAP_PYTHON_MAP_FILES_H_
#define LINEMAP_PYTHON_MAP_FILES_H_

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "linemap/codec.h"
#include "linemap/grid.h"
#include "linemap/status.h"

namespace linemap::python {

// A name ending in .yaml or .yml, in any case.
bool IsYamlPath(const std::string& path);

// A name ending in .lmap, in any case (whether or not the file exists).
bool HasLmapName(const std::string& path);

// An .lmap file by its name (HasLmapName) or, for a file that exists, by
// its signature (IsLmapPath).
bool IsLmapFile(const std::string& path);

// An .lmap file within `limits`, or a map YAML or bare image refused beyond
// limits.max_cells cells. Runs without the GIL.
StatusOr<Grid> LoadMapFile(const std::string& path, const DecodeLimits& limits);

// What an .lmap file says of its cells: exact (the robot's map), or not,
// with the tolerance it was saved within when it names one
// (ToleranceCellsOf).
struct LmapFidelity {
  bool exact = true;
  std::optional<int> tolerance;
};

// A map file as load() reads it: its grid (for an .lmap file, only the
// cells of `window` when one is given) and, for an .lmap file, what it says
// of its cells (any other map is exact), both from one read of the file.
// Runs without the GIL.
struct LoadedMap {
  Grid grid;
  LmapFidelity fidelity;
};
StatusOr<LoadedMap> LoadMapAndTolerance(const std::string& path,
                                        const std::optional<CellWindow>& window,
                                        const DecodeLimits& limits);

// What the .lmap `bytes` say of their cells, read from their header; for
// bytes a decode has already checked.
LmapFidelity FidelityOfLmapBytes(const std::vector<std::uint8_t>& bytes,
                                 const DecodeLimits& limits);

}  // namespace linemap::python

#endif  // LINEMAP_PYTHON_MAP_FILES_H_
