// linemap: compress occupancy-grid maps into line-segment files and back.
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include "tools/linemap/cli.h"
#include "tools/linemap/commands.h"

namespace linemap::cli {

const std::vector<CommandEntry>& Commands() {
  static const std::vector<CommandEntry> kCommands = {
      {&kInfoSpec, RunInfo},   {&kEncodeSpec, RunEncode},   {&kDecodeSpec, RunDecode},
      {&kLinesSpec, RunLines}, {&kSegmentSpec, RunSegment}, {&kExportSpec, RunExport},
      {&kEvalSpec, RunEval},   {&kPlanSpec, RunPlan},       {&kBenchSpec, RunBench},
  };
  return kCommands;
}

namespace {

void PrintUsage(std::FILE* out) {
  std::fprintf(out,
               "Usage: linemap <command> [options]\n\n"
               "Compresses ROS occupancy-grid maps into compact .lmap line-segment files and\n"
               "reloads them as grids.\n\nCommands:\n");
  for (const CommandEntry& entry : Commands()) {
    std::fprintf(out, "  %-9s %s\n", entry.spec->name.c_str(), entry.spec->summary.c_str());
  }
  std::fprintf(out,
               "\n'linemap <command> --help' describes a command. 'linemap --version' prints "
               "the version.\nExit status: 0 success, 1 failure while working, 2 bad usage or "
               "bad input.\n");
}

// The codec allocates grid-sized arrays and frees them again (measured with
// the former lossy 1.0 encoder, a few per candidate file; not re-measured
// with the 2.x encoder, which codes maps over 4096 cells a side a band at a
// time).
// glibc serves arrays over 32 MB (a 32-Mcell grid) by mmap and returns them
// to the kernel when freed, so every such array of a large map is faulted in
// and zeroed afresh: 64-Mcell encodes with that encoder spent about 7 % of
// their time in page faults. Raising the mmap and trim thresholds keeps freed
// arrays in the heap for reuse; one arena keeps the encoder's second thread
// from mapping its own (a thread arena's heaps hold at most 64 MB, so larger
// arrays were mapped afresh there whatever the threshold). Process-wide
// settings, so they belong to the program, not the library (README: "Large
// maps").
void KeepLargeArraysForReuse() {
#if defined(__GLIBC__)
  constexpr int kOneGiB = 1 << 30;
  mallopt(M_MMAP_THRESHOLD, kOneGiB);
  mallopt(M_TRIM_THRESHOLD, kOneGiB);
  mallopt(M_ARENA_MAX, 1);
#endif
}

}  // namespace
}  // namespace linemap::cli

int main(int argc, char** argv) {
  using namespace linemap::cli;
  if (argc < 2) {
    PrintUsage(stderr);
    return kExitBadInput;
  }
  const std::string command = argv[1];
  if (command == "--help" || command == "-h" || command == "help") {
    PrintUsage(stdout);
    return kExitOk;
  }
  if (command == "--version") {
    std::printf("linemap %s\n", LINEMAP_VERSION_STRING);
    return kExitOk;
  }
  KeepLargeArraysForReuse();
  const std::vector<std::string> args(argv + 2, argv + argc);
  for (const CommandEntry& entry : Commands()) {
    if (entry.spec->name == command) return entry.run(args);
  }
  std::fprintf(stderr, "linemap: unknown command '%s' (see 'linemap --help')\n", command.c_str());
  return kExitBadInput;
}
