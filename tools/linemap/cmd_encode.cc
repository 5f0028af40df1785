// linemap encode: not implemented yet (see the open issues).
#include <cstdio>

#include "tools/linemap/commands.h"

namespace linemap::cli {

const CommandSpec kEncodeSpec = {
    "encode", "MAP -o OUT.lmap", "compress a map into an .lmap file", "", {}, 0, 1000,
};

int RunEncode(const std::vector<std::string>& args) {
  int exit_code = kExitOk;
  if (!ParseArgs(kEncodeSpec, args, &exit_code)) return exit_code;
  std::fprintf(stderr, "linemap encode: not implemented yet in this version\n");
  return kExitFailure;
}

}  // namespace linemap::cli
