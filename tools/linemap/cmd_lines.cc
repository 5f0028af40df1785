// linemap lines: not implemented yet (see the open issues).
#include <cstdio>

#include "tools/linemap/commands.h"

namespace linemap::cli {

const CommandSpec kLinesSpec = {
    "lines",
    "MAP -o LINES.csv",
    "extract wall line segments from a map (RM-Line or linemap's extractor)",
    "",
    {},
    0,
    1000,
};

int RunLines(const std::vector<std::string>& args) {
  int exit_code = kExitOk;
  if (!ParseArgs(kLinesSpec, args, &exit_code)) return exit_code;
  std::fprintf(stderr, "linemap lines: not implemented yet in this version\n");
  return kExitFailure;
}

}  // namespace linemap::cli
