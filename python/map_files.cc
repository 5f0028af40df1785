#include "python/map_files.h"

#include <vector>

#include "format/file_io.h"
#include "linemap/codec.h"
#include "linemap/map_io.h"

namespace linemap::python {

bool IsYamlPath(const std::string& path) {
  return HasExtension(path, ".yaml") || HasExtension(path, ".yml");
}

bool HasLmapName(const std::string& path) { return HasExtension(path, ".lmap"); }

bool IsLmapFile(const std::string& path) { return HasLmapName(path) || IsLmapPath(path); }

StatusOr<Grid> LoadMapFile(const std::string& path, const DecodeLimits& limits) {
  if (IsLmapPath(path)) return LoadLmap(path, limits);
  MapLoadOptions options;
  options.max_cells = limits.max_cells;
  return LoadRosMap(path, options);
}

}  // namespace linemap::python
