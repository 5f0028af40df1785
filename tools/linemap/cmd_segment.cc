// linemap segment: not implemented yet (see the open issues).
#include <cstdio>

#include "tools/linemap/commands.h"

namespace linemap::cli {

const CommandSpec kSegmentSpec = {
    "segment", "MAP -o OUT.json", "find room-border chains and furniture blobs", "", {}, 0, 1000,
};

int RunSegment(const std::vector<std::string>& args) {
  int exit_code = kExitOk;
  if (!ParseArgs(kSegmentSpec, args, &exit_code)) return exit_code;
  std::fprintf(stderr, "linemap segment: not implemented yet in this version\n");
  return kExitFailure;
}

}  // namespace linemap::cli
