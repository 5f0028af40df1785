// Timing and peak-memory measurement of one operation.
#ifndef LINEMAP_TOOLS_BENCH_MEASURE_H_
#define LINEMAP_TOOLS_BENCH_MEASURE_H_

#include <functional>
#include <optional>
#include <utility>
#include <vector>

namespace linemap::bench {

// CPU milliseconds (the process's CPU clock, all threads) of each of
// `repeats` runs of `op`. CPU time rather than wall time: the benchmark
// machines are shared, and another process's load must not show up here.
std::vector<double> TimeRuns(const std::function<void()>& op, int repeats);

// The same for two operations timed in turn, `a` then `b`, then `b` then
// `a`, and so on: a rival codec and ours measured in the same moments, so
// that a slow phase of a shared machine, or what the anchors' processes left
// in the caches, weighs on both alike. Returns the runs of a, then of b.
std::pair<std::vector<double>, std::vector<double>> TimeRunsInTurn(const std::function<void()>& a,
                                                                   const std::function<void()>& b,
                                                                   int repeats);

double Median(std::vector<double> values);  // NaN for an empty list

// The peak resident memory `op` adds, in bytes: `op` runs once in a forked
// child that first returns its free heap to the system (malloc_trim) and
// resets its peak-RSS mark (/proc/self/clear_refs), and the
// result is VmHWM after minus VmRSS before. nullopt when the kernel does not
// allow this (no /proc, no clear_refs) or the child fails.
std::optional<double> PeakExtraMemoryBytes(const std::function<void()>& op);

// How many timed runs a map of `cells` cells gets: `repeats` up to 1 Mcell,
// fewer for bigger maps so that a whole-corpus run stays short.
int RepeatsFor(std::size_t cells, int repeats);

}  // namespace linemap::bench

#endif  // LINEMAP_TOOLS_BENCH_MEASURE_H_
