// linemap eval: not implemented yet (see the open issues).
#include <cstdio>

#include "tools/linemap/commands.h"

namespace linemap::cli {

const CommandSpec kEvalSpec = {
    "eval",
    "ORIGINAL DECODED_OR_LMAP [--json]",
    "compare a decoded map with the original, cell by cell",
    "",
    {},
    0,
    1000,
};

int RunEval(const std::vector<std::string>& args) {
  int exit_code = kExitOk;
  if (!ParseArgs(kEvalSpec, args, &exit_code)) return exit_code;
  std::fprintf(stderr, "linemap eval: not implemented yet in this version\n");
  return kExitFailure;
}

}  // namespace linemap::cli
