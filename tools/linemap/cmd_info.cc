// linemap info MAP [--json]: size, resolution, origin and cell counts.
#include <cstdio>

#include "tools/linemap/commands.h"
#include "tools/linemap/json.h"
#include "tools/linemap/map_input.h"

namespace linemap::cli {

const CommandSpec kInfoSpec = {
    "info",
    "MAP [--json]",
    "print a map's size, resolution, origin and free / occupied / unknown cell counts",
    "MAP is a ROS map YAML (its image: PGM or PNG) or a bare PGM/PNG image, which\n"
    "gets the defaults 0.05 m/cell, origin 0,0,0 and thresholds 0.65 / 0.196.",
    WithMapLoadOptions({{"--json", "",
                         "print one JSON object with keys width, height, "
                         "resolution, origin, free, occupied, unknown"}}),
    1,
    1,
};

int RunInfo(const std::vector<std::string>& args) {
  int exit_code = kExitOk;
  std::optional<ParsedArgs> parsed = ParseArgs(kInfoSpec, args, &exit_code);
  if (!parsed) return exit_code;
  StatusOr<Grid> grid = LoadMapArgument(parsed->positional[0], *parsed);
  if (!grid.ok()) return ReportError("info", grid.status());
  const CellCounts counts = grid->Count();
  const MapMetadata& meta = grid->meta;
  if (parsed->Has("--json")) {
    JsonObject json;
    json.Add("width", grid->width())
        .Add("height", grid->height())
        .Add("resolution", meta.resolution)
        .Add("origin", std::vector<double>{meta.origin.x, meta.origin.y, meta.origin.yaw})
        .Add("free", std::uint64_t{counts.free})
        .Add("occupied", std::uint64_t{counts.occupied})
        .Add("unknown", std::uint64_t{counts.unknown})
        .Add("mode", MapModeName(meta.mode))
        .Add("negate", meta.negate)
        .Add("occupied_thresh", meta.occupied_thresh)
        .Add("free_thresh", meta.free_thresh);
    std::printf("%s\n", json.str().c_str());
    return kExitOk;
  }
  const double total = static_cast<double>(grid->size());
  auto share = [total](std::size_t n) { return total > 0 ? 100.0 * n / total : 0.0; };
  std::printf("map:        %s\n", parsed->positional[0].c_str());
  std::printf("size:       %d x %d cells (%.2f x %.2f m)\n", grid->width(), grid->height(),
              grid->width() * meta.resolution, grid->height() * meta.resolution);
  std::printf("resolution: %g m/cell\n", meta.resolution);
  std::printf("origin:     x %g m, y %g m, yaw %g rad\n", meta.origin.x, meta.origin.y,
              meta.origin.yaw);
  std::printf("pixels:     mode %s, negate %d, occupied_thresh %g, free_thresh %g\n",
              MapModeName(meta.mode), meta.negate ? 1 : 0, meta.occupied_thresh, meta.free_thresh);
  std::printf("free:       %zu (%.1f%%)\n", counts.free, share(counts.free));
  std::printf("occupied:   %zu (%.1f%%)\n", counts.occupied, share(counts.occupied));
  std::printf("unknown:    %zu (%.1f%%)\n", counts.unknown, share(counts.unknown));
  return kExitOk;
}

}  // namespace linemap::cli
