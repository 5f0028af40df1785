// Chunk bodies read from crafted bytes: positions that must not wrap, counts
// that are corrupt (impossible for the body) or over a caller's limit
// (resource exhausted), reserved payload coders (unsupported), and the
// metadata's tolerance.
#include "codec/lmap/chunk_coding.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "format/byte_io.h"
#include "format/container.h"
#include "linemap/codec.h"

namespace linemap {
namespace {

struct RawSegment {
  std::uint64_t drow;
  std::uint64_t col;
  std::uint64_t rows;
  std::int64_t cols;
};

std::vector<std::uint8_t> SegmentsBody(const std::vector<RawSegment>& segments) {
  ByteWriter w;
  w.PutVarint(segments.size());
  for (const RawSegment& s : segments) {
    w.PutVarint(s.drow);
    w.PutVarint(s.col);
    w.PutVarint(s.rows);
    w.PutSignedVarint(s.cols);
  }
  return w.bytes();
}

// Limits raised so a map of 2^30 + 8 columns (or 2^31 - 1 rows) is allowed.
DecodeLimits RaisedLimits() {
  DecodeLimits limits;
  limits.max_cells = std::uint64_t{1} << 31;
  return limits;
}

// Regression: a column of prev.col + c above 2^31 - 1 used to wrap to a
// negative int that passed the `>= width` test, and the rasteriser wrote
// before the canvas. Only the SEGS body is decoded here: the canvas for such
// a map would take 1 GiB.
TEST(ChunkCodingTest, SegmentColumnNearTwoToThe31DoesNotWrap) {
  const int width = 1073741832;  // 2^30 + 8
  const std::vector<std::uint8_t> body = SegmentsBody({
      {0, 1073741831, 0, 0},           // a = b = (width - 1, 0): valid
      {0, 1073741832, 0, 2147483633},  // prev.col + c = 2^31 + 15: wrapped to -2^31 + 15
  });
  auto segments = ReadSegments(body, width, 1, RaisedLimits());
  ASSERT_FALSE(segments.ok());
  EXPECT_EQ(segments.status().code(), StatusCode::kCorrupt) << segments.status().ToString();
  EXPECT_NE(segments.status().message().find("segment 1 lies outside the map"), std::string::npos)
      << segments.status().ToString();

  // The first segment alone is fine.
  auto first = ReadSegments(SegmentsBody({{0, 1073741831, 0, 0}}), width, 1, RaisedLimits());
  ASSERT_TRUE(first.ok()) << first.status().ToString();
  EXPECT_EQ((*first)[0].a, (CellIndex{1073741831, 0}));
}

TEST(ChunkCodingTest, SegmentRowNearTwoToThe31DoesNotWrap) {
  const int height = 2147483647;
  const std::vector<std::uint8_t> body = SegmentsBody({
      {2147483646, 0, 0, 0},  // a = b = (0, height - 1): valid
      {2147483647, 0, 0, 0},  // prev.row + dr = 2^32 - 3: wrapped to -3
  });
  auto segments = ReadSegments(body, 1, height, RaisedLimits());
  ASSERT_FALSE(segments.ok());
  EXPECT_EQ(segments.status().code(), StatusCode::kCorrupt) << segments.status().ToString();
}

// A column step far outside the map must not overflow int64 either.
TEST(ChunkCodingTest, HugeSegmentColumnStepIsCorrupt) {
  for (std::int64_t cols : {INT64_MAX, INT64_MIN, std::int64_t{11}, std::int64_t{-1}}) {
    auto segments = ReadSegments(SegmentsBody({{0, 0, 1, cols}}), 10, 10, DecodeLimits{});
    ASSERT_FALSE(segments.ok()) << cols;
    EXPECT_EQ(segments.status().code(), StatusCode::kCorrupt) << segments.status().ToString();
  }
}

TEST(ChunkCodingTest, SegmentCountOverTheBodyIsCorruptOverTheLimitExhausted) {
  // Claims 1000 segments in a 4-byte body: impossible.
  ByteWriter w;
  w.PutVarint(1000);
  w.PutBytes(std::vector<std::uint8_t>{0, 0, 0});
  auto impossible = ReadSegments(w.bytes(), 10, 10, DecodeLimits{});
  ASSERT_FALSE(impossible.ok());
  EXPECT_EQ(impossible.status().code(), StatusCode::kCorrupt);

  const std::vector<std::uint8_t> two = SegmentsBody({{0, 0, 0, 1}, {1, 0, 0, 1}});
  DecodeLimits tight;
  tight.max_segments = 1;
  auto over = ReadSegments(two, 10, 10, tight);
  ASSERT_FALSE(over.ok());
  EXPECT_EQ(over.status().code(), StatusCode::kResourceExhausted) << over.status().ToString();
  EXPECT_TRUE(ReadSegments(two, 10, 10, DecodeLimits{}).ok());
}

TEST(ChunkCodingTest, ChainLengthOverTheBodyIsCorruptOverTheLimitExhausted) {
  // One chain of 4 cells: start (1, 1), steps east, north, west.
  const std::vector<std::uint8_t> body = {1, 4, 1, 1, 0, 2, 2};
  ASSERT_TRUE(ReadChains(body, 5, 5, DecodeLimits{}).ok());
  DecodeLimits tight;
  tight.max_chain_length = 3;
  auto over = ReadChains(body, 5, 5, tight);
  ASSERT_FALSE(over.ok());
  EXPECT_EQ(over.status().code(), StatusCode::kResourceExhausted) << over.status().ToString();
  // A length of 9 with 3 step bytes left: corrupt whatever the limit.
  const std::vector<std::uint8_t> longer = {1, 9, 1, 1, 0, 2, 2};
  auto impossible = ReadChains(longer, 5, 5, tight);
  ASSERT_FALSE(impossible.ok());
  EXPECT_EQ(impossible.status().code(), StatusCode::kCorrupt) << impossible.status().ToString();
}

// Coders 3-255 are reserved for later minor versions: unsupported, not
// corrupt, both for the payload alone and for a whole file.
TEST(ChunkCodingTest, ReservedPayloadCoderIsUnsupported) {
  for (int coder : {3, 7, 255}) {
    const std::vector<std::uint8_t> payload = {static_cast<std::uint8_t>(coder), 1, 2, 3};
    PayloadCoder kind = PayloadCoder::kRaw;
    auto body = UnwrapPayload(payload.data(), payload.size(), DecodeLimits{}, &kind);
    ASSERT_FALSE(body.ok());
    EXPECT_EQ(body.status().code(), StatusCode::kUnsupported) << body.status().ToString();
  }
  HeaderFields header;
  header.width = 4;
  header.height = 3;
  ContainerWriter writer(1, 0);
  writer.AddChunk("LMHD", WriteHeader(header));
  writer.AddChunk("FREE", {7, 0, 0});
  auto decoded = DecodeLmap(writer.Finish());
  ASSERT_FALSE(decoded.ok());
  EXPECT_EQ(decoded.status().code(), StatusCode::kUnsupported);
  EXPECT_NE(decoded.status().message().find("chunk FREE: unknown payload coder 7"),
            std::string::npos)
      << decoded.status().ToString();
}

// Unknown ancillary chunks are skipped before their coder byte is read; the
// last of several `meta` chunks gives the metadata.
TEST(ChunkCodingTest, UnknownAncillaryCoderIsNotReadLastMetaWins) {
  HeaderFields header;
  header.width = 4;
  header.height = 3;
  ContainerWriter writer(1, 0);
  writer.AddChunk("LMHD", WriteHeader(header));
  writer.AddChunk("zzzz", {200, 1});
  writer.AddChunk("meta", WrapPayload(WriteMetadata({{"creator", "first"}}), false));
  writer.AddChunk("meta", WrapPayload(WriteMetadata({{"creator", "second"}}), false));
  auto decoded = DecodeLmapContents(writer.Finish());
  ASSERT_TRUE(decoded.ok()) << decoded.status().ToString();
  ASSERT_EQ(decoded->metadata.size(), 1u);
  EXPECT_EQ(decoded->metadata[0].second, "second");
}

// The tolerance a file names: plain decimal whole numbers only, the last
// entry winning; anything else names none (metadata never rejects a file).
TEST(ChunkCodingTest, ToleranceCellsOfReadsOnlyPlainWholeNumbers) {
  using Entries = std::vector<std::pair<std::string, std::string>>;
  const std::pair<std::string, std::optional<int>> values[] = {
      {"1", 1},           {"4", 4},
      {"17", 17},         {"2147483647", 2147483647},
      {"0", {}},          {"", {}},
      {"02", {}},         {"+2", {}},
      {"-2", {}},         {" 2", {}},
      {"2 ", {}},         {"2.0", {}},
      {"2147483648", {}}, {"99999999999", {}},
      {"two", {}},
  };
  for (const auto& [text, want] : values) {
    EXPECT_EQ(ToleranceCellsOf(2, false, Entries{{"tolerance", text}}), want) << "'" << text << "'";
  }
  EXPECT_EQ(ToleranceCellsOf(2, false, Entries{}), std::nullopt);
  EXPECT_EQ(ToleranceCellsOf(2, false, Entries{{"Tolerance", "2"}, {"tolerance_cells", "2"}}),
            std::nullopt);
  EXPECT_EQ(
      ToleranceCellsOf(2, false, Entries{{"tolerance", "1"}, {"creator", "x"}, {"tolerance", "3"}}),
      3);
  EXPECT_EQ(ToleranceCellsOf(2, false, Entries{{"tolerance", "1"}, {"tolerance", "x"}}),
            std::nullopt);
  // Only a file simplified within a tolerance names one: not an exact file,
  // not one of version 1.0 (whose lossy mode had no T).
  const Entries two{{"tolerance", "2"}};
  EXPECT_EQ(ToleranceCellsOf(2, true, two), std::nullopt);
  EXPECT_EQ(ToleranceCellsOf(1, false, two), std::nullopt);
  EXPECT_EQ(ToleranceCellsOf(1, true, two), std::nullopt);
  EXPECT_EQ(ToleranceCellsOf(3, false, two), 2);
}

}  // namespace
}  // namespace linemap
