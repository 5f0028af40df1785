#include "python/map_files.h"

#include <vector>

#include "linemap/codec.h"
#include "linemap/map_io.h"

namespace linemap::python {

bool EndsWith(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() &&
         text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

bool IsYamlPath(const std::string& path) {
  return EndsWith(path, ".yaml") || EndsWith(path, ".yml");
}

StatusOr<Grid> LoadMapFile(const std::string& path, const DecodeLimits& limits) {
  if (IsLmapPath(path)) return LoadLmap(path, limits);
  MapLoadOptions options;
  options.max_cells = limits.max_cells;
  return LoadRosMap(path, options);
}

}  // namespace linemap::python
