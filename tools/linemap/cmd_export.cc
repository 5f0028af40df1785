// linemap export: not implemented yet (see the open issues).
#include <cstdio>

#include "tools/linemap/commands.h"

namespace linemap::cli {

const CommandSpec kExportSpec = {
    "export",
    "IN.lmap -o OUT.csv|OUT.geojson|OUT.svg",
    "export the layers of an .lmap file as CSV, GeoJSON or SVG",
    "",
    {},
    0,
    1000,
};

int RunExport(const std::vector<std::string>& args) {
  int exit_code = kExitOk;
  if (!ParseArgs(kExportSpec, args, &exit_code)) return exit_code;
  std::fprintf(stderr, "linemap export: not implemented yet in this version\n");
  return kExitFailure;
}

}  // namespace linemap::cli
