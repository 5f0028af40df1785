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

// The codec allocates grid-sized arrays and frees them again: the checks of
// a file saved within a tolerance, round after round. glibc serves arrays
// over 32 MB (a 32-Mcell grid) by mmap and returns them to the kernel when
// freed, so every such array of a large map is faulted in and zeroed afresh:
// `encode --tolerance 1` of a generated 6000 x 6000 office map takes 81 s
// (24 s of it in the kernel) without the settings below and 56 s with them.
// (An exact file of a map over 4096 cells a side is coded a band at a time
// and gains nothing: 8.4-8.6 s either way on the 282-Mcell office map.) Raising the mmap and trim
// thresholds keeps freed arrays in the heap for reuse; one arena keeps the encoder's second thread
// from mapping its own (a thread arena's heaps hold at most 64 MB, so larger
// arrays were mapped afresh there whatever the threshold). Process-wide
// settings, so they belong to the program, not the library (README: "Large
// maps").
void KeepLargeArraysForReuse() {
#if defined(__GLIBC__)
  constexpr int kOneGiB = 1 << 30;
  // Older glibc refuses a threshold over half its heap size (32 MiB on
  // 64-bit machines, 512 KiB on 32-bit ones): the largest it takes, halving
  // down to its default of 128 KiB.
  for (int bytes = kOneGiB; bytes >= 128 * 1024 && mallopt(M_MMAP_THRESHOLD, bytes) == 0;) {
    bytes /= 2;
  }
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
