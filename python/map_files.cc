#include "python/map_files.h"

#include <fstream>
#include <vector>

#include "linemap/codec.h"
#include "linemap/map_io.h"

namespace linemap::python {

bool EndsWith(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() &&
         text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

bool IsLmapPath(const std::string& path) {
  if (EndsWith(path, ".lmap")) return true;
  std::ifstream in(path, std::ios::binary);
  std::vector<std::uint8_t> head(8, 0);
  in.read(reinterpret_cast<char*>(head.data()), 8);
  return in.gcount() == 8 && LooksLikeLmap(head);
}

bool IsYamlPath(const std::string& path) {
  return EndsWith(path, ".yaml") || EndsWith(path, ".yml");
}

StatusOr<Grid> LoadMapFile(const std::string& path, std::uint64_t max_cells) {
  if (IsLmapPath(path)) {
    DecodeLimits limits;
    limits.max_cells = max_cells;
    return LoadLmap(path, limits);
  }
  MapLoadOptions options;
  options.max_cells = max_cells;
  return LoadRosMap(path, options);
}

}  // namespace linemap::python
