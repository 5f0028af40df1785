// Draco-coded SEGS bodies (spec/format.md 4.5.1): the bitstream rules the
// decoder enforces on top of Draco's own checks.
#include "codec/lmap/draco_segments.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "linemap/codec.h"

namespace linemap {
namespace {

const std::vector<LatticeSegment> kSegments = {{{0, 0}, {5, 0}}, {{1, 2}, {1, 7}}};

std::vector<std::uint8_t> Body() {
  std::vector<std::uint8_t> body = EncodeSegmentsDraco(kSegments);
  EXPECT_GE(body.size(), 15u);
  return body;
}

TEST(DracoSegmentsTest, RoundTripEndsExactlyAtTheStream) {
  auto decoded = DecodeSegmentsDraco(Body(), 10, 10, DecodeLimits{});
  ASSERT_TRUE(decoded.ok()) << decoded.status().ToString();
  EXPECT_EQ(*decoded, kSegments);
}

TEST(DracoSegmentsTest, TrailingBytesAreCorrupt) {
  for (std::uint8_t extra : {0, 1, 0xFF}) {
    std::vector<std::uint8_t> body = Body();
    body.push_back(extra);
    auto decoded = DecodeSegmentsDraco(body, 10, 10, DecodeLimits{});
    ASSERT_FALSE(decoded.ok());
    EXPECT_EQ(decoded.status().code(), StatusCode::kCorrupt);
    EXPECT_NE(decoded.status().message().find("trailing bytes"), std::string::npos)
        << decoded.status().ToString();
  }
}

TEST(DracoSegmentsTest, NonSequentialOrMetadataIsCorrupt) {
  std::vector<std::uint8_t> kd_tree = Body();
  kd_tree[8] = 1;  // encoding method: 1 = kd-tree
  auto a = DecodeSegmentsDraco(kd_tree, 10, 10, DecodeLimits{});
  ASSERT_FALSE(a.ok());
  EXPECT_EQ(a.status().code(), StatusCode::kCorrupt);

  std::vector<std::uint8_t> mesh = Body();
  mesh[7] = 1;  // encoder type: 1 = triangular mesh
  EXPECT_EQ(DecodeSegmentsDraco(mesh, 10, 10, DecodeLimits{}).status().code(),
            StatusCode::kCorrupt);

  std::vector<std::uint8_t> with_metadata = Body();
  with_metadata[10] |= 0x80;  // header flags bit 15
  auto b = DecodeSegmentsDraco(with_metadata, 10, 10, DecodeLimits{});
  ASSERT_FALSE(b.ok());
  EXPECT_EQ(b.status().code(), StatusCode::kCorrupt);
  EXPECT_NE(b.status().message().find("metadata"), std::string::npos);
}

// More than 1024 points per body byte breaks a format rule (corrupt), more
// than the caller's limit is resource exhausted, and a negative int32 count
// is corrupt whatever the limit.
TEST(DracoSegmentsTest, PointCountRules) {
  std::vector<std::uint8_t> body = Body();
  const std::uint32_t dense = static_cast<std::uint32_t>(1024 * body.size() + 1);
  for (int i = 0; i < 4; ++i) body[11 + i] = static_cast<std::uint8_t>(dense >> (8 * i));
  DecodeLimits unlimited;
  unlimited.max_segments = std::uint64_t{1} << 40;
  EXPECT_EQ(DecodeSegmentsDraco(body, 10, 10, unlimited).status().code(), StatusCode::kCorrupt);

  body[11] = body[12] = body[13] = 0;
  body[14] = 0x80;  // -2^31
  EXPECT_EQ(DecodeSegmentsDraco(body, 10, 10, unlimited).status().code(), StatusCode::kCorrupt);

  DecodeLimits tight;
  tight.max_segments = 1;
  EXPECT_EQ(DecodeSegmentsDraco(Body(), 10, 10, tight).status().code(),
            StatusCode::kResourceExhausted);
}

}  // namespace
}  // namespace linemap
