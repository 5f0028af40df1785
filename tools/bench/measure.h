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

// In TimeSamples and TimeRunsInBlocks, a timed sample of an operation under kMinSampleMs is
// the mean of as many runs back to back as reach it (at most kMaxLoops),
// the count set by the block's untimed run: a single sub-millisecond run is
// at the mercy of the machine (nav2 depot's default file decodes in about
// 0.4 ms; in 5 single runs it came out 1.07x faster than libpng, in 21
// 1.75x). Both codecs of a comparison are sampled the same way.
inline constexpr double kMinSampleMs = 10.0;
inline constexpr int kMaxLoops = 100;

// `repeats` such samples of `op` (ms per run), after one untimed run that
// sets the loop count.
std::vector<double> TimeSamples(const std::function<void()>& op, int repeats);

// The pieces of TimeSamples, for callers that take the samples of several
// operations in turns (the scaling table's rounds): the loop count of `op`
// from one untimed run, and one sample of `loops` runs (ms per run).
int SampleLoops(const std::function<void()>& op);
double TimeSample(const std::function<void()>& op, int loops);

// The same for two operations timed in blocks: one untimed run of `a`, then
// half of a's timed samples (rounded up), then the same for `b`; then, with
// `repeats` of 2 or more, b's block before a's for the other half. Each
// block's untimed run adds a run per operation and round (maps of one
// timed run take about twice as long as before). Blocks rather than runs
// taking turns, because a run finds the heap as the previous operation
// left it (which of its buffers come from fresh pages, a page fault per
// 4 kB, and which are reused), and interleaved decodes of one map swung
// up to 3x with it (avz5floor_plan: 0.22 ms alone, 0.66 ms in turn with
// libpng's, libpng's 0.67 and 1.25 ms). The two orders still put a rival
// codec and ours in the same phase of a shared machine. Returns the
// samples of a, then of b (each in ms per run).
std::pair<std::vector<double>, std::vector<double>> TimeRunsInBlocks(const std::function<void()>& a,
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
