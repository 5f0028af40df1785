#include "python/map_files.h"

#include <vector>

#include "format/file_io.h"
#include "linemap/codec.h"
#include "linemap/lmap_vectors.h"
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

LmapFidelity FidelityOfLmapBytes(const std::vector<std::uint8_t>& bytes,
                                 const DecodeLimits& limits) {
  LmapFidelity out;
  const StatusOr<LmapHeader> header = DecodeLmapHeader(bytes, limits);
  if (!header.ok()) return out;
  out.exact = header->lossless;
  out.tolerance = ToleranceCellsOf(header->major, header->lossless, header->metadata);
  return out;
}

StatusOr<LoadedMap> LoadMapAndTolerance(const std::string& path,
                                        const std::optional<CellWindow>& window,
                                        const DecodeLimits& limits) {
  LoadedMap out;
  // .lmap by name in any case or by signature, as load() checks a window's
  // file: a window is never dropped by a map-image read.
  if (!IsLmapFile(path)) {
    LINEMAP_ASSIGN_OR_RETURN(out.grid, LoadMapFile(path, limits));
    return out;
  }
  // As LoadLmap and LoadLmapRegion read it, the header from the same bytes.
  LINEMAP_ASSIGN_OR_RETURN(std::vector<std::uint8_t> bytes,
                           ReadFileBytes(path, limits.max_file_bytes));
  StatusOr<Grid> grid =
      window ? DecodeLmapRegion(bytes, *window, limits) : DecodeLmap(bytes, limits);
  if (!grid.ok()) return grid.status().WithContext("'" + path + "'");
  out.grid = std::move(*grid);
  out.fidelity = FidelityOfLmapBytes(bytes, limits);
  return out;
}

}  // namespace linemap::python
