#include "tools/bench/png_codec.h"

#include <gtest/gtest.h>

#include <cstdint>

#include "format/image.h"

namespace linemap::bench {
namespace {

Grid RandomGrid(int width, int height, std::uint32_t seed) {
  Grid grid(width, height);
  std::uint32_t state = seed;
  for (Cell& cell : grid.mutable_cells()) {
    state = state * 1664525u + 1013904223u;
    cell = static_cast<Cell>((state >> 16) % 3);
  }
  return grid;
}

std::span<const std::uint8_t> Bytes(const std::string& s) {
  return {reinterpret_cast<const std::uint8_t*>(s.data()), s.size()};
}

class PngLayoutTest : public ::testing::TestWithParam<PngLayout> {};

TEST_P(PngLayoutTest, RoundTripsThroughLibpng) {
  // Odd widths exercise the 2-bit packing of a row's last byte.
  for (int width : {1, 3, 4, 5, 17}) {
    const Grid grid = RandomGrid(width, 7, static_cast<std::uint32_t>(width));
    StatusOr<std::string> png = EncodeTrinaryPng(grid, GetParam(), 9);
    ASSERT_TRUE(png.ok()) << png.status().message();
    StatusOr<Grid> back = DecodeTrinaryPng(Bytes(*png));
    ASSERT_TRUE(back.ok()) << back.status().message();
    EXPECT_EQ(back->cells(), grid.cells()) << "width " << width;
  }
}

TEST_P(PngLayoutTest, PixelsAreMapSaverValuesTopRowFirst) {
  // Read back with the library's own PNG reader (independent of the writer):
  // grid row 0 is the bottom image row; free 254, occupied 0, unknown 205.
  Grid grid(2, 2);
  grid.set(0, 0, Cell::kFree);
  grid.set(1, 0, Cell::kOccupied);
  grid.set(0, 1, Cell::kUnknown);
  grid.set(1, 1, Cell::kFree);
  StatusOr<std::string> png = EncodeTrinaryPng(grid, GetParam(), 9);
  ASSERT_TRUE(png.ok());
  StatusOr<RawImage> image = DecodePng(Bytes(*png), "test", 100);
  ASSERT_TRUE(image.ok()) << image.status().message();
  ASSERT_EQ(image->width, 2);
  ASSERT_EQ(image->height, 2);
  auto grey = [&](int x, int y) { return image->pixel(x, y)[0] / 257; };
  EXPECT_EQ(grey(0, 0), 205);  // top row = grid row 1
  EXPECT_EQ(grey(1, 0), 254);
  EXPECT_EQ(grey(0, 1), 254);
  EXPECT_EQ(grey(1, 1), 0);
}

INSTANTIATE_TEST_SUITE_P(AllLayouts, PngLayoutTest,
                         ::testing::Values(PngLayout::kGrey8, PngLayout::kPalette8,
                                           PngLayout::kPalette2));

TEST(BenchPngCodecTest, HeaderSaysTheLayout) {
  const Grid grid = RandomGrid(9, 4, 1);
  // IHDR bytes 24 and 25 of the file: bit depth and colour type.
  StatusOr<std::string> two = EncodeTrinaryPng(grid, PngLayout::kPalette2, 9);
  ASSERT_TRUE(two.ok());
  EXPECT_EQ(static_cast<int>((*two)[24]), 2);
  EXPECT_EQ(static_cast<int>((*two)[25]), 3);  // palette
  StatusOr<std::string> grey = EncodeTrinaryPng(grid, PngLayout::kGrey8, 9);
  ASSERT_TRUE(grey.ok());
  EXPECT_EQ(static_cast<int>((*grey)[24]), 8);
  EXPECT_EQ(static_cast<int>((*grey)[25]), 0);  // grey
}

TEST(BenchPngCodecTest, RejectsEmptyGridsAndBadLevelsAndGarbage) {
  EXPECT_FALSE(EncodeTrinaryPng(Grid(), PngLayout::kGrey8, 9).ok());
  EXPECT_FALSE(EncodeTrinaryPng(Grid(2, 2), PngLayout::kGrey8, 10).ok());
  const std::string garbage = "\x89PNG\r\n\x1a\n garbage";
  EXPECT_FALSE(DecodeTrinaryPng(Bytes(garbage)).ok());
}

}  // namespace
}  // namespace linemap::bench
