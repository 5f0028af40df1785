// linemap plan: not implemented yet (see the open issues).
#include <cstdio>

#include "tools/linemap/commands.h"

namespace linemap::cli {

const CommandSpec kPlanSpec = {
    "plan",
    "MAP_OR_LMAP --from X,Y[,HEADING] --to X,Y",
    "plan a turn-and-move trajectory on a map",
    "",
    {},
    0,
    1000,
};

int RunPlan(const std::vector<std::string>& args) {
  int exit_code = kExitOk;
  if (!ParseArgs(kPlanSpec, args, &exit_code)) return exit_code;
  std::fprintf(stderr, "linemap plan: not implemented yet in this version\n");
  return kExitFailure;
}

}  // namespace linemap::cli
