#include "tools/bench/measure.h"

#include <malloc.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <fstream>
#include <string>

namespace linemap::bench {
namespace {

// A "VmXXX:  1234 kB" field of /proc/self/status in bytes, or -1.
long long ProcStatusBytes(const char* field) {
  std::ifstream in("/proc/self/status");
  std::string line;
  const std::size_t n = std::strlen(field);
  while (std::getline(in, line)) {
    if (line.compare(0, n, field) == 0 && line.size() > n && line[n] == ':') {
      return std::atoll(line.c_str() + n + 1) * 1024;
    }
  }
  return -1;
}

bool ResetPeakRss() {
  std::FILE* f = std::fopen("/proc/self/clear_refs", "w");
  if (!f) return false;
  const bool ok = std::fputs("5", f) >= 0;
  return std::fclose(f) == 0 && ok;
}

double CpuMs() {
  timespec ts{};
  ::clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return ts.tv_sec * 1e3 + ts.tv_nsec * 1e-6;
}

double TimeOnce(const std::function<void()>& op) {
  const double start = CpuMs();
  op();
  return CpuMs() - start;
}

// Runs per timed sample for an operation that took `once_ms`: enough for
// kMinSampleMs, at most kMaxLoops.
int LoopsFor(double once_ms) {
  if (!(once_ms > 0)) return kMaxLoops;
  return static_cast<int>(std::clamp(std::ceil(kMinSampleMs / once_ms), 1.0, double{kMaxLoops}));
}

}  // namespace

double TimeSample(const std::function<void()>& op, int loops) {
  const double start = CpuMs();
  for (int i = 0; i < loops; ++i) op();
  return (CpuMs() - start) / loops;
}

int SampleLoops(const std::function<void()>& op) { return LoopsFor(TimeOnce(op)); }

std::vector<double> TimeRuns(const std::function<void()>& op, int repeats) {
  std::vector<double> ms;
  for (int i = 0; i < std::max(1, repeats); ++i) ms.push_back(TimeOnce(op));
  return ms;
}

std::vector<double> TimeSamples(const std::function<void()>& op, int repeats) {
  const int loops = SampleLoops(op);  // also settles the heap for `op`; not counted
  std::vector<double> ms;
  for (int i = 0; i < std::max(1, repeats); ++i) ms.push_back(TimeSample(op, loops));
  return ms;
}

std::pair<std::vector<double>, std::vector<double>> TimeRunsInBlocks(const std::function<void()>& a,
                                                                     const std::function<void()>& b,
                                                                     int repeats) {
  std::pair<std::vector<double>, std::vector<double>> ms;
  const int total = std::max(1, repeats);
  const auto block = [](const std::function<void()>& op, int runs, std::vector<double>* out) {
    const std::vector<double> ms = TimeSamples(op, runs);
    out->insert(out->end(), ms.begin(), ms.end());
  };
  const int first_half = (total + 1) / 2, second_half = total / 2;
  block(a, first_half, &ms.first);
  block(b, first_half, &ms.second);
  if (second_half > 0) {
    block(b, second_half, &ms.second);
    block(a, second_half, &ms.first);
  }
  return ms;
}

double Median(std::vector<double> values) {
  if (values.empty()) return std::nan("");
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

std::optional<double> PeakExtraMemoryBytes(const std::function<void()>& op) {
  std::fflush(nullptr);
  int fds[2];
  if (::pipe(fds) != 0) return std::nullopt;
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    return std::nullopt;
  }
  if (pid == 0) {
    ::close(fds[0]);
    long long result = -1;
    // Give the parent's free heap pages back first: they are resident, so
    // reusing them would hide the operation's memory from the RSS figures.
    ::malloc_trim(0);
    if (ResetPeakRss()) {
      const long long before = ProcStatusBytes("VmRSS");
      op();
      const long long peak = ProcStatusBytes("VmHWM");
      if (before >= 0 && peak >= 0) result = std::max(0LL, peak - before);
    }
    const ssize_t written = ::write(fds[1], &result, sizeof result);
    _exit(written == sizeof result ? 0 : 1);
  }
  ::close(fds[1]);
  long long result = -1;
  const ssize_t got = ::read(fds[0], &result, sizeof result);
  ::close(fds[0]);
  int status = 0;
  ::waitpid(pid, &status, 0);
  if (got != sizeof result || result < 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    return std::nullopt;
  }
  return static_cast<double>(result);
}

int RepeatsFor(std::size_t cells, int repeats) {
  if (cells > (std::size_t{4} << 20)) return 1;
  if (cells > (std::size_t{1} << 20)) return std::min(repeats, 3);
  return repeats;
}

}  // namespace linemap::bench
