#include "python/map_files.h"

#include <cctype>
#include <vector>

#include "linemap/codec.h"
#include "linemap/map_io.h"

namespace linemap::python {

bool EndsWithIgnoringCase(const std::string& text, const std::string& suffix) {
  if (text.size() < suffix.size()) return false;
  const std::size_t start = text.size() - suffix.size();
  for (std::size_t i = 0; i < suffix.size(); ++i) {
    if (std::tolower(static_cast<unsigned char>(text[start + i])) != suffix[i]) return false;
  }
  return true;
}

bool IsYamlPath(const std::string& path) {
  return EndsWithIgnoringCase(path, ".yaml") || EndsWithIgnoringCase(path, ".yml");
}

bool HasLmapName(const std::string& path) { return EndsWithIgnoringCase(path, ".lmap"); }

bool IsLmapFile(const std::string& path) { return HasLmapName(path) || IsLmapPath(path); }

StatusOr<Grid> LoadMapFile(const std::string& path, const DecodeLimits& limits) {
  if (IsLmapPath(path)) return LoadLmap(path, limits);
  MapLoadOptions options;
  options.max_cells = limits.max_cells;
  return LoadRosMap(path, options);
}

}  // namespace linemap::python
