// Small pieces of linemap bench: tables, general codecs, timing helpers,
// progress bar, generated maps, SVG helpers.
#include <gtest/gtest.h>
#include <lzma.h>
#include <zstd.h>

#include <cmath>
#include <cstring>
#include <utility>

#include "tools/bench/general_codecs.h"
#include "tools/bench/measure.h"
#include "tools/bench/progress.h"
#include "tools/bench/svg.h"
#include "tools/bench/synthetic.h"
#include "tools/bench/table.h"

namespace linemap::bench {
namespace {

TEST(BenchTableTest, TextMarkdownCsv) {
  Table table({"map", "bytes"});
  table.AddRow({"a|b", "12"});
  table.AddRow({"long,name", "3"});
  EXPECT_EQ(table.Text(),
            "map        bytes\n"
            "---------  -----\n"
            "a|b           12\n"
            "long,name      3\n");
  EXPECT_EQ(table.Markdown(),
            "| map | bytes |\n| --- | ---: |\n| a\\|b | 12 |\n| long,name | 3 |\n");
  EXPECT_EQ(table.Csv(), "map,bytes\na|b,12\n\"long,name\",3\n");
  EXPECT_EQ(CsvField("say \"hi\""), "\"say \"\"hi\"\"\"");
}

TEST(BenchTableTest, LeftAlignedColumnsOfWords) {
  Table table({"goal", "verdict", "ms"});
  table.LeftAlign(1);
  table.AddRow({"a", "PASS", "1.5"});
  table.AddRow({"bb", "INCOMPLETE", "12.25"});
  EXPECT_EQ(table.Text(),
            "goal  verdict        ms\n"
            "----  ----------  -----\n"
            "a     PASS          1.5\n"
            "bb    INCOMPLETE  12.25\n");
  EXPECT_EQ(table.Markdown(),
            "| goal | verdict | ms |\n| --- | --- | ---: |\n| a | PASS | 1.5 |\n"
            "| bb | INCOMPLETE | 12.25 |\n");
}

TEST(BenchTableTest, Formatting) {
  EXPECT_EQ(FormatFixed(1.23456, 2), "1.23");
  EXPECT_EQ(FormatFixed(std::nullopt, 2), "n/a");
  EXPECT_EQ(FormatFixed(std::nan(""), 2), "n/a");
  EXPECT_EQ(FormatCount(1234567.4), "1234567");
}

TEST(BenchMeasureTest, MedianAndRepeats) {
  EXPECT_EQ(Median({3, 1, 2}), 2);
  EXPECT_EQ(Median({4, 1, 3, 2}), 2.5);
  EXPECT_TRUE(std::isnan(Median({})));
  EXPECT_EQ(RepeatsFor(1000, 5), 5);
  EXPECT_EQ(RepeatsFor(2 << 20, 5), 3);
  EXPECT_EQ(RepeatsFor(16 << 20, 5), 1);
  EXPECT_EQ(TimeRuns([] {}, 4).size(), 4u);
}

// Spins for `ms` of the process's CPU time.
void SpinCpuMs(double ms) {
  const auto cpu_ms = [] {
    timespec ts{};
    ::clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return ts.tv_sec * 1e3 + ts.tv_nsec * 1e-6;
  };
  const double start = cpu_ms();
  while (cpu_ms() - start < ms) {
  }
}

TEST(BenchMeasureTest, TwoOperationsAreTimedInBlocks) {
  // Each block starts with an untimed run, and the second round puts the
  // blocks in the other order: a, 3 timed a, b, 3 timed b, b, 2 timed b, a,
  // 2 timed a. (Runs of kMinSampleMs: one run a sample.)
  std::string order;
  const auto a = [&] {
    order += 'a';
    SpinCpuMs(kMinSampleMs);
  };
  const auto b = [&] {
    order += 'b';
    SpinCpuMs(kMinSampleMs);
  };
  const auto [a_ms, b_ms] = TimeRunsInBlocks(a, b, /*repeats=*/5);
  EXPECT_EQ(order, "aaaabbbbbbbaaa");
  EXPECT_EQ(a_ms.size(), 5u);
  EXPECT_EQ(b_ms.size(), 5u);
  order.clear();
  const auto [one_a, one_b] = TimeRunsInBlocks(a, b, /*repeats=*/1);
  EXPECT_EQ(order, "aabb");
  EXPECT_EQ(one_a.size(), 1u);
  EXPECT_EQ(one_b.size(), 1u);
  // A busy operation's runs are its own, not the other's.
  const auto [busy_ms, idle_ms] = TimeRunsInBlocks(
      [] {
        volatile double x = 0;
        for (int i = 0; i < 20'000'000; ++i) x = x + 1e-9 * i;
      },
      [] {}, 2);
  EXPECT_GT(Median(busy_ms), 10 * Median(idle_ms) + 1.0);
}

// A run shorter than kMinSampleMs is timed in loops: a sample is the mean
// of enough runs back to back to reach it, so it is one run's time.
TEST(BenchMeasureTest, ShortRunsAreSampledInLoops) {
  int fast_runs = 0, slow_runs = 0;
  const auto [fast_ms, slow_ms] = TimeRunsInBlocks(
      [&] {
        ++fast_runs;
        SpinCpuMs(0.5);
      },
      [&] {
        ++slow_runs;
        SpinCpuMs(2 * kMinSampleMs);
      },
      /*repeats=*/3);
  EXPECT_EQ(slow_runs, 2 + 3) << "two untimed runs, one run per sample";
  // 0.5 ms a run (more on a loaded machine): up to 20 runs a sample.
  EXPECT_GE(fast_runs, 2 + 3 * 2);
  EXPECT_LE(fast_runs, 2 + 3 * 20);
  ASSERT_EQ(fast_ms.size(), 3u);
  for (double ms : fast_ms) {
    EXPECT_GE(ms, 0.5);
    EXPECT_LT(ms, 2.5);  // a run's time, not a loop's
  }
  for (double ms : slow_ms) EXPECT_GE(ms, 2 * kMinSampleMs);
}

TEST(BenchMeasureTest, PeakMemorySeesATouchedAllocation) {
  constexpr std::size_t kBytes = 32 << 20;
  std::optional<double> peak = PeakExtraMemoryBytes([] {
    char* block = new char[kBytes];
    std::memset(block, 1, kBytes);
    asm volatile("" : : "r"(block) : "memory");
    delete[] block;
  });
  if (!peak) GTEST_SKIP() << "/proc/self/clear_refs is not available here";
  EXPECT_GE(*peak, 0.95 * kBytes);
  EXPECT_LE(*peak, 1.5 * kBytes);
}

TEST(BenchGeneralCodecsTest, ZstdAndXzRoundTrip) {
  Grid grid(100, 50, Cell::kFree);
  for (int c = 0; c < 100; ++c) grid.set(c, 25, Cell::kOccupied);
  grid.set(3, 3, Cell::kUnknown);
  const std::span<const std::uint8_t> raw = RawCells(grid);
  ASSERT_EQ(raw.size(), 5000u);
  EXPECT_EQ(raw[grid.Index(3, 3)], 2);

  StatusOr<std::string> zstd = ZstdCompress(raw, 19);
  ASSERT_TRUE(zstd.ok());
  std::vector<std::uint8_t> back(raw.size());
  EXPECT_EQ(ZSTD_decompress(back.data(), back.size(), zstd->data(), zstd->size()), raw.size());
  EXPECT_TRUE(std::equal(back.begin(), back.end(), raw.begin()));

  StatusOr<std::string> xz = XzCompress(raw, 9);
  ASSERT_TRUE(xz.ok());
  std::uint64_t memlimit = UINT64_MAX;
  std::size_t in_pos = 0, out_pos = 0;
  std::vector<std::uint8_t> back_xz(raw.size());
  ASSERT_EQ(lzma_stream_buffer_decode(&memlimit, 0, nullptr,
                                      reinterpret_cast<const std::uint8_t*>(xz->data()), &in_pos,
                                      xz->size(), back_xz.data(), &out_pos, back_xz.size()),
            LZMA_OK);
  EXPECT_EQ(out_pos, raw.size());
  EXPECT_TRUE(std::equal(back_xz.begin(), back_xz.end(), raw.begin()));
}

TEST(BenchProgressTest, RenderByHand) {
  EXPECT_EQ(ProgressBar::Render(0, 4, "a", 8), "[        ] 0/4 a");
  EXPECT_EQ(ProgressBar::Render(2, 4, "b", 8), "[####    ] 2/4 b");
  EXPECT_EQ(ProgressBar::Render(12, 12, "", 4), "[####] 12/12");
  EXPECT_EQ(ProgressBar::Render(3, 12, "", 4), "[#   ]  3/12");
}

TEST(BenchProgressTest, SilentWhenDisabled) {
  std::FILE* sink = std::tmpfile();
  ASSERT_NE(sink, nullptr);
  {
    ProgressBar bar(3, sink, false);
    bar.Update(1, "x");
  }
  EXPECT_EQ(std::ftell(sink), 0);
  std::fclose(sink);
}

TEST(BenchSyntheticTest, OfficeMapIsDeterministicAndHasAllThreeStates) {
  const Grid a = GenerateOfficeMap(256, 7);
  EXPECT_EQ(a, GenerateOfficeMap(256, 7));
  EXPECT_NE(a, GenerateOfficeMap(256, 8));
  const CellCounts counts = a.Count();
  EXPECT_GT(counts.free, counts.occupied);
  EXPECT_GT(counts.occupied, 0u);
  EXPECT_GT(counts.unknown, 0u);
  EXPECT_EQ(a.at(0, 0), Cell::kUnknown);  // the margin
}

// A map of another shape is the square of its larger side, cut at the
// origin: every cell equal, and the frame kept.
TEST(BenchSyntheticTest, OfficeMapOfSizeIsTheSquaresCorner) {
  const Grid square = GenerateOfficeMap(300, 3);
  for (const auto& [width, height] : {std::pair{300, 120}, std::pair{90, 300}}) {
    const Grid cut = GenerateOfficeMapOfSize(width, height, 3);
    ASSERT_EQ(cut.width(), width);
    ASSERT_EQ(cut.height(), height);
    EXPECT_EQ(cut.meta.resolution, square.meta.resolution);
    for (int r = 0; r < height; ++r) {
      for (int c = 0; c < width; ++c) ASSERT_EQ(cut.at(c, r), square.at(c, r)) << c << "," << r;
    }
  }
  EXPECT_EQ(GenerateOfficeMapOfSize(300, 300, 3), square);
}

TEST(BenchSvgTest, Base64KnownAnswers) {
  EXPECT_EQ(Base64(""), "");
  EXPECT_EQ(Base64("f"), "Zg==");
  EXPECT_EQ(Base64("fo"), "Zm8=");
  EXPECT_EQ(Base64("foo"), "Zm9v");
  EXPECT_EQ(Base64("foobar"), "Zm9vYmFy");
}

TEST(BenchSvgTest, OverlayPutsRowZeroAtTheBottom) {
  Grid grid(10, 4, Cell::kFree);
  // A segment from cell (0,0) to (9,0): the bottom row, SVG y = 4 - 0.5 = 3.5.
  const std::string svg = MapOverlaySvg(grid, {{0, 0, 9, 0}}, nullptr, "t<1>");
  EXPECT_NE(svg.find("<line x1=\"0.50\" y1=\"3.50\" x2=\"9.50\" y2=\"3.50\"/>"), std::string::npos);
  EXPECT_NE(svg.find("<title>t&lt;1&gt;</title>"), std::string::npos);
}

}  // namespace
}  // namespace linemap::bench
