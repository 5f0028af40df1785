// A map of more than 2^28 cells (16,500 x 16,500 = 272 Mcells, past the
// largest map nav2 users reported) through the whole path a robot's map
// takes: encoded to an .lmap file, decoded band by band to YAML + PGM
// (DecodeLmapToRosMap), and the PGM loaded back row by row (LoadRosMap).
// The cell counts are checked against the pattern's own counts, and the
// reloaded grid against the original cell for cell.
//
// Slow (28 s on 2 cores, 0.8 GB peak, measured with /usr/bin/time -v
// build/tests/codec_tests --gtest_filter='HugeMap*'): it runs in CI as its
// own ctest entry (gtest_discover_tests gives each test one, under
// run_tests.sh's 600 s timeout); LINEMAP_SKIP_HUGE_TEST=1 skips it locally. Skipped under the
// sanitizers, whose tenfold slowdown would not fit the suite's timeout.
#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "linemap/codec.h"
#include "linemap/map_io.h"
#include "tests/testing/test_support.h"

#if defined(__SANITIZE_ADDRESS__)
#define LINEMAP_HUGE_TEST_SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define LINEMAP_HUGE_TEST_SANITIZED 1
#endif
#endif

namespace linemap {
namespace {

constexpr int kSide = 16500;
constexpr int kWallPeriod = 100;   // a wall on every 100th row and column
constexpr int kUnknownBand = 250;  // the lowest rows and leftmost columns are unexplored

// The pattern, cell by cell: offices of 99 x 99 free cells between one-cell
// walls, and an unexplored L along the bottom and left edges.
Cell Pattern(int col, int row) {
  if (col < kUnknownBand || row < kUnknownBand) return Cell::kUnknown;
  if (col % kWallPeriod == 0 || row % kWallPeriod == 0) return Cell::kOccupied;
  return Cell::kFree;
}

// The grid of Pattern, built row by row from the two kinds of rows it has
// above the unknown band (cheap: 272 MB of row copies).
Grid PatternGrid() {
  Grid grid(kSide, kSide, Cell::kUnknown);
  grid.meta.resolution = 0.05;
  grid.meta.origin = {-412.5, -10.0, 0.0};
  std::vector<Cell> wall_row(kSide), room_row(kSide);
  for (int c = 0; c < kSide; ++c) {
    wall_row[c] = Pattern(c, kWallPeriod * 3);
    room_row[c] = Pattern(c, kWallPeriod * 3 + 1);
  }
  for (int r = kUnknownBand; r < kSide; ++r) {
    const std::vector<Cell>& row = r % kWallPeriod == 0 ? wall_row : room_row;
    std::memcpy(grid.mutable_cells().data() + grid.Index(0, r), row.data(), kSide);
  }
  return grid;
}

// The pattern's counts straight from Pattern(), cell by cell.
CellCounts PatternCounts() {
  CellCounts counts;
  for (int r = 0; r < kSide; ++r) {
    for (int c = 0; c < kSide; ++c) {
      switch (Pattern(c, r)) {
        case Cell::kFree:
          ++counts.free;
          break;
        case Cell::kOccupied:
          ++counts.occupied;
          break;
        case Cell::kUnknown:
          ++counts.unknown;
          break;
      }
    }
  }
  return counts;
}

void ExpectCounts(const CellCounts& got, const CellCounts& want, const char* what) {
  EXPECT_EQ(got.free, want.free) << what;
  EXPECT_EQ(got.occupied, want.occupied) << what;
  EXPECT_EQ(got.unknown, want.unknown) << what;
}

TEST(HugeMapTest, MapAbove2To28CellsRoundTripsThroughFiles) {
  const char* skip = std::getenv("LINEMAP_SKIP_HUGE_TEST");
  if (skip != nullptr && std::string(skip) == "1") {
    GTEST_SKIP() << "LINEMAP_SKIP_HUGE_TEST=1";
  }
#ifdef LINEMAP_HUGE_TEST_SANITIZED
  GTEST_SKIP() << "runs in the optimized build only (too slow under the sanitizers)";
#endif
  const CellCounts want = PatternCounts();
  ASSERT_GT(std::uint64_t{kSide} * kSide, std::uint64_t{1} << 28);
  const std::string dir = testing::MakeTempDir("huge_map");
  {
    const Grid grid = PatternGrid();
    ExpectCounts(grid.Count(), want, "the built grid");
    // The default file: walls, rooms and furniture besides the cells.
    ASSERT_TRUE(SaveLmap(dir + "/huge.lmap", grid).ok());
  }
  StatusOr<MapFileSummary> written =
      DecodeLmapToRosMap(dir + "/huge.lmap", dir + "/huge.yaml", {}, Durability::kUnsynced);
  ASSERT_TRUE(written.ok()) << written.status().message();
  EXPECT_EQ(written->width, kSide);
  EXPECT_EQ(written->height, kSide);
  ExpectCounts(written->counts, want, "the decode's counts");

  StatusOr<Grid> reloaded = LoadRosMap(dir + "/huge.yaml");
  ASSERT_TRUE(reloaded.ok()) << reloaded.status().message();
  ASSERT_EQ(reloaded->width(), kSide);
  ASSERT_EQ(reloaded->height(), kSide);
  EXPECT_DOUBLE_EQ(reloaded->meta.origin.x, -412.5);
  ExpectCounts(reloaded->Count(), want, "the PGM read back");
  const Grid original = PatternGrid();
  EXPECT_TRUE(reloaded->cells() == original.cells()) << "the PGM differs from the input";
}

}  // namespace
}  // namespace linemap
