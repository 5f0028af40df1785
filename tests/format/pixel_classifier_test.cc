// Pixel classification against values worked out by hand from nav2's
// map_io.cpp (loadMapFromFile): shade = mean quantum / 65535, occ = 1 - shade
// (or shade with negate), strict comparisons with the thresholds.
#include "format/pixel_classifier.h"

#include <gtest/gtest.h>

namespace linemap {
namespace {

MapMetadata Trinary(double occupied = 0.65, double free = 0.196, bool negate = false) {
  MapMetadata meta;
  meta.occupied_thresh = occupied;
  meta.free_thresh = free;
  meta.negate = negate;
  return meta;
}

TEST(PixelClassifierTest, MapSaverValuesUnderDefaultThresholds) {
  const MapMetadata meta = Trinary();
  EXPECT_EQ(ClassifyGrey8(0, meta), Cell::kOccupied);   // occ 1.0
  EXPECT_EQ(ClassifyGrey8(254, meta), Cell::kFree);     // occ 0.0039
  EXPECT_EQ(ClassifyGrey8(255, meta), Cell::kFree);     // occ 0
  EXPECT_EQ(ClassifyGrey8(205, meta), Cell::kUnknown);  // occ 0.19608 > 0.196
  EXPECT_EQ(ClassifyGrey8(206, meta), Cell::kFree);     // occ 0.19216 < 0.196
}

TEST(PixelClassifierTest, OccupiedThresholdEdge) {
  const MapMetadata meta = Trinary();
  // occ = 1 - v/255 > 0.65  <=>  v < 89.25
  EXPECT_EQ(ClassifyGrey8(89, meta), Cell::kOccupied);  // occ 0.65098
  EXPECT_EQ(ClassifyGrey8(90, meta), Cell::kUnknown);   // occ 0.64706
}

TEST(PixelClassifierTest, ValueExactlyOnAThresholdIsUnknown) {
  // v = 51: occ = 1 - 51/255 = 0.8 exactly in binary? Use thresholds that
  // equal the computed occ to check the strict comparisons.
  const double occ_of_51 = 1.0 - (51.0 * 257.0) / 65535.0;
  EXPECT_EQ(ClassifyGrey8(51, Trinary(occ_of_51, 0.1)), Cell::kUnknown);
  const double occ_of_230 = 1.0 - (230.0 * 257.0) / 65535.0;
  EXPECT_EQ(ClassifyGrey8(230, Trinary(0.9, occ_of_230)), Cell::kUnknown);
}

TEST(PixelClassifierTest, OccupiedWinsWhenThresholdsOverlap) {
  // nav2 tests occupied first: with free_thresh above occupied_thresh a
  // value satisfying both is occupied.
  EXPECT_EQ(ClassifyGrey8(128, Trinary(0.3, 0.8)), Cell::kOccupied);
}

TEST(PixelClassifierTest, NegateSwapsDarkAndLight) {
  const MapMetadata meta = Trinary(0.65, 0.196, /*negate=*/true);
  EXPECT_EQ(ClassifyGrey8(0, meta), Cell::kFree);
  EXPECT_EQ(ClassifyGrey8(255, meta), Cell::kOccupied);
  EXPECT_EQ(ClassifyGrey8(128, meta), Cell::kUnknown);
}

TEST(PixelClassifierTest, RgbAveragesChannelsAndTruncates) {
  const MapMetadata meta = Trinary();
  // Mean of (255, 255, 0) * 257 = 43690 -> shade 0.6667, occ 0.333 -> unknown.
  const std::uint16_t yellow[3] = {255 * 257, 255 * 257, 0};
  EXPECT_EQ(ClassifyPixel(yellow, 3, meta), Cell::kUnknown);
  const std::uint16_t white[3] = {65535, 65535, 65535};
  EXPECT_EQ(ClassifyPixel(white, 3, meta), Cell::kFree);
  // nav2 takes the plain mean, not luminance: pure green has mean 1/3, so
  // occ 0.667 > 0.65 -> occupied (luminance 0.587 would give unknown).
  const std::uint16_t green[3] = {0, 65535, 0};
  EXPECT_EQ(ClassifyPixel(green, 3, meta), Cell::kOccupied);
}

TEST(PixelClassifierTest, TrinaryAveragesAlphaIn) {
  const MapMetadata meta = Trinary();
  // White, fully transparent: mean (3 * 65535 + 0) / 4 -> shade 0.75,
  // occ 0.25 -> unknown.
  const std::uint16_t clear_white[4] = {65535, 65535, 65535, 0};
  EXPECT_EQ(ClassifyPixel(clear_white, 4, meta), Cell::kUnknown);
  const std::uint16_t opaque_white[2] = {65535, 65535};
  EXPECT_EQ(ClassifyPixel(opaque_white, 2, meta), Cell::kFree);
  // Black and transparent: shade 0 -> occupied.
  const std::uint16_t clear_black[2] = {0, 0};
  EXPECT_EQ(ClassifyPixel(clear_black, 2, meta), Cell::kOccupied);
}

TEST(PixelClassifierTest, ScaleModeTreatsAnyTransparencyAsUnknown) {
  MapMetadata meta = Trinary();
  meta.mode = MapMode::kScale;
  const std::uint16_t almost_opaque_black[2] = {0, 65534};
  EXPECT_EQ(ClassifyPixel(almost_opaque_black, 2, meta), Cell::kUnknown);
  const std::uint16_t opaque_black[2] = {0, 65535};
  EXPECT_EQ(ClassifyPixel(opaque_black, 2, meta), Cell::kOccupied);
  // In between the thresholds nav2 keeps a level; a trinary grid says unknown.
  EXPECT_EQ(ClassifyGrey8(128, meta), Cell::kUnknown);
  EXPECT_EQ(ClassifyGrey8(255, meta), Cell::kFree);
}

TEST(PixelClassifierTest, RawModeUsesTheGreyValue) {
  MapMetadata meta = Trinary();
  meta.mode = MapMode::kRaw;
  EXPECT_EQ(ClassifyGrey8(0, meta), Cell::kFree);
  EXPECT_EQ(ClassifyGrey8(100, meta), Cell::kOccupied);
  EXPECT_EQ(ClassifyGrey8(50, meta), Cell::kUnknown);
  EXPECT_EQ(ClassifyGrey8(255, meta), Cell::kUnknown);
  // Raw ignores negate.
  meta.negate = true;
  EXPECT_EQ(ClassifyGrey8(100, meta), Cell::kOccupied);
}

TEST(PixelClassifierTest, SixteenBitSamplesUseFullPrecision) {
  const MapMetadata meta = Trinary();
  // occ = 1 - q / 65535 < 0.196  <=>  q > 52690.14
  const std::uint16_t just_free = 52691;
  const std::uint16_t just_not = 52690;
  EXPECT_EQ(ClassifyPixel(&just_free, 1, meta), Cell::kFree);
  EXPECT_EQ(ClassifyPixel(&just_not, 1, meta), Cell::kUnknown);
}

}  // namespace
}  // namespace linemap
