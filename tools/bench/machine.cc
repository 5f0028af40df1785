#include "tools/bench/machine.h"

#include <sys/utsname.h>
#include <unistd.h>

#include <fstream>

namespace linemap::bench {
namespace {

std::string ProcField(const char* file, const std::string& field) {
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line)) {
    if (line.compare(0, field.size(), field) != 0) continue;
    const std::size_t colon = line.find(':');
    if (colon == std::string::npos) continue;
    std::string value = line.substr(colon + 1);
    value.erase(0, value.find_first_not_of(" \t"));
    return value;
  }
  return "";
}

}  // namespace

std::string MachineDescription() {
  std::string cpu = ProcField("/proc/cpuinfo", "model name");
  if (cpu.empty()) cpu = "unknown CPU";
  const long cores = ::sysconf(_SC_NPROCESSORS_ONLN);
  std::string memory = ProcField("/proc/meminfo", "MemTotal");
  std::string text = cpu + ", " + std::to_string(cores) + " cores";
  if (!memory.empty()) {
    const long long kb = std::atoll(memory.c_str());
    text += ", " + std::to_string((kb + 512 * 1024) / (1024 * 1024)) + " GB RAM";
  }
  struct utsname uts;
  if (::uname(&uts) == 0) text += ", " + std::string(uts.sysname) + " " + uts.release;
#if defined(__clang__)
  text += ", clang " __clang_version__;
#elif defined(__GNUC__)
  text += ", gcc " __VERSION__;
#endif
#ifdef NDEBUG
  text += ", optimised build";
#else
  text += ", debug build (assertions on)";
#endif
  return text;
}

}  // namespace linemap::bench
