// linemap decode: not implemented yet (see the open issues).
#include <cstdio>

#include "tools/linemap/commands.h"

namespace linemap::cli {

const CommandSpec kDecodeSpec = {
    "decode", "IN.lmap -o OUT.yaml", "decode an .lmap file into a ROS map (YAML + PGM)", "", {}, 0,
    1000,
};

int RunDecode(const std::vector<std::string>& args) {
  int exit_code = kExitOk;
  if (!ParseArgs(kDecodeSpec, args, &exit_code)) return exit_code;
  std::fprintf(stderr, "linemap decode: not implemented yet in this version\n");
  return kExitFailure;
}

}  // namespace linemap::cli
