#include "tools/bench/jbig.h"

#include <gtest/gtest.h>

#include "format/file_io.h"
#include "tests/testing/test_support.h"
#include "tools/bench/subprocess.h"

namespace linemap::bench {
namespace {

Grid SmallGrid() {
  // Grid row 1 (top image row): free occupied unknown ... ; 10 columns so a
  // row takes two PBM bytes.
  Grid grid(10, 2, Cell::kUnknown);
  grid.set(0, 1, Cell::kFree);
  grid.set(1, 1, Cell::kOccupied);
  grid.set(9, 1, Cell::kFree);
  grid.set(0, 0, Cell::kOccupied);
  grid.set(8, 0, Cell::kOccupied);
  return grid;
}

TEST(BenchJbigTest, PbmPlanesByHand) {
  const Grid grid = SmallGrid();
  // Not free: top row columns 1-8 (0 and 9 are free), bottom row all ten.
  EXPECT_EQ(PbmPlane(grid, BitPlane::kNotFree), std::string("P4\n10 2\n\x7f\x80\xff\xc0", 12));
  EXPECT_EQ(PbmPlane(grid, BitPlane::kOccupied), std::string("P4\n10 2\n\x40\x00\x80\x80", 12));
}

TEST(BenchJbigTest, RoundTripThroughJbigKit) {
  if (!ToolAvailable("pbmtojbg") || !ToolAvailable("jbgtopbm")) {
    GTEST_SKIP() << "jbigkit-bin (pbmtojbg, jbgtopbm) is not installed";
  }
  const Grid grid = SmallGrid();
  for (BitPlane plane : {BitPlane::kNotFree, BitPlane::kOccupied}) {
    const std::string pbm = PbmPlane(grid, plane);
    StatusOr<std::string> jbg = JbigEncodePbm(pbm);
    ASSERT_TRUE(jbg.ok()) << jbg.status().message();
    const std::string dir = linemap::testing::MakeTempDir("bench-jbig");
    ASSERT_TRUE(WriteFileAtomic(dir + "/p.jbg", *jbg).ok());
    StatusOr<int> code = RunSubprocess({"jbgtopbm", dir + "/p.jbg", dir + "/p.pbm"});
    ASSERT_TRUE(code.ok()) << code.status().message();
    ASSERT_EQ(*code, 0);
    // jbgtopbm lays out the header its own way; the 2 x 2 bytes of pixels
    // at the end must be ours.
    const std::string decoded = linemap::testing::ReadFile(dir + "/p.pbm");
    ASSERT_GE(decoded.size(), 4u);
    EXPECT_EQ(decoded.substr(0, 2), "P4");
    EXPECT_EQ(decoded.substr(decoded.size() - 4), pbm.substr(pbm.size() - 4));
  }
  StatusOr<JbigSizes> sizes = JbigTwoPlaneSizes(grid);
  ASSERT_TRUE(sizes.ok());
  EXPECT_GT(sizes->not_free_plane, 0u);
  EXPECT_EQ(sizes->total(), sizes->not_free_plane + sizes->occupied_plane);
}

TEST(BenchJbigTest, AMissingEncoderIsReported) {
  JbigOptions options;
  options.encoder = "linemap-no-such-jbig-encoder";
  StatusOr<JbigSizes> sizes = JbigTwoPlaneSizes(SmallGrid(), options);
  ASSERT_FALSE(sizes.ok());
  EXPECT_EQ(sizes.status().code(), StatusCode::kNotFound);
}

TEST(BenchSubprocessTest, ExitCodesAndScratchCleanup) {
  StatusOr<int> ok = RunSubprocess({"sh", "-c", "exit 3"});
  ASSERT_TRUE(ok.ok());
  EXPECT_EQ(*ok, 3);
  std::string path;
  {
    StatusOr<ScratchDir> dir = ScratchDir::Create("test");
    ASSERT_TRUE(dir.ok());
    path = dir->path();
    EXPECT_TRUE(linemap::testing::FileExists(path));
  }
  EXPECT_FALSE(linemap::testing::FileExists(path));
}

}  // namespace
}  // namespace linemap::bench
