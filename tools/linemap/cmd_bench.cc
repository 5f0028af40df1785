// linemap bench: not implemented yet (see the open issues).
#include <cstdio>

#include "tools/linemap/commands.h"

namespace linemap::cli {

const CommandSpec kBenchSpec = {
    "bench",
    "[CORPUS_DIR ...]",
    "benchmark size, fidelity and speed against PNG and other codecs",
    "",
    {},
    0,
    1000,
};

int RunBench(const std::vector<std::string>& args) {
  int exit_code = kExitOk;
  if (!ParseArgs(kBenchSpec, args, &exit_code)) return exit_code;
  std::fprintf(stderr, "linemap bench: not implemented yet in this version\n");
  return kExitFailure;
}

}  // namespace linemap::cli
