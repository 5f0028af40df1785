// One line describing the machine a benchmark ran on (CPU, cores, memory,
// kernel, compiler), so that published figures say where they came from.
#ifndef LINEMAP_TOOLS_BENCH_MACHINE_H_
#define LINEMAP_TOOLS_BENCH_MACHINE_H_

#include <string>

namespace linemap::bench {

std::string MachineDescription();

}  // namespace linemap::bench

#endif  // LINEMAP_TOOLS_BENCH_MACHINE_H_
